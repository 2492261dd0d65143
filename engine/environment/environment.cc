#include "engine/environment/environment.h"

#include "engine/core/config.h"
#include "engine/core/error.h"
#include "engine/environment/world_magnetic_model.h"

namespace airis::engine {
namespace {

std::unique_ptr<MagneticFieldModel> MakeMagneticModel(const EnvironmentConfig& config) {
  if (config.magnetic_model == MagneticModelKind::kDipole) {
    return std::make_unique<TiltedDipoleField>(config.dipole);
  }
  return std::make_unique<WorldMagneticModel>(WorldMagneticModel::Wmm2025());
}

}  // namespace

void EnvironmentConfig::Validate() const {
  ValidateNested(gravity, "gravity");
  RequireFinite("date_decimal_year", date_decimal_year);
  if (magnetic_model == MagneticModelKind::kWmm) {
    const WorldMagneticModel& wmm = WorldMagneticModel::Wmm2025();
    const double end = wmm.epoch() + WorldMagneticModel::kValidityYears;
    Require(date_decimal_year >= wmm.epoch() && date_decimal_year < end, "date_decimal_year",
            "must be in [" + FormatNumber(wmm.epoch()) + ", " + FormatNumber(end) + ") for the " +
                wmm.name() + " magnetic model (got " + FormatNumber(date_decimal_year) + ")");
  } else {
    ValidateNested(dipole, "dipole");
  }
  ValidateNested(wind, "wind");
}

Environment::Environment(const EnvironmentConfig& config, const GeodeticPosition& origin,
                         RandomStream stream)
    : config_((config.Validate(), config)),
      origin_(origin),
      frame_(origin),
      gravity_(config.gravity),
      magnetic_(MakeMagneticModel(config)),
      wind_(config.wind, stream) {}

double Environment::CalcGravity_m_s2(const Vec3& p_W) const {
  return gravity_.CalcAcceleration_m_s2(AltitudeOf(p_W));
}

AtmosphereSample Environment::CalcAir(const Vec3& p_W) const {
  return ussa1976::Calc(AltitudeOf(p_W));
}

Vec3 Environment::CalcMagneticField_nT(const Vec3& p_W) const {
  return magnetic_->CalcField_nT(frame_.ToGeodetic(p_W), config_.date_decimal_year);
}

}  // namespace airis::engine
