// libFuzzer target: scene text through what `airis scene check` does with it (scenes::LoadScene,
// then the world with every vehicle and sensor, short of cameras' GL context). The text is anchored
// in scenes/, so the includes and meshes that the example scenes name resolve, and its objects may
// take 128 MiB (tests/fuzz/scene_fuzz_options.h). A refused scene throws engine::ConfigError;
// anything else (another exception, a crash, a sanitizer report, a hang, gigabytes allocated) is
// a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/core/error.h"
#include "scenes/scene.h"
#include "scenes/world_builder.h"
#include "tests/fuzz/scene_fuzz_options.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const airis::scenes::Scene scene = airis::scenes::LoadSceneFromString(
        text, AIRIS_SOURCE_DIR "/scenes/fuzz_input.yaml", airis::testing::FuzzSceneLoadOptions());
    airis::scenes::BuildWorldWithoutCameras(scene);
  } catch (const airis::engine::ConfigError&) {
    // Refused with a located error: what a bad scene must get.
  }
  return 0;
}
