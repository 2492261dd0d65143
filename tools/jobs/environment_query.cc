#include "tools/jobs/environment_query.h"

#include <cstdio>
#include <memory>

#include "engine/core/config.h"
#include "engine/core/error.h"
#include "engine/core/geodetic.h"
#include "engine/environment/gravity.h"
#include "engine/environment/tilted_dipole.h"
#include "engine/environment/world_magnetic_model.h"

namespace airis::tools {
namespace {

// Limits as people write them ("1000000", not "1e+06").
std::string FormatLimit(double value) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.10g", value);
  return buf;
}

void RequireRange(const char* field, double value, double lo, double hi, const std::string& why) {
  if (!(value >= lo && value <= hi)) {
    throw engine::InvalidField(field, "must be between " + FormatLimit(lo) + " and " +
                                          FormatLimit(hi) + why + " (got " +
                                          engine::FormatNumber(value) + ")");
  }
}

}  // namespace

void EnvironmentQuery::Validate() const {
  RequireRange("latitude_deg", latitude_deg, -90.0, 90.0, " degrees");
  RequireRange("longitude_deg", longitude_deg, -180.0, 180.0, " degrees");
  // The altitude must lie inside every model that is evaluated; the dipole has no limit of its own.
  if (magnetic == engine::MagneticModelKind::kWmm) {
    using engine::WorldMagneticModel;
    RequireRange(
        "altitude_m", altitude_m, WorldMagneticModel::kMinAltitude_m,
        WorldMagneticModel::kMaxAltitude_m,
        " m, the World Magnetic Model's range (the atmosphere alone spans -5000 to 1000000 m)");
    const WorldMagneticModel& model = WorldMagneticModel::Wmm2025();
    const double end = model.epoch() + WorldMagneticModel::kValidityYears;
    if (!(date_decimal_year >= model.epoch() && date_decimal_year < end)) {
      throw engine::InvalidField(
          "date_decimal_year", "must be in [" + engine::FormatNumber(model.epoch()) + ", " +
                                   engine::FormatNumber(end) + ") for " + model.name() + " (got " +
                                   engine::FormatNumber(date_decimal_year) + ")");
    }
  } else {
    RequireRange("altitude_m", altitude_m, engine::ussa1976::kMinAltitude_m,
                 engine::ussa1976::kMaxAltitude_m, " m, the standard atmosphere's range");
  }
}

EnvironmentReport CalcEnvironmentAt(const EnvironmentQuery& q) {
  q.Validate();
  // Height above the ellipsoid is used as height above sea level for gravity and air (geoid not
  // modelled).
  const engine::GeodeticPosition where{engine::DegToRad(q.latitude_deg),
                                       engine::DegToRad(q.longitude_deg), q.altitude_m};
  EnvironmentReport r;
  r.gravity_m_s2 = engine::Gravity().CalcAcceleration_m_s2(q.altitude_m);
  r.air = engine::ussa1976::Calc(q.altitude_m);
  std::unique_ptr<engine::MagneticFieldModel> dipole;
  if (q.magnetic != engine::MagneticModelKind::kWmm) {
    dipole = std::make_unique<engine::TiltedDipoleField>();
  }
  const engine::MagneticFieldModel& model =
      dipole
          ? *dipole
          : static_cast<const engine::MagneticFieldModel&>(engine::WorldMagneticModel::Wmm2025());
  r.field = engine::DescribeField(model.CalcField_nT(where, q.date_decimal_year));
  r.magnetic_model = model.name();
  return r;
}

}  // namespace airis::tools
