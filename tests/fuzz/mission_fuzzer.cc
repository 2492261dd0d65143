// libFuzzer target: mission text through the mission loader (scenes::ParseMission) and, as `airis
// scene check --mission` does, the checks of each track against the scene it flies in
// (tests/inputs/support/mission_scene.yaml, loaded once). A refused mission throws
// engine::ConfigError; anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "scenes/mission_file.h"
#include "scenes/mission_limits.h"
#include "scenes/scene.h"

namespace {

const airis::scenes::Scene& MissionScene() {
  static const airis::scenes::Scene scene =
      airis::scenes::LoadScene(AIRIS_SOURCE_DIR "/tests/inputs/support/mission_scene.yaml");
  return scene;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const airis::scenes::Scene& scene = MissionScene();
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const airis::engine::Mission mission =
        airis::scenes::ParseMission(text, AIRIS_SOURCE_DIR "/tests/inputs/support/fuzz_input.yaml");
    // Each track flown by the vehicle it names (the first when it names none), as a run binds them.
    std::vector<std::size_t> vehicles;
    for (const airis::engine::MissionTrack& track : mission.tracks) {
      std::size_t v = 0;
      while (v < scene.vehicles.size() && !track.vehicle.empty() &&
             scene.vehicles[v].name != track.vehicle) {
        ++v;
      }
      if (v == scene.vehicles.size()) return 0;  // a vehicle the scene lacks: refused by the run
      vehicles.push_back(v);
    }
    airis::scenes::CheckMissionInScene(mission, scene, vehicles);
  } catch (const airis::engine::ConfigError&) {
    // Refused with a located error.
  }
  return 0;
}
