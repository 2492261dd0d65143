#include "engine/mission/mission_check.h"

#include <string>

#include "engine/core/config.h"
#include "engine/core/limits.h"

namespace airis::engine {

void CheckMission(const Mission& mission, const MissionLimits& limits, const Vec3& start_W,
                  const LocalNedFrame& frame) {
  ErrorCollector errors;
  StepPlan plan{start_W, start_W, &frame};
  double total_s = 0.0;
  for (std::size_t i = 0; i < mission.steps.size(); ++i) {
    const MissionStep& step = mission.steps[i];
    const std::string prefix = "steps[" + std::to_string(i) + "]." + std::string(step.kind());
    auto fail = [&](const std::string& field, const std::string& problem) {
      const std::string key = field.empty() ? prefix : prefix + "." + field;
      const SourceLocation where = mission.locate ? mission.locate(key) : step.where;
      throw ConfigError(where, key, problem);
    };
    errors.Try([&] {
      try {
        step.spec->Check(limits, plan);
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
      const std::string key = "steps";
      throw ConfigError(mission.locate ? mission.locate(key) : SourceLocation{mission.file, 0, 0},
                        key,
                        "the mission would take " + FormatRounded(total_s) +
                            " s of simulated time, more than the limit of " +
                            FormatNumber(kMaxMissionDuration_s) + " s (docs/limits.md)");
    });
  }
  errors.ThrowIfAny();
}

}  // namespace airis::engine
