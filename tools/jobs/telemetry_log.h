#pragma once

#include <memory>
#include <optional>
#include <string>

#include "engine/core/clock.h"
#include "engine/dataset/telemetry_recorder.h"
#include "engine/world/world.h"

namespace airis::tools {

/// The options `airis run` and `airis px4` share: ConfigError for a --realtime factor that is not
/// > 0, a --truth-rate-hz outside kMinRate_hz to the scene's `physics_rate_hz` (truth is made once
/// per tick) or an --until-s before the start.
void CheckPacingOptions(const std::optional<double>& realtime, double truth_rate_hz,
                        double physics_rate_hz, engine::TimeNs until_ns);

/// The telemetry log of a run in `out` (must be empty or absent; ConfigError otherwise), its
/// first rows written; null when `out` is empty (no log).
std::unique_ptr<engine::TelemetryRecorder> OpenTelemetryLog(engine::World& world,
                                                            const std::string& out,
                                                            double truth_rate_hz);

}  // namespace airis::tools
