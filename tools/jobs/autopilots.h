#pragma once

#include <functional>
#include <string>
#include <vector>

#include "engine/mavlink/px4/px4_autopilot.h"
#include "tools/jobs/simulation_job.h"

namespace airis::tools {

/// A vehicle flown by PX4, as AttachAutopilots left it.
struct AttachedAutopilot {
  std::size_t vehicle = 0;
  engine::mavlink::Px4Autopilot* px4 = nullptr;  ///< owned by the job's Simulation
};

/// Gives every vehicle whose scene entry says `autopilot: {kind: px4, ...}` to PX4 (docs/px4.md):
/// opens its link at once (SITL: listens on TCP 4560 + instance; HIL: opens the serial port or UDP
/// socket), with HIL_GPS's UTC from the scene's date and the world's geodetic frame. PX4 connects
/// on the first tick. `log` gets one line per event worth telling a user ("waiting for PX4
/// instance 0 on TCP 127.0.0.1:4560", what PX4 will miss among the vehicle's sensors). Throws
/// LinkError when a link cannot be opened (port in use, no such device).
std::vector<AttachedAutopilot> AttachAutopilots(SimulationJob& job,
                                                const std::function<void(const std::string&)>& log);

}  // namespace airis::tools
