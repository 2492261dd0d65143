// The airframe presets shipped as vehicles/presets/*.yaml (compiled in as text, their one source)
// load, validate and describe the airframes parameters.md and docs/flight-controller.md give.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "scenes/vehicle_kinds.h"
#include "vehicles/multirotor/multirotor.h"
#include "vehicles/multirotor/preset_files.h"

namespace airis::scenes {
namespace {

constexpr double kArm_m = 0.2275;  // reference arm (parameters.md)

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(PresetFilesTest, TheCompiledInTextIsTheFileInTheRepository) {
  ASSERT_EQ(vehicles::MultirotorPresetFiles().size(), 5u);
  for (const vehicles::PresetFile& p : vehicles::MultirotorPresetFiles()) {
    EXPECT_EQ(std::string(p.yaml), ReadFile(std::string(p.path))) << p.path;
  }
}

TEST(PresetFilesTest, QuadXIsTheReferenceQuadrotorOfParametersMd) {
  const vehicles::MultirotorConfig quad = LoadMultirotorPreset("quad_x");
  const vehicles::MultirotorConfig reference;  // the struct's defaults are parameters.md's quad
  EXPECT_EQ(quad.mass_kg, reference.mass_kg);
  EXPECT_EQ(quad.box_size_m, reference.box_size_m);
  ASSERT_EQ(quad.rotors.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(quad.rotors[i].position_m, reference.rotors[i].position_m) << i;
    EXPECT_EQ(quad.rotors[i].spin, reference.rotors[i].spin) << i;
    EXPECT_EQ(quad.rotors[i].thrust_coefficient, 0.109919);
    EXPECT_EQ(quad.rotors[i].max_rpm, 6396.667);
  }
}

TEST(PresetFilesTest, RingPresetsPutTheirRotorsOnTheReferenceArmWithAlternatingSpins) {
  for (const auto& [name, count, first_deg] :
       {std::tuple{"hexa_x", 6, 30.0}, std::tuple{"octo_x", 8, 22.5}}) {
    SCOPED_TRACE(name);
    const vehicles::MultirotorConfig c = LoadMultirotorPreset(name);
    ASSERT_EQ(c.rotors.size(), static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
      const double angle = engine::DegToRad(first_deg + 360.0 * i / count);
      const auto& r = c.rotors[static_cast<std::size_t>(i)];
      // The files write positions to a micrometre.
      EXPECT_NEAR(r.position_m.x(), kArm_m * std::cos(angle), 1e-6) << i;
      EXPECT_NEAR(r.position_m.y(), kArm_m * std::sin(angle), 1e-6) << i;
      EXPECT_EQ(r.position_m.z(), 0.025);
      EXPECT_EQ(r.spin, i % 2 == 0 ? vehicles::Spin::kCcw : vehicles::Spin::kCw) << i;
    }
  }
}

TEST(PresetFilesTest, TiltRotorTiltsItsFrontPairForward) {
  const vehicles::MultirotorConfig c = LoadMultirotorPreset("tilt_rotor");
  ASSERT_EQ(c.rotors.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(c.rotors[i].tiltable, i == 0 || i == 2) << i;
  }
  EXPECT_EQ(c.rotors[0].tilt_axis, engine::Vec3(0, -1, 0));
  EXPECT_EQ(c.rotors[0].max_tilt_deg, 90.0);
  EXPECT_EQ(vehicles::Multirotor("vtol", c).actuator_count(), 6);
}

TEST(PresetFilesTest, AnUnknownPresetIsAnError) {
  EXPECT_THROW(LoadMultirotorPreset("quad_z"), engine::ConfigError);
}

}  // namespace
}  // namespace airis::scenes
