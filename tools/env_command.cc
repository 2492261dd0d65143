// `airis env`: gravity, standard atmosphere and geomagnetic field at a geodetic point.
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/core/config.h"
#include "engine/core/error.h"
#include "engine/core/geodetic.h"
#include "engine/environment/atmosphere.h"
#include "engine/environment/gravity.h"
#include "engine/environment/magnetic_field.h"
#include "engine/environment/tilted_dipole.h"
#include "engine/environment/world_magnetic_model.h"
#include "tools/cli_util.h"
#include "tools/commands.h"

namespace airis::tools {
namespace {

using engine::ConfigError;
using engine::FormatNumber;

// Options as given on the command line; numbers stay text until ParseFiniteNumber names the option
// that holds a bad one. Defaults: the reference implementation's home point, 2026.0, the WMM.
struct EnvOptions {
  std::string lat = "47.641468";
  std::string lon = "-122.140165";
  std::string alt_m = "122";
  std::string date = "2026.0";
  std::string magnetic = "wmm";
  bool json = false;
};

// Limits as people write them ("1000000", not "1e+06").
std::string FormatLimit(double value) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.10g", value);
  return buf;
}

void RequireRange(const std::string& option, double value, double lo, double hi,
                  const std::string& why) {
  if (!(value >= lo && value <= hi)) {
    throw ConfigError({}, "--" + option,
                      "must be between " + FormatLimit(lo) + " and " + FormatLimit(hi) + why +
                          " (got " + FormatNumber(value) + ")");
  }
}

int RunEnv(const EnvOptions& options) {
  const double lat_deg = ParseFiniteNumber("lat", options.lat);
  const double lon_deg = ParseFiniteNumber("lon", options.lon);
  const double alt_m = ParseFiniteNumber("alt-m", options.alt_m);
  const double date = ParseFiniteNumber("date", options.date);
  const auto kind = engine::ParseEnum<engine::MagneticModelKind>(options.magnetic);
  if (!kind) {
    throw ConfigError({}, "--magnetic",
                      "must be " + engine::EnumChoices<engine::MagneticModelKind>() + " (got '" +
                          options.magnetic + "')");
  }
  RequireRange("lat", lat_deg, -90.0, 90.0, " degrees");
  RequireRange("lon", lon_deg, -180.0, 180.0, " degrees");

  // The altitude must lie inside every model that is evaluated: the atmosphere spans -5 km to 1000
  // km, the WMM only -1 km to 850 km; the dipole has no limit of its own.
  const bool wmm = *kind == engine::MagneticModelKind::kWmm;
  if (wmm) {
    using engine::WorldMagneticModel;
    RequireRange(
        "alt-m", alt_m, WorldMagneticModel::kMinAltitude_m, WorldMagneticModel::kMaxAltitude_m,
        " m, the World Magnetic Model's range (the atmosphere alone spans -5000 to 1000000 m)");
    const WorldMagneticModel& model = WorldMagneticModel::Wmm2025();
    const double end = model.epoch() + WorldMagneticModel::kValidityYears;
    if (!(date >= model.epoch() && date < end)) {
      throw ConfigError({}, "--date",
                        "must be in [" + FormatNumber(model.epoch()) + ", " + FormatNumber(end) +
                            ") for " + model.name() + " (got " + FormatNumber(date) + ")");
    }
  } else {
    RequireRange("alt-m", alt_m, engine::ussa1976::kMinAltitude_m, engine::ussa1976::kMaxAltitude_m,
                 " m, the standard atmosphere's range");
  }

  // Height above the ellipsoid is used as height above sea level for gravity and air (geoid not
  // modelled).
  const engine::GeodeticPosition where{engine::DegToRad(lat_deg), engine::DegToRad(lon_deg), alt_m};
  const double gravity_m_s2 = engine::Gravity().CalcAcceleration_m_s2(alt_m);
  const engine::AtmosphereSample air = engine::ussa1976::Calc(alt_m);
  std::unique_ptr<engine::MagneticFieldModel> dipole;
  if (!wmm) dipole = std::make_unique<engine::TiltedDipoleField>();
  const engine::MagneticFieldModel& model =
      wmm ? static_cast<const engine::MagneticFieldModel&>(engine::WorldMagneticModel::Wmm2025())
          : *dipole;
  const engine::MagneticFieldSample mag = engine::DescribeField(model.CalcField_nT(where, date));

  if (options.json) {
    nlohmann::json out;
    out["gravity_m_s2"] = gravity_m_s2;
    out["temperature_k"] = air.temperature_k;
    out["pressure_pa"] = air.pressure_pa;
    out["density_kg_m3"] = air.density_kg_m3;
    out["speed_of_sound_m_s"] = air.speed_of_sound_m_s;
    out["mag_north_nt"] = mag.field_ned_nt.x();
    out["mag_east_nt"] = mag.field_ned_nt.y();
    out["mag_down_nt"] = mag.field_ned_nt.z();
    out["declination_deg"] = engine::RadToDeg(mag.declination_rad);
    out["inclination_deg"] = engine::RadToDeg(mag.inclination_rad);
    out["total_intensity_nt"] = mag.total_intensity_nt;
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  std::printf("position         %.6f N, %.6f E, %.1f m above the WGS84 ellipsoid\n", lat_deg,
              lon_deg, alt_m);
  std::printf("date             %.4f (magnetic model %s)\n", date, model.name().c_str());
  std::printf("gravity          %.6f m/s^2\n", gravity_m_s2);
  std::printf("temperature      %.3f K\n", air.temperature_k);
  std::printf("pressure         %.6g Pa\n", air.pressure_pa);
  std::printf("density          %.6g kg/m^3\n", air.density_kg_m3);
  std::printf("speed of sound   %.3f m/s\n", air.speed_of_sound_m_s);
  std::printf("magnetic field   north %.1f nT, east %.1f nT, down %.1f nT\n", mag.field_ned_nt.x(),
              mag.field_ned_nt.y(), mag.field_ned_nt.z());
  std::printf("declination      %.2f deg\n", engine::RadToDeg(mag.declination_rad));
  std::printf("inclination      %.2f deg\n", engine::RadToDeg(mag.inclination_rad));
  std::printf("total intensity  %.1f nT\n", mag.total_intensity_nt);
  std::fflush(stdout);
  return 0;
}

}  // namespace

void AddEnvCommand(CLI::App& app, int& exit_code) {
  CLI::App* cmd = app.add_subcommand(
      "env",
      "Print gravity, the U.S. Standard Atmosphere 1976 and the geomagnetic field at a point");
  auto options = std::make_shared<EnvOptions>();
  cmd->add_option("--lat", options->lat, "geodetic latitude (degrees, north +, -90 to 90)")
      ->type_name("DEG")
      ->capture_default_str();
  cmd->add_option("--lon", options->lon, "longitude (degrees, east +, -180 to 180)")
      ->type_name("DEG")
      ->capture_default_str();
  cmd->add_option(
         "--alt-m", options->alt_m,
         "height above the WGS84 ellipsoid, used as altitude above sea level (m); -1000 to "
         "850000 with --magnetic wmm, -5000 to 1000000 with dipole")
      ->type_name("M")
      ->capture_default_str();
  cmd->add_option("--date", options->date,
                  "decimal year for the magnetic model (WMM2025: 2025.0 to 2030.0)")
      ->type_name("YEAR")
      ->capture_default_str();
  cmd->add_option("--magnetic", options->magnetic,
                  "magnetic model: wmm (World Magnetic Model 2025) or dipole")
      ->type_name("wmm|dipole")
      ->capture_default_str();
  cmd->add_flag("--json", options->json, "print one JSON object instead of text");
  cmd->callback(
      [options, &exit_code] { exit_code = RunReportingErrors([&] { return RunEnv(*options); }); });
}

}  // namespace airis::tools
