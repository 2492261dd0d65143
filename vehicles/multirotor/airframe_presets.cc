#include "vehicles/multirotor/airframe_presets.h"

#include <array>
#include <cmath>
#include <numbers>

namespace airis::vehicles {
namespace {

constexpr double kArm_m = 0.2275;       // reference arm length (parameters.md)
constexpr double kRotorDrop_m = 0.025;  // rotor plane below the centre of mass

// `count` rotors on a ring, the first at `first_deg` clockwise from the nose (seen from above),
// spins alternating from CCW.
std::vector<RotorConfig> Ring(int count, double first_deg) {
  std::vector<RotorConfig> rotors(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double angle = engine::DegToRad(first_deg + 360.0 * i / count);
    auto& r = rotors[static_cast<std::size_t>(i)];
    r.position_m = Vec3(kArm_m * std::cos(angle), kArm_m * std::sin(angle), kRotorDrop_m);
    r.spin = i % 2 == 0 ? Spin::kCcw : Spin::kCw;
  }
  return rotors;
}

}  // namespace

std::span<const engine::EnumName<AirframePreset>> EnumNames(AirframePreset) {
  static constexpr std::array<engine::EnumName<AirframePreset>, 5> kNames{{
      {AirframePreset::kQuadX, "quad_x"},
      {AirframePreset::kQuadPlus, "quad_plus"},
      {AirframePreset::kHexaX, "hexa_x"},
      {AirframePreset::kOctoX, "octo_x"},
      {AirframePreset::kTiltRotor, "tilt_rotor"},
  }};
  return kNames;
}

MultirotorConfig QuadXConfig() { return MultirotorConfig{}; }

MultirotorConfig QuadPlusConfig() {
  MultirotorConfig c;
  c.rotors = std::vector<RotorConfig>(4);
  c.rotors[0].position_m = Vec3(0.0, kArm_m, kRotorDrop_m);
  c.rotors[0].spin = Spin::kCcw;
  c.rotors[1].position_m = Vec3(0.0, -kArm_m, kRotorDrop_m);
  c.rotors[1].spin = Spin::kCcw;
  c.rotors[2].position_m = Vec3(kArm_m, 0.0, kRotorDrop_m);
  c.rotors[2].spin = Spin::kCw;
  c.rotors[3].position_m = Vec3(-kArm_m, 0.0, kRotorDrop_m);
  c.rotors[3].spin = Spin::kCw;
  return c;
}

MultirotorConfig HexaXConfig() {
  MultirotorConfig c;
  c.rotors = Ring(6, 30.0);
  return c;
}

MultirotorConfig OctoXConfig() {
  MultirotorConfig c;
  c.rotors = Ring(8, 22.5);
  return c;
}

MultirotorConfig TiltRotorConfig() {
  MultirotorConfig c;
  for (int i : {0, 2}) {
    auto& r = c.rotors[static_cast<std::size_t>(i)];
    r.tiltable = true;
    r.tilt_axis = Vec3(0.0, -1.0, 0.0);  // turning about -y takes up (-z) to forward (+x)
    r.max_tilt_deg = 90.0;
    r.tilt_rate_deg_s = 90.0;
  }
  return c;
}

MultirotorConfig MakeAirframe(AirframePreset preset) {
  switch (preset) {
    case AirframePreset::kQuadX:
      return QuadXConfig();
    case AirframePreset::kQuadPlus:
      return QuadPlusConfig();
    case AirframePreset::kHexaX:
      return HexaXConfig();
    case AirframePreset::kOctoX:
      return OctoXConfig();
    case AirframePreset::kTiltRotor:
      return TiltRotorConfig();
  }
  return QuadXConfig();
}

}  // namespace airis::vehicles
