#include "sensors/imu.h"

#include <array>
#include <cmath>

#include "engine/core/config.h"
#include "engine/core/geodetic.h"
#include "engine/core/standard_normal.h"
#include "sensors/sensor_checks.h"

namespace airis::sensors {

using engine::Vec3;

namespace {
constexpr double kDegPerHourToRadPerSecond = 0.017453292519943295 / 3600.0;
constexpr double kMicroG = 1e-6 * kStandardGravity_m_s2;
constexpr double kMilliG = 1e-3 * kStandardGravity_m_s2;

const std::string kColumns[] = {
    "angular_velocity_sensor_x_rad_s", "angular_velocity_sensor_y_rad_s",
    "angular_velocity_sensor_z_rad_s", "specific_force_sensor_x_m_s2",
    "specific_force_sensor_y_m_s2",    "specific_force_sensor_z_m_s2"};
const std::string_view kColumnDocs[] = {
    "angular velocity measured by the gyroscope, sensor axes (noise, bias and scale error "
    "included)",
    "",
    "",
    "specific force measured by the accelerometer, sensor axes: (0, 0, -g) level at rest",
    "",
    "",
};
static_assert(std::size(kColumnDocs) == std::size(kColumns));
}  // namespace

void ImuConfig::Validate() const {
  engine::RequireRate("rate_hz", rate_hz, engine::kMaxPhysicsRate_hz);
  ValidateNested("mount", mount);
  engine::RequireNonNegative("gyro_noise_density_deg_s_sqrt_hz", gyro_noise_density_deg_s_sqrt_hz);
  engine::RequireNonNegative("gyro_bias_instability_deg_h", gyro_bias_instability_deg_h);
  engine::RequirePositive("gyro_bias_correlation_s", gyro_bias_correlation_s);
  engine::RequireNonNegative("gyro_turn_on_bias_deg_s", gyro_turn_on_bias_deg_s);
  engine::RequireNonNegative("gyro_scale_factor_ppm", gyro_scale_factor_ppm);
  engine::RequireNonNegative("accel_noise_density_ug_sqrt_hz", accel_noise_density_ug_sqrt_hz);
  engine::RequireNonNegative("accel_bias_instability_ug", accel_bias_instability_ug);
  engine::RequirePositive("accel_bias_correlation_s", accel_bias_correlation_s);
  engine::RequireNonNegative("accel_turn_on_bias_mg", accel_turn_on_bias_mg);
  engine::RequireNonNegative("accel_scale_factor_ppm", accel_scale_factor_ppm);
}

void ImuConfig::ValidateForPhysicsRate(double physics_rate_hz) const {
  Validate();
  RequireRateWithinPhysics("rate_hz", rate_hz, physics_rate_hz);
}

Imu::Imu(std::string name, const ImuConfig& config, engine::RandomStream stream)
    : Sensor(std::move(name), (config.Validate(), config.rate_hz)),
      config_(config),
      stream_(stream),
      R_SB_(config.mount.q_BS().conjugate().toRotationMatrix()),
      p_BS_(config.mount.position_m),
      rotated_(R_SB_ != engine::Mat3::Identity()),
      has_lever_arm_(p_BS_ != Vec3::Zero()) {
  // A white noise of density N (unit/sqrt(Hz)) sampled at f_s has per-sample sigma N sqrt(f_s).
  const double sqrt_rate = std::sqrt(config.rate_hz);
  const double dt_s = 1.0 / config.rate_hz;
  white_sigma_.head<3>().setConstant(engine::DegToRad(config.gyro_noise_density_deg_s_sqrt_hz) *
                                     sqrt_rate);
  white_sigma_.tail<3>().setConstant(config.accel_noise_density_ug_sqrt_hz * kMicroG * sqrt_rate);

  // The peak of the bias's Allan deviation is the floor IEEE Std 952 reads a data sheet's bias
  // instability B from, 0.664 B: sigma_b = 0.664 B / 0.617.
  constexpr double kSigmaPerInstability = kFlickerAllanFloor / kGaussMarkovAllanPeak;
  const double gyro_bias_sigma =
      config.gyro_bias_instability_deg_h * kDegPerHourToRadPerSecond * kSigmaPerInstability;
  const double accel_bias_sigma = config.accel_bias_instability_ug * kMicroG * kSigmaPerInstability;
  const auto gyro_step =
      GaussMarkovStep::Make(gyro_bias_sigma, config.gyro_bias_correlation_s, dt_s);
  const auto accel_step =
      GaussMarkovStep::Make(accel_bias_sigma, config.accel_bias_correlation_s, dt_s);
  bias_decay_ << Vec3::Constant(gyro_step.a), Vec3::Constant(accel_step.a);
  bias_innovation_ << Vec3::Constant(gyro_step.b), Vec3::Constant(accel_step.b);

  // Power-on draws, in a fixed order: in-run biases from their stationary distribution, then
  // turn-on biases, then scale factors.
  bias_.head<3>() = GaussianVec3(stream_, gyro_bias_sigma);
  bias_.tail<3>() = GaussianVec3(stream_, accel_bias_sigma);
  gyro_turn_on_bias_ = GaussianVec3(stream_, engine::DegToRad(config.gyro_turn_on_bias_deg_s));
  accel_turn_on_bias_ = GaussianVec3(stream_, config.accel_turn_on_bias_mg * kMilliG);
  gyro_scale_ = Vec3::Ones() + GaussianVec3(stream_, config.gyro_scale_factor_ppm * 1e-6);
  accel_scale_ = Vec3::Ones() + GaussianVec3(stream_, config.accel_scale_factor_ppm * 1e-6);
}

std::span<const std::string> Imu::columns() const { return kColumns; }

std::string_view Imu::column_doc(std::size_t column) const { return kColumnDocs[column]; }

void Imu::CopyLatestRow(std::span<double> out) const {
  AIRIS_DEMAND(out.size() == std::size(kColumns));
  for (int i = 0; i < 3; ++i) {
    out[i] = latest_.angular_velocity_S_rad_s[i];
    out[3 + i] = latest_.specific_force_S_m_s2[i];
  }
}

void Imu::Sample(const engine::SensorContext& context) {
  AIRIS_DEMAND(context.state != nullptr && context.accelerations != nullptr &&
               context.environment != nullptr);
  const engine::RigidBodyState& s = *context.state;
  const engine::RigidBodyAccelerations& a = *context.accelerations;
  // The truth is worked out again unless the state is the one of the last sample (a body
  // asleep: SensorContext::motion_serial).
  if (context.motion_serial == 0 || context.motion_serial != truth_motion_serial_) {
    UpdateTruth(s, a, *context.environment);
    truth_motion_serial_ = context.motion_serial;
  }

  // Draw order is fixed (gyro bias, accel bias, gyro noise, accel noise) so streams are
  // reproducible. Each bias steps as GaussMarkovStep::Next, a x + b n; the sample is the truth plus
  // the bias plus the white noise, in that order.
  alignas(16) std::array<double, 12> n;
  engine::StandardNormals(stream_, n);
  const Eigen::Map<const Vec6, Eigen::Aligned16> bias_normals(n.data());
  const Eigen::Map<const Vec6, Eigen::Aligned16> white_normals(n.data() + 6);
  bias_ = bias_decay_.cwiseProduct(bias_) + bias_innovation_.cwiseProduct(bias_normals);
  const Vec6 sample = (truth_S_ + bias_) + white_sigma_.cwiseProduct(white_normals);

  latest_.time_ns = context.now_ns;
  latest_.angular_velocity_S_rad_s = sample.head<3>();
  latest_.specific_force_S_m_s2 = sample.tail<3>();
}

void Imu::UpdateTruth(const engine::RigidBodyState& s, const engine::RigidBodyAccelerations& a,
                      const engine::Environment& environment) {
  // Truth at the mounting point (rigid body kinematics), in sensor axes. The lever-arm terms and
  // the mount rotation are skipped where they are exactly zero and the identity (an IMU at the
  // centre of mass, not rotated: the usual mount), which leaves every number as it was.
  const Vec3& w_B = s.w_B;
  Vec3 f_B = a.CalcSpecificForce_B(s.q_WB);
  if (has_lever_arm_) f_B = f_B + a.alpha_B.cross(p_BS_) + w_B.cross(w_B.cross(p_BS_));
  // The gyroscope senses rotation against inertial space: the body's rate in the Earth-fixed world
  // frame plus the Earth's own. The Earth's axis is ECEF z, so its rate in W is Omega times the
  // third row of R_EW: Omega [cos(lat0), 0, -sin(lat0)] at the origin's latitude lat0. The
  // lever-arm terms above keep w_B (the Earth's rate changes them by < 1e-8 m/s^2).
  Vec3 w_IB_B = w_B;
  if (config_.gyro_earth_rotation) {
    const Vec3 earth_W =
        engine::wgs84::kAngularVelocity_rad_s * environment.frame().R_EW().row(2).transpose();
    w_IB_B += s.q_WB.conjugate() * earth_W;
  }
  const Vec3 w_S = rotated_ ? Vec3(R_SB_ * w_IB_B) : w_IB_B;
  const Vec3 f_S = rotated_ ? Vec3(R_SB_ * f_B) : f_B;

  truth_S_.head<3>() = gyro_scale_.cwiseProduct(w_S) + gyro_turn_on_bias_;
  truth_S_.tail<3>() = accel_scale_.cwiseProduct(f_S) + accel_turn_on_bias_;
}

}  // namespace airis::sensors
