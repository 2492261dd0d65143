// `airis env`: gravity, standard atmosphere and geomagnetic field at a geodetic point.
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/core/config.h"
#include "engine/core/error.h"
#include "tools/cli/cli_util.h"
#include "tools/cli/commands.h"
#include "tools/jobs/environment_query.h"

namespace airis::tools {
namespace {

using engine::ConfigError;

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

// The report, as text or JSON.
int PrintEnv(const EnvironmentQuery& q, const EnvironmentReport& r, bool json) {
  const engine::AtmosphereSample& air = r.air;
  const engine::MagneticFieldSample& mag = r.field;
  if (json) {
    nlohmann::json out;
    out["gravity_m_s2"] = r.gravity_m_s2;
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
  std::printf("position         %.6f N, %.6f E, %.1f m above the WGS84 ellipsoid\n", q.latitude_deg,
              q.longitude_deg, q.altitude_m);
  std::printf("date             %.4f (magnetic model %s)\n", q.date_decimal_year,
              r.magnetic_model.c_str());
  std::printf("gravity          %.6f m/s^2\n", r.gravity_m_s2);
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

// Checks the options (the query's ranges too); returns the work: print the report.
std::function<int()> CheckEnv(const EnvOptions& options) {
  EnvironmentQuery q;
  q.latitude_deg = ParseFiniteNumber("latitude-deg", options.lat);
  q.longitude_deg = ParseFiniteNumber("longitude-deg", options.lon);
  q.altitude_m = ParseFiniteNumber("altitude-m", options.alt_m);
  q.date_decimal_year = ParseFiniteNumber("date-decimal-year", options.date);
  const auto kind = engine::ParseEnum<engine::MagneticModelKind>(options.magnetic);
  if (!kind) {
    throw ConfigError({}, "--magnetic-model",
                      "must be " + engine::EnumChoices<engine::MagneticModelKind>() + " (got '" +
                          options.magnetic + "')");
  }
  q.magnetic = *kind;
  EnvironmentReport r;
  try {
    r = CalcEnvironmentAt(q);
  } catch (const engine::InvalidField& e) {
    // The options are named after the query's fields (docs/cli.md, "Option names").
    throw ConfigError({}, OptionForKey(e.field()), e.problem());
  }
  const bool json = options.json;
  return [q, r, json] { return PrintEnv(q, r, json); };
}

}  // namespace

void AddEnvCommand(CLI::App& app, int& exit_code) {
  CLI::App* cmd = app.add_subcommand(
      "env",
      "Print gravity, the U.S. Standard Atmosphere 1976 and the geomagnetic field at a point");
  auto options = std::make_shared<EnvOptions>();
  cmd->add_option("--latitude-deg", options->lat, "geodetic latitude (north +, -90 to 90)")
      ->type_name("DEG")
      ->capture_default_str();
  cmd->add_option("--longitude-deg", options->lon, "longitude (east +, -180 to 180)")
      ->type_name("DEG")
      ->capture_default_str();
  cmd->add_option("--altitude-m", options->alt_m,
                  "height above the WGS84 ellipsoid, used as altitude above sea level; -1000 to "
                  "850000 with --magnetic-model wmm, -5000 to 1000000 with dipole")
      ->type_name("M")
      ->capture_default_str();
  cmd->add_option("--date-decimal-year", options->date,
                  "date for the magnetic model (WMM2025: 2025.0 to 2030.0)")
      ->type_name("YEAR")
      ->capture_default_str();
  cmd->add_option("--magnetic-model", options->magnetic,
                  "wmm (World Magnetic Model 2025) or dipole")
      ->type_name("wmm|dipole")
      ->capture_default_str();
  cmd->add_flag("--json", options->json, "print one JSON object instead of text");
  SetCommandCallback(cmd, exit_code, [options] { return CheckEnv(*options); });
}

}  // namespace airis::tools
