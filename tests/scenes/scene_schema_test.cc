#include "scenes/scene_schema.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace airis::scenes {
namespace {

std::string ReadDoc(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path << ": run from the repository root";
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(SceneSchemaTest, DocsListEveryKeyOfTheFormat) {
  // docs/scene-format.md must hold each generated table verbatim, and docs/vehicles.md the
  // airframe keys of each vehicle kind: a key added, renamed or re-defaulted in a config struct
  // fails here until the pages are regenerated (`airis scene schema | python3
  // scenes/update_scene_docs.py`).
  const std::string scene_doc = ReadDoc("docs/scene-format.md");
  const std::string vehicles_doc = ReadDoc("docs/vehicles.md");
  const std::vector<SchemaSection> sections = SceneSchemaSections();
  ASSERT_EQ(sections.size(), 19u);  // 10 blocks, 1 vehicle kind, 8 sensor kinds
  for (const auto& s : sections) {
    const bool airframe = s.title.rfind("vehicles[].overrides", 0) == 0;
    const char* page = airframe ? "docs/vehicles.md" : "docs/scene-format.md";
    EXPECT_NE((airframe ? vehicles_doc : scene_doc).find(s.markdown), std::string::npos)
        << page << " lacks the current table for `" << s.title << "`:\n"
        << s.markdown;
  }
}

TEST(SceneSchemaTest, TablesNameNestedEnvironmentKeys) {
  const std::vector<SchemaSection> sections = SceneSchemaSections();
  EXPECT_NE(sections[1].markdown.find(
                "| `scene.environment.wind.gust` | one of none, gauss_markov or dryden | "
                "`none` |"),
            std::string::npos)
      << sections[1].markdown;
}

}  // namespace
}  // namespace airis::scenes
