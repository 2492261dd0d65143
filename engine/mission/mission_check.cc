#include "engine/mission/mission_check.h"

#include <string>

#include "engine/core/config.h"
#include "engine/core/limits.h"

namespace airis::engine {
namespace {

/// Checks `track`, flown from `start_W` within `limits`, recording its mistakes in `errors`.
void CheckTrack(const Mission& mission, const MissionTrack& track, const TrackLimits& limits,
                const LocalNedFrame& frame, ErrorCollector& errors) {
  const std::string prefix = track.key_path.empty() ? "" : track.key_path + ".";
  auto where = [&](const std::string& key, const SourceLocation& fallback) {
    return mission.locate ? mission.locate(key) : fallback;
  };
  StepPlan plan{limits.start_W, limits.start_W, &frame, limits.limits.terrain.get()};
  double total_s = 0.0;
  for (std::size_t i = 0; i < track.steps.size(); ++i) {
    const MissionStep& step = track.steps[i];
    const std::string step_key =
        prefix + "steps[" + std::to_string(i) + "]." + std::string(step.kind());
    auto fail = [&](const std::string& field, const std::string& problem) {
      const std::string key = field.empty() ? step_key : step_key + "." + field;
      throw ConfigError(where(key, step.where), key, problem);
    };
    errors.Try([&] {
      try {
        step.spec->Check(limits.limits, plan);
      } catch (const InvalidField& e) {
        fail(e.field(), e.problem());
      }
    });
    const double step_s = step.spec->EstimateDuration_s(plan);
    if (!(step_s <= kMaxMissionDuration_s)) {
      errors.Try([&] {
        fail("", "would take " + FormatRounded(step_s) + " s of simulated time, more than the " +
                     "limit of " + FormatNumber(kMaxMissionDuration_s) + " s (docs/limits.md)");
      });
    }
    total_s += step_s;
  }
  if (!(total_s <= kMaxMissionDuration_s)) {
    errors.Try([&] {
      const std::string key = prefix + "steps";
      throw ConfigError(where(key, SourceLocation{mission.file, 0, 0}), key,
                        "the track would take " + FormatRounded(total_s) +
                            " s of simulated time, more than the limit of " +
                            FormatNumber(kMaxMissionDuration_s) + " s (docs/limits.md)");
    });
  }
}

}  // namespace

void CheckMission(const Mission& mission, std::span<const TrackLimits> tracks,
                  const LocalNedFrame& frame) {
  AIRIS_DEMAND(tracks.size() == mission.tracks.size());
  ErrorCollector errors;
  for (std::size_t t = 0; t < tracks.size(); ++t) {
    CheckTrack(mission, mission.tracks[t], tracks[t], frame, errors);
  }
  errors.ThrowIfAny();
}

}  // namespace airis::engine
