#include "engine/mission/mission_estimate.h"

namespace airis::engine {

double EstimateTrackDuration_s(const MissionTrack& track, const Vec3& start_W,
                               const LocalNedFrame& frame, const Heightfield* terrain) {
  StepPlan plan{start_W, start_W, &frame, terrain};
  double total_s = 0.0;
  for (const MissionStep& step : track.steps) total_s += step.spec->EstimateDuration_s(plan);
  return total_s;
}

}  // namespace airis::engine
