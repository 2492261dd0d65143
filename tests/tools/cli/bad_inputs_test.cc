// Every bad input kept in tests/inputs/bad/ (scenes, missions, meshes) is refused by `airis scene
// check` with exit code 2 and errors a user can act on: each line `error: FILE:LINE:COL: KEY.PATH:
// PROBLEM`, the fragments the input expects among them, and nothing of the implementation's own
// exception text. The inputs say what they expect in their first lines (`# expect: ...`, and for
// missions `# scene: ...`); meshes list theirs in tests/inputs/bad/meshes/MESHES. The fuzz targets
// start from the same files.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/fixtures/temp_dir.h"
#include "tests/tools/cli/run_airis.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;
using testing::RunAiris;

const fs::path kInputs = fs::path(AIRIS_SOURCE_DIR) / "tests" / "inputs";
// The scene missions are checked in unless they name another (`# scene: PATH`, relative to them).
const fs::path kMissionScene = kInputs / "support" / "mission_scene.yaml";

// Text of an exception that no user should read: a C++ library's or JSON library's own message.
const char* const kRawExceptionText[] = {
    "std::",     "json.exception", "what()",       "bad_alloc", "vector::", "basic_string",
    "terminate", "Assertion",      "AIRIS_DEMAND", "stoi",      "stod",     "out_of_range"};
// A message longer than this quotes a value it should have cut.
constexpr std::size_t kMaxLineChars = 2500;

struct Expectation {
  std::vector<std::string> fragments;  // each must appear in one error line
  fs::path scene;                      // missions: the scene to check them in
};

/// The `# expect:` and `# scene:` lines at the top of `file`.
Expectation ReadExpectation(const fs::path& file) {
  Expectation e;
  std::ifstream in(file, std::ios::binary);
  std::string line;
  while (std::getline(in, line) && line.rfind("# ", 0) == 0) {
    if (line.rfind("# expect: ", 0) == 0) e.fragments.push_back(line.substr(10));
    if (line.rfind("# scene: ", 0) == 0) e.scene = file.parent_path() / line.substr(9);
  }
  return e;
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) out.push_back(line);
  return out;
}

/// Checks what `scene check` printed for a refused input.
void ExpectRefused(const testing::CommandResult& r, const std::vector<std::string>& fragments) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.out, "") << "a refused input prints no summary";
  const std::vector<std::string> lines = Lines(r.err);
  ASSERT_FALSE(lines.empty()) << "no error printed";
  // error: FILE:LINE:COL: KEY.PATH: PROBLEM (the key path of a whole-file mistake may be empty).
  static const std::regex kError(
      R"(^error: ([^:]+):([1-9][0-9]*):([1-9][0-9]*): (([^ :]+): )?(.+)$)");
  for (const std::string& line : lines) {
    if (line.rfind("note: stopped after ", 0) == 0) continue;
    EXPECT_TRUE(std::regex_match(line, kError)) << "not file:line:col: key: problem: " << line;
    EXPECT_LE(line.size(), kMaxLineChars) << line.substr(0, 200);
    for (const char* raw : kRawExceptionText) {
      EXPECT_EQ(line.find(raw), std::string::npos)
          << "raw exception text '" << raw << "': " << line;
    }
  }
  for (const std::string& fragment : fragments) {
    const bool found = std::any_of(lines.begin(), lines.end(), [&](const std::string& l) {
      return l.find(fragment) != std::string::npos;
    });
    EXPECT_TRUE(found) << "expected '" << fragment << "' in:\n" << r.err;
  }
}

/// The files of a folder of the corpus (sorted, so the test names are stable).
std::vector<fs::path> CorpusFiles(const std::string& folder, const std::string& extension) {
  std::vector<fs::path> out;
  for (const auto& entry : fs::directory_iterator(kInputs / "bad" / folder)) {
    if (extension.empty() || entry.path().extension() == extension) out.push_back(entry.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string TestName(const ::testing::TestParamInfo<fs::path>& info) {
  std::string name = info.param.filename().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

class BadSceneTest : public ::testing::TestWithParam<fs::path> {};

TEST_P(BadSceneTest, RefusedWithLocatedErrors) {
  const fs::path& file = GetParam();
  const Expectation e = ReadExpectation(file);
  ASSERT_FALSE(e.fragments.empty()) << file << " lacks a '# expect:' line";
  ExpectRefused(RunAiris(AddSceneCommand, "scene check " + file.string()), e.fragments);
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadSceneTest, ::testing::ValuesIn(CorpusFiles("scenes", ".yaml")),
                         TestName);

class BadMissionTest : public ::testing::TestWithParam<fs::path> {};

TEST_P(BadMissionTest, RefusedInItsSceneWithLocatedErrors) {
  const fs::path& file = GetParam();
  const Expectation e = ReadExpectation(file);
  ASSERT_FALSE(e.fragments.empty()) << file << " lacks a '# expect:' line";
  const fs::path scene = e.scene.empty() ? kMissionScene : e.scene;
  ExpectRefused(
      RunAiris(AddSceneCommand, "scene check " + scene.string() + " --mission " + file.string()),
      e.fragments);
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadMissionTest,
                         ::testing::ValuesIn(CorpusFiles("missions", ".yaml")), TestName);

/// MESHES: "FILE: FRAGMENT" per bad mesh.
std::vector<std::pair<std::string, std::string>> MeshExpectations() {
  std::vector<std::pair<std::string, std::string>> out;
  std::ifstream in(kInputs / "bad" / "meshes" / "MESHES");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::size_t colon = line.find(": ");
    out.emplace_back(line.substr(0, colon), line.substr(colon + 2));
  }
  return out;
}

class BadMeshTest : public ::testing::TestWithParam<fs::path> {};

TEST_P(BadMeshTest, RefusedAtTheObjectThatPlacesIt) {
  const fs::path& mesh = GetParam();
  std::string fragment;
  for (const auto& [name, expected] : MeshExpectations()) {
    if (name == mesh.filename().string()) fragment = expected;
  }
  ASSERT_FALSE(fragment.empty()) << mesh << " is not listed in MESHES";
  const fs::path scene =
      airis::testing::WriteTempFile("mesh_" + mesh.filename().string() + ".yaml",
                                    "objects:\n  - {name: thing, mesh: " + mesh.string() + "}\n");
  const testing::CommandResult r = RunAiris(AddSceneCommand, "scene check " + scene.string());
  ExpectRefused(r, {scene.string() + ":2:", "objects[0].mesh: cannot load mesh", fragment});
}

std::vector<fs::path> BadMeshes() {
  std::vector<fs::path> out;
  for (const fs::path& p : CorpusFiles("meshes", "")) {
    if (p.filename() != "MESHES" && p.extension() != ".mtl") out.push_back(p);
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadMeshTest, ::testing::ValuesIn(BadMeshes()), TestName);

TEST(BadInputCorpusTest, HoldsAtLeastThreeHundredInputs) {
  // The issue's bar: a corpus of at least 300 bad inputs, every one checked above.
  const std::size_t total = CorpusFiles("scenes", ".yaml").size() +
                            CorpusFiles("missions", ".yaml").size() + BadMeshes().size();
  EXPECT_GE(total, 300u);
}

}  // namespace
}  // namespace airis::tools
