// docs/dataset-format.md documents every column the code writes: its column tables are the ones
// generated from the column lists of the streams, the sensors and the pose tables.
#include "tools/jobs/dataset_columns.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace airis::tools {
namespace {

TEST(DatasetColumnsTest, TheFormatPageListsEveryColumnTheCodeWrites) {
  // A column added, renamed, retyped or redescribed fails here until the page is refreshed
  // (`build/airis dataset schema | python3 tools/jobs/update_dataset_docs.py`).
  std::ifstream in("docs/dataset-format.md");
  ASSERT_TRUE(in) << "run from the repository root";
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::vector<ColumnTable> tables = DatasetColumnTables();
  ASSERT_EQ(tables.size(), 13u);  // truth, commands, 6 sensor kinds, 2 CSVs, 2 poses, PCD
  for (const ColumnTable& t : tables) {
    EXPECT_NE(doc.find("#### `" + t.title + "`\n\n" + t.markdown), std::string::npos)
        << "docs/dataset-format.md lacks the current table for `" << t.title << "`:\n"
        << t.markdown;
  }
}

TEST(DatasetColumnsTest, TheRangefinderAndLidarTablesNameTheirColumns) {
  for (const ColumnTable& t : DatasetColumnTables()) {
    if (t.title == "<vehicle>.rangefinder") {
      EXPECT_NE(t.markdown.find("| `distance_m` | float32 | measured distance along the beam"),
                std::string::npos)
          << t.markdown;
    }
    if (t.title == "<vehicle>.<lidar>/NNNNNN.pcd") {
      EXPECT_NE(t.markdown.find("| `x`, `y`, `z` | F4 |"), std::string::npos) << t.markdown;
      EXPECT_NE(t.markdown.find("| `ring` | U2 |"), std::string::npos) << t.markdown;
    }
  }
}

}  // namespace
}  // namespace airis::tools
