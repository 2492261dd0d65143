#pragma once

#include <memory>
#include <optional>
#include <string>

#include "engine/dataset/telemetry_recorder.h"
#include "engine/world/world.h"

namespace airis::tools {

/// The options `airis run` and `airis px4` share: ConfigError for a --realtime factor or a
/// --truth-rate that is not > 0.
void CheckPacingOptions(const std::optional<double>& realtime, double truth_rate_hz);

/// The telemetry log of a run in `out` (must be empty or absent; ConfigError otherwise), its
/// first rows written; null when `out` is empty (no log).
std::unique_ptr<engine::TelemetryRecorder> OpenTelemetryLog(engine::World& world,
                                                            const std::string& out,
                                                            double truth_rate_hz);

}  // namespace airis::tools
