#pragma once

// A scene with one PX4 quad, for the tests of `airis px4` and `airis run` with PX4.

#include <string>

namespace airis::tools::testing {

/// A PX4 quad on instance N (TCP 4560 + N), connect timeout given; `camera`: a sensor entry more.
inline std::string Px4Scene(int instance, double connect_timeout_s,
                            const std::string& camera = "") {
  return "scene: {name: px4_cli}\n"
         "vehicles:\n"
         "  - name: drone1\n"
         "    preset: quad_x\n"
         "    start: {position_ned_m: [0, 0, -0.2]}\n"
         "    autopilot: {kind: px4, instance: " +
         std::to_string(instance) + ", connect_timeout_s: " + std::to_string(connect_timeout_s) +
         "}\n"
         "    sensors: [{imu: {}}, {barometer: {}}, {magnetometer: {}}, {gps: {}}" +
         (camera.empty() ? "" : ", " + camera) + "]\n";
}

}  // namespace airis::tools::testing
