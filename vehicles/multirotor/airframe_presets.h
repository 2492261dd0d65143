#pragma once

#include <span>
#include <string_view>

#include "vehicles/multirotor/multirotor_config.h"

namespace airis::vehicles {

/// The airframes shipped as vehicles/presets/<name>.yaml, built in C++ (the YAML files hold the
/// same values; a scene can override any key of them).
enum class AirframePreset { kQuadX, kQuadPlus, kHexaX, kOctoX, kTiltRotor };
std::span<const engine::EnumName<AirframePreset>> EnumNames(AirframePreset);

/// The reference quad-x (parameters.md): the defaults of MultirotorConfig.
MultirotorConfig QuadXConfig();
/// Quad in "+" layout, same arm (0.2275 m), mass and box; PX4 order: 0 right CCW, 1 left CCW, 2
/// front CW, 3 rear CW.
MultirotorConfig QuadPlusConfig();
/// Hexa-x: six rotors on 0.2275 m arms at 30, 90, ..., 330 deg (clockwise from the nose seen from
/// above), in that order, spins alternating from CCW; same mass and box.
MultirotorConfig HexaXConfig();
/// Octo-x: eight rotors at 22.5, 67.5, ..., 337.5 deg, in that order, spins alternating from CCW.
MultirotorConfig OctoXConfig();
/// Tilt-rotor VTOL: the quad-x whose front pair (rotors 0 and 2) tilt about the body -y axis from
/// vertical (tilt command 0) to forward thrust (tilt command 1 = 90 deg) at 90 deg/s. Actuators:
/// the four motors, then the tilts of rotors 0 and 2.
MultirotorConfig TiltRotorConfig();
/// The config of `preset`.
MultirotorConfig MakeAirframe(AirframePreset preset);

}  // namespace airis::vehicles
