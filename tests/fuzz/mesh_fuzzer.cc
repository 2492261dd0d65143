// libFuzzer target: bytes written as a mesh file and read by scenes::LoadMeshFile (airis's checks,
// then assimp). The input's first byte picks the extension (its value modulo the number of
// extensions scenes accept, in the order of scenes::MeshFileExtensions()); the rest is the file.
// tests/fuzz/make_corpus.py writes the seeds that way. A refused file throws
// scenes::MeshLoadError; anything else (another exception, a crash, a sanitizer report, a hang,
// gigabytes allocated, inside airis or inside assimp) is a finding. The example landing pad's
// material library is copied next to the input (when the target runs from the source folder, as
// CTest runs it), so that the OBJ seeds' `mtllib landing_pad.mtl` reaches assimp's MTL reader.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "scenes/mesh_file_check.h"
#include "scenes/mesh_loader.h"

namespace {

namespace fs = std::filesystem;

// A fresh folder of this process's own (libFuzzer's -jobs and -fork run several processes) in the
// temporary folder, which tests/fuzz/run_fuzzer.sh points into its work folder; emptied first (a
// folder left by an earlier process of the same id would hold other files that inputs could name).
const fs::path& WorkDir() {
  static const fs::path dir = [] {
    const fs::path d =
        fs::temp_directory_path() / ("airis_mesh_fuzzer_" + std::to_string(getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    std::error_code ignored;  // without the example (another folder), the seeds' mtllib is refused
    fs::copy_file("scenes/assets/landing_pad.mtl", d / "landing_pad.mtl",
                  fs::copy_options::overwrite_existing, ignored);
    return d;
  }();
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const auto extensions = airis::scenes::MeshFileExtensions();
  const fs::path path =
      WorkDir() / (std::string("input.") + extensions[data[0] % extensions.size()]);
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  try {
    airis::scenes::LoadMeshFile(path.string(), airis::scenes::MeshAxes::kYUp);
  } catch (const airis::scenes::MeshLoadError&) {
    // Refused with a reason.
  }
  return 0;
}
