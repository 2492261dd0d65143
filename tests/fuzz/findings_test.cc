// Every input that a fuzz target found crashing, hanging or leaking (tests/fuzz/findings/, listed
// with the error each must now get in tests/fuzz/findings/FINDINGS), fed through its loader in the
// normal build: each is refused with that error. docs/fuzzing.md tells what each one was.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "scenes/mesh_file_check.h"
#include "scenes/mesh_loader.h"
#include "scenes/mission_file.h"
#include "scenes/scene.h"
#include "scenes/world_builder.h"
#include "tests/fixtures/temp_dir.h"
#include "tests/fuzz/scene_fuzz_options.h"

namespace airis::scenes {
namespace {

namespace fs = std::filesystem;

// The tests run in the source folder (tests/fuzz/CMakeLists.txt).
const fs::path kFindings = fs::path("tests") / "fuzz" / "findings";

struct Finding {
  std::string file;      // relative to kFindings: TARGET/NAME
  std::string fragment;  // of the error it must get
};

std::vector<Finding> ReadFindings() {
  std::vector<Finding> out;
  std::ifstream in(kFindings / "FINDINGS");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::size_t colon = line.find(": ");
    if (colon == std::string::npos) {
      ADD_FAILURE() << "FINDINGS line without 'FILE: FRAGMENT': " << line;
      continue;
    }
    out.push_back({line.substr(0, colon), line.substr(colon + 2)});
  }
  return out;
}

std::string ReadBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// The error the loader of `target` gives for `input` (as the fuzz target feeds it), or "accepted".
std::string ErrorOf(const std::string& target, const std::string& input) {
  try {
    if (target == "mesh") {
      // The first byte picks the extension (tests/fuzz/mesh_fuzzer.cc).
      const auto extensions = MeshFileExtensions();
      const std::string extension =
          extensions[static_cast<unsigned char>(input.at(0)) % extensions.size()];
      const fs::path path = testing::WriteTempFile("finding." + extension, input.substr(1));
      // The target keeps the example landing pad's material library next to its input.
      fs::copy_file("scenes/assets/landing_pad.mtl", path.parent_path() / "landing_pad.mtl",
                    fs::copy_options::overwrite_existing);
      LoadMeshFile(path.string(), MeshAxes::kYUp);
    } else if (target == "scene") {
      BuildWorldWithoutCameras(
          LoadSceneFromString(input, "scenes/fuzz_input.yaml", testing::FuzzSceneLoadOptions()));
    } else if (target == "mission") {
      ParseMission(input, "tests/inputs/support/fuzz_input.yaml");
    } else {
      return "no loader for target " + target;
    }
  } catch (const MeshLoadError& e) {
    return e.what();
  } catch (const engine::ConfigError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(FuzzFindingsTest, EachIsRefusedWithItsError) {
  const std::vector<Finding> findings = ReadFindings();
  ASSERT_FALSE(findings.empty());
  std::size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kFindings)) {
    if (entry.is_regular_file() && entry.path().filename() != "FINDINGS") ++files;
  }
  EXPECT_EQ(files, findings.size()) << "every file in tests/fuzz/findings/ is listed in FINDINGS";
  for (const Finding& f : findings) {
    const fs::path path = kFindings / f.file;
    ASSERT_TRUE(fs::is_regular_file(path)) << path;
    const std::string target = f.file.substr(0, f.file.find('/'));
    const std::string error = ErrorOf(target, ReadBytes(path));
    EXPECT_NE(error.find(f.fragment), std::string::npos)
        << f.file << ": expected '" << f.fragment << "' in: " << error;
  }
}

}  // namespace
}  // namespace airis::scenes
