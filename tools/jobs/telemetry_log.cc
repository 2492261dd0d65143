#include "tools/jobs/telemetry_log.h"

#include "engine/core/config.h"
#include "engine/core/error.h"
#include "tools/jobs/output_folder.h"

namespace airis::tools {

void CheckPacingOptions(const std::optional<double>& realtime, double truth_rate_hz,
                        double physics_rate_hz, engine::TimeNs until_ns) {
  if (realtime && !(*realtime > 0.0)) throw engine::ConfigError({}, "--realtime", "must be > 0");
  try {
    engine::RequireRate("truth-rate-hz", truth_rate_hz, physics_rate_hz);
  } catch (const engine::InvalidField& e) {
    throw engine::ConfigError({}, "--truth-rate-hz", e.problem());
  }
  if (until_ns < 0) {
    throw engine::ConfigError(
        {}, "--until-s",
        "must be >= 0 s (got " + engine::FormatNumber(engine::ToSeconds(until_ns)) + ")");
  }
}

std::unique_ptr<engine::TelemetryRecorder> OpenTelemetryLog(engine::World& world,
                                                            const std::string& out,
                                                            double truth_rate_hz) {
  if (out.empty()) return nullptr;
  PrepareEmptyOutputFolder(out, "--out");
  engine::TelemetryOptions t;
  t.truth_rate_hz = truth_rate_hz;
  auto telemetry = std::make_unique<engine::TelemetryRecorder>(world, out, t);
  telemetry->OnTick(0);
  return telemetry;
}

}  // namespace airis::tools
