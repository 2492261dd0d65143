// `airis env`, driven through the same CLI11 app setup as main.cc, with stdout and stderr captured.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "engine/core/frames.h"
#include "engine/environment/atmosphere.h"
#include "engine/environment/gravity.h"
#include "engine/environment/tilted_dipole.h"
#include "engine/environment/world_magnetic_model.h"
#include "tests/tools/cli/run_airis.h"
#include "tools/cli/commands.h"

namespace airis::tools {
namespace {

using Result = testing::CommandResult;

Result RunAiris(const std::string& args) { return testing::RunAiris(&AddEnvCommand, args); }

const std::set<std::string> kKeys = {"gravity_m_s2",    "temperature_k",      "pressure_pa",
                                     "density_kg_m3",   "speed_of_sound_m_s", "mag_north_nt",
                                     "mag_east_nt",     "mag_down_nt",        "declination_deg",
                                     "inclination_deg", "total_intensity_nt"};

TEST(EnvCommandTest, JsonHasExactlyTheDocumentedKeys) {
  const Result r = RunAiris("env --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.is_object());
  std::set<std::string> keys;
  for (const auto& item : j.items()) {
    keys.insert(item.key());
    EXPECT_TRUE(item.value().is_number()) << item.key();
  }
  EXPECT_EQ(keys, kKeys);
}

TEST(EnvCommandTest, DefaultsAreTheReferenceOriginIn2026WithTheWmm) {
  const nlohmann::json j = nlohmann::json::parse(RunAiris("env --json").out);
  const double alt_m = 122.0;
  EXPECT_DOUBLE_EQ(j["gravity_m_s2"].get<double>(), engine::Gravity().CalcAcceleration_m_s2(alt_m));
  const engine::AtmosphereSample air = engine::ussa1976::Calc(alt_m);
  EXPECT_DOUBLE_EQ(j["temperature_k"].get<double>(), air.temperature_k);
  EXPECT_DOUBLE_EQ(j["pressure_pa"].get<double>(), air.pressure_pa);
  EXPECT_DOUBLE_EQ(j["density_kg_m3"].get<double>(), air.density_kg_m3);
  EXPECT_DOUBLE_EQ(j["speed_of_sound_m_s"].get<double>(), air.speed_of_sound_m_s);
  const engine::GeodeticPosition origin{engine::DegToRad(47.641468), engine::DegToRad(-122.140165),
                                        alt_m};
  const engine::Vec3 b = engine::WorldMagneticModel::Wmm2025().CalcField_nT(origin, 2026.0);
  EXPECT_DOUBLE_EQ(j["mag_north_nt"].get<double>(), b.x());
  EXPECT_DOUBLE_EQ(j["mag_east_nt"].get<double>(), b.y());
  EXPECT_DOUBLE_EQ(j["mag_down_nt"].get<double>(), b.z());
  EXPECT_NEAR(j["total_intensity_nt"].get<double>(), b.norm(), 1e-9);
  // Seattle in 2026: declination ~15 deg east, inclination ~68 deg down (WMM2025 charts).
  EXPECT_NEAR(j["declination_deg"].get<double>(), 15.0, 1.0);
  EXPECT_NEAR(j["inclination_deg"].get<double>(), 68.0, 1.0);
}

TEST(EnvCommandTest, OptionsChooseThePointDateAndModel) {
  const Result r = RunAiris(
      "env --json --latitude-deg -33.9 --longitude-deg 18.4 --altitude-m 2500 --date-decimal-year "
      "2029.5 --magnetic-model dipole");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const engine::GeodeticPosition p{engine::DegToRad(-33.9), engine::DegToRad(18.4), 2500.0};
  const engine::Vec3 b = engine::TiltedDipoleField().CalcField_nT(p, 2029.5);
  EXPECT_DOUBLE_EQ(j["mag_down_nt"].get<double>(), b.z());
  EXPECT_DOUBLE_EQ(j["pressure_pa"].get<double>(), engine::ussa1976::Calc(2500.0).pressure_pa);
  // The dipole has no altitude limit of its own: the atmosphere's 1000 km applies.
  EXPECT_EQ(RunAiris("env --json --altitude-m 950000 --magnetic-model dipole").exit_code, 0);
}

TEST(EnvCommandTest, TextOutputNamesEveryQuantityWithItsUnit) {
  const Result r = RunAiris("env");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* part : {"gravity", "m/s^2", "temperature", " K\n", "pressure", " Pa\n",
                           "density", "kg/m^3", "speed of sound", "north", "east", "down", " nT",
                           "declination", "inclination", "deg", "total intensity", "WMM-2025"}) {
    EXPECT_NE(r.out.find(part), std::string::npos) << part << " missing in:\n" << r.out;
  }
}

// A bad input exits non-zero with one line on stderr that names the option, and prints nothing on
// stdout.
void ExpectError(const std::string& args, const std::string& option,
                 const std::string& detail = "") {
  const Result r = RunAiris(args);
  EXPECT_NE(r.exit_code, 0) << args;
  EXPECT_TRUE(r.out.empty()) << args << " printed: " << r.out;
  EXPECT_NE(r.err.find(option), std::string::npos) << args << " -> " << r.err;
  if (!detail.empty()) {
    EXPECT_NE(r.err.find(detail), std::string::npos) << args << " -> " << r.err;
  }
}

TEST(EnvCommandTest, RejectsOutOfRangeCoordinates) {
  ExpectError("env --latitude-deg 90.5", "--latitude-deg", "got 90.5");
  ExpectError("env --latitude-deg=-91", "--latitude-deg", "between -90 and 90");
  ExpectError("env --longitude-deg 180.01", "--longitude-deg", "between -180 and 180");
  ExpectError("env --longitude-deg=-200", "--longitude-deg");
}

TEST(EnvCommandTest, RejectsAltitudesOutsideTheModels) {
  ExpectError("env --altitude-m 900000", "--altitude-m", "850000");  // above the WMM's 850 km
  ExpectError("env --altitude-m=-2000", "--altitude-m", "-1000");    // below the WMM's -1 km
  ExpectError("env --altitude-m 1000001 --magnetic-model dipole", "--altitude-m",
              "1000000");  // above the atmosphere
  ExpectError("env --altitude-m=-5001 --magnetic-model dipole", "--altitude-m", "-5000");
}

TEST(EnvCommandTest, RejectsDatesOutsideTheWmmValidity) {
  ExpectError("env --date-decimal-year 2030", "--date-decimal-year", "[2025, 2030)");
  ExpectError("env --date-decimal-year 2024.9", "--date-decimal-year", "WMM-2025");
}

TEST(EnvCommandTest, RejectsNonNumbersNamingTheOption) {
  ExpectError("env --latitude-deg abc", "--latitude-deg", "abc");
  ExpectError("env --longitude-deg nan", "--longitude-deg", "nan");
  ExpectError("env --altitude-m inf", "--altitude-m");
  ExpectError("env --date-decimal-year 2026x", "--date-decimal-year", "2026x");
  ExpectError("env --magnetic-model igrf", "--magnetic-model", "dipole or wmm");
}

TEST(EnvCommandTest, NegativeNumbersAreValues) {
  const Result r = RunAiris("env --json --latitude-deg -45 --longitude-deg -60");
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

}  // namespace
}  // namespace airis::tools
