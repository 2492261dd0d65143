#include "sensors/magnetometer.h"

#include "engine/core/config.h"
#include "sensors/gauss_markov.h"
#include "sensors/sensor_checks.h"

namespace airis::sensors {

namespace {
constexpr double kGaussPerNanotesla = 1e-5;  // 1 G = 1e-4 T = 1e5 nT
const std::string kColumns[] = {"magnetic_field_sensor_x_gauss", "magnetic_field_sensor_y_gauss",
                                "magnetic_field_sensor_z_gauss"};
const std::string_view kColumnDocs[] = {
    "measured magnetic field, sensor axes (1 G = 1e5 nT)",
    "",
    "",
};
static_assert(std::size(kColumnDocs) == std::size(kColumns));
}  // namespace

void MagnetometerConfig::Validate() const {
  engine::RequireRate("rate_hz", rate_hz, engine::kMaxPhysicsRate_hz);
  ValidateNested("mount", mount);
  engine::RequireNonNegative("noise_gauss", noise_gauss);
  engine::RequireNonNegative("field_update_distance_m", field_update_distance_m);
  for (int i = 0; i < 3; ++i) {
    engine::RequireFinite("scale_factor[" + std::to_string(i) + "]", scale_factor[i]);
    engine::RequireFinite("hard_iron_sensor_gauss[" + std::to_string(i) + "]", hard_iron_gauss[i]);
  }
  engine::Require(soft_iron.empty() || soft_iron.size() == 9, "soft_iron",
                  "must be empty or hold 9 numbers (got " + std::to_string(soft_iron.size()) + ")");
  for (std::size_t i = 0; i < soft_iron.size(); ++i) {
    engine::RequireFinite("soft_iron[" + std::to_string(i) + "]", soft_iron[i]);
  }
}

void MagnetometerConfig::ValidateForPhysicsRate(double physics_rate_hz) const {
  Validate();
  RequireRateWithinPhysics("rate_hz", rate_hz, physics_rate_hz);
}

Magnetometer::Magnetometer(std::string name, const MagnetometerConfig& config,
                           engine::RandomStream stream)
    : Sensor(std::move(name), (config.Validate(), config.rate_hz)),
      config_(config),
      stream_(stream),
      R_SB_(config.mount.q_BS().conjugate().toRotationMatrix()) {
  engine::Mat3 soft_iron = engine::Mat3::Identity();
  if (!config.soft_iron.empty()) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) soft_iron(r, c) = config.soft_iron[3 * r + c];
    }
  }
  gain_ = kGaussPerNanotesla * soft_iron * config.scale_factor.asDiagonal();
}

std::span<const std::string> Magnetometer::columns() const { return kColumns; }

std::string_view Magnetometer::column_doc(std::size_t column) const { return kColumnDocs[column]; }

void Magnetometer::CopyLatestRow(std::span<double> out) const {
  AIRIS_DEMAND(out.size() == std::size(kColumns));
  for (int i = 0; i < 3; ++i) out[i] = latest_.field_S_gauss[i];
}

void Magnetometer::Sample(const engine::SensorContext& context) {
  AIRIS_DEMAND(context.state != nullptr && context.environment != nullptr);
  if (context.motion_serial == 0 || context.motion_serial != field_motion_serial_) {
    const engine::RigidBodyState& s = *context.state;
    const engine::Vec3 p_WS = s.p_W + s.q_WB * config_.mount.position_m;
    const double d = config_.field_update_distance_m;
    if (!has_field_ || (p_WS - field_p_W_).squaredNorm() > d * d || d == 0.0) {
      field_W_nT_ = context.environment->CalcMagneticField_nT(p_WS);
      field_p_W_ = p_WS;
      has_field_ = true;
    }
    field_S_nT_ = R_SB_ * (s.q_WB.conjugate() * field_W_nT_);
    field_motion_serial_ = context.motion_serial;
  }
  const engine::Vec3& field_S_nT = field_S_nT_;

  latest_.time_ns = context.now_ns;
  latest_.field_S_gauss =
      gain_ * field_S_nT + config_.hard_iron_gauss + GaussianVec3(stream_, config_.noise_gauss);
}

}  // namespace airis::sensors
