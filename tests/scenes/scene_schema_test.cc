#include "scenes/scene_schema.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace airis::scenes {
namespace {

TEST(SceneSchemaTest, DocsListEveryKeyOfTheFormat) {
  // docs/scene-format.md must hold each generated table verbatim: a key added, renamed or
  // re-defaulted in a config struct fails here until the page is regenerated (`airis scene
  // schema`).
  std::ifstream in("docs/scene-format.md");
  ASSERT_TRUE(in) << "run from the repository root";
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::vector<SchemaSection> sections = SceneSchemaSections();
  ASSERT_EQ(sections.size(), 18u);  // 9 blocks, 1 vehicle kind, 8 sensor kinds
  for (const auto& s : sections) {
    EXPECT_NE(doc.find(s.markdown), std::string::npos)
        << "docs/scene-format.md lacks the current table for `" << s.title << "`:\n"
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
