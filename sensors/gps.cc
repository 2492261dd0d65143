#include "sensors/gps.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/core/config.h"
#include "engine/core/standard_normal.h"
#include "sensors/gauss_markov.h"
#include "sensors/sensor_checks.h"

namespace airis::sensors {

using engine::TimeNs;
using engine::Vec3;

namespace {
const std::string kColumns[] = {
    "fix_type",           "latitude_deg", "longitude_deg", "altitude_m",      "velocity_ned_x_m_s",
    "velocity_ned_y_m_s", "eph_m",        "epv_m",         "position_time_s", "velocity_ned_z_m_s"};
const std::string_view kColumnDocs[] = {
    "1 no fix, 2 2D fix, 3 3D fix (MAVLink GPS_FIX_TYPE); a row without a fix (before the first) "
    "has NaN position, velocity and position_time_s",
    "measured position, WGS84",
    "",
    "height above the WGS84 ellipsoid",
    "measured velocity, world NED",
    "",
    "1-sigma horizontal accuracy estimate",
    "1-sigma vertical accuracy estimate",
    "simulated time the fix describes: the row time minus the receiver latency",
    "measured velocity, world NED (down)",
};
static_assert(std::size(kColumnDocs) == std::size(kColumns));

// First-order decay from `initial` to `final` with time constant `tau_s`, started at `start_ns`.
double Decay(double initial, double final_value, double tau_s, TimeNs start_ns, TimeNs t_ns) {
  if (t_ns <= start_ns) return initial;
  return final_value +
         (initial - final_value) * std::exp(-engine::ToSeconds(t_ns - start_ns) / tau_s);
}
}  // namespace

void GpsConfig::Validate() const {
  engine::RequireRate("rate_hz", rate_hz, engine::kMaxPhysicsRate_hz);
  ValidateNested("mount", mount);
  engine::RequireInRange("latency_s", latency_s, 0.0, 10.0);
  engine::RequireNonNegative("startup_delay_s", startup_delay_s);
  engine::RequirePositive("eph_initial_m", eph_initial_m);
  engine::RequirePositive("eph_final_m", eph_final_m);
  engine::RequirePositive("eph_time_constant_s", eph_time_constant_s);
  engine::RequirePositive("epv_initial_m", epv_initial_m);
  engine::RequirePositive("epv_final_m", epv_final_m);
  engine::RequirePositive("epv_time_constant_s", epv_time_constant_s);
  engine::RequirePositive("fix_3d_max_eph_m", fix_3d_max_eph_m);
  engine::RequirePositive("fix_2d_max_eph_m", fix_2d_max_eph_m);
  engine::Require(fix_2d_max_eph_m >= fix_3d_max_eph_m, "fix_2d_max_eph_m",
                  "must be >= fix_3d_max_eph_m (got " + engine::FormatNumber(fix_2d_max_eph_m) +
                      " < " + engine::FormatNumber(fix_3d_max_eph_m) + ")");
  engine::RequirePositive("position_error_correlation_s", position_error_correlation_s);
  engine::RequireInRange("position_white_fraction", position_white_fraction, 0.0, 1.0);
  engine::RequireNonNegative("velocity_noise_m_s", velocity_noise_m_s);
  engine::RequireNonNegative("velocity_down_noise_m_s", velocity_down_noise_m_s);
}

void GpsConfig::ValidateForPhysicsRate(double physics_rate_hz) const {
  Validate();
  RequireRateWithinPhysics("rate_hz", rate_hz, physics_rate_hz);
}

Gps::Gps(std::string name, const GpsConfig& config, engine::RandomStream stream)
    : Sensor(std::move(name), (config.Validate(), config.rate_hz)),
      config_(config),
      stream_(stream),
      latency_ns_(engine::SecondsToNs(config.latency_s, "latency_s")),
      startup_ns_(engine::SecondsToNs(config.startup_delay_s, "startup_delay_s")),
      vertical_stream_(stream.Fork("velocity_down")) {
  // Fixes are at least half a period apart (the schedule fires at the first tick at or after each
  // due time and the rate never exceeds the tick rate), so this many entries always span the
  // latency.
  const auto capacity =
      static_cast<std::size_t>(2.0 * std::ceil(config.latency_s * config.rate_hz)) + 4;
  history_.resize(capacity);
  slow_error_ = GaussianVec3(stream_, 1.0);  // stationary start
}

double Gps::CalcEph_m(TimeNs t_ns) const {
  return Decay(config_.eph_initial_m, config_.eph_final_m, config_.eph_time_constant_s, startup_ns_,
               t_ns);
}

double Gps::CalcEpv_m(TimeNs t_ns) const {
  return Decay(config_.epv_initial_m, config_.epv_final_m, config_.epv_time_constant_s, startup_ns_,
               t_ns);
}

engine::GnssFixType Gps::CalcFixType(TimeNs t_ns, double eph_m) const {
  if (t_ns < startup_ns_ || first_truth_ns_ < 0 || t_ns - latency_ns_ < first_truth_ns_) {
    return engine::GnssFixType::kNoFix;
  }
  if (eph_m <= config_.fix_3d_max_eph_m) return engine::GnssFixType::k3D;
  if (eph_m <= config_.fix_2d_max_eph_m) return engine::GnssFixType::k2D;
  return engine::GnssFixType::kNoFix;
}

std::span<const std::string> Gps::columns() const { return kColumns; }

std::string_view Gps::column_doc(std::size_t column) const { return kColumnDocs[column]; }

engine::LogType Gps::column_type(std::size_t column) const {
  if (column == 0) return engine::LogType::kInt64;
  const bool wide = column == 1 || column == 2 || column == 3 || column == 8;
  return wide ? engine::LogType::kFloat64 : engine::LogType::kFloat32;
}

void Gps::CopyLatestRow(std::span<double> out) const {
  AIRIS_DEMAND(out.size() == std::size(kColumns));
  out[0] = static_cast<double>(latest_.fix_type);
  out[1] = engine::RadToDeg(latest_.latitude_rad);
  out[2] = engine::RadToDeg(latest_.longitude_rad);
  out[3] = latest_.altitude_m;
  out[4] = latest_.velocity_north_m_s;
  out[5] = latest_.velocity_east_m_s;
  out[6] = latest_.eph_m;
  out[7] = latest_.epv_m;
  out[8] = latest_.position_time_ns < 0 ? std::numeric_limits<double>::quiet_NaN()
                                        : engine::ToSeconds(latest_.position_time_ns);
  out[9] = latest_.velocity_down_m_s;
}

Gps::Truth Gps::Lookup(TimeNs t_ns) const {
  AIRIS_DEMAND(history_size_ > 0);
  const auto at = [this](std::size_t i) -> const Truth& {
    return history_[(history_head_ + i) % history_.size()];
  };
  if (t_ns <= at(0).t_ns) return at(0);
  const Truth& newest = at(history_size_ - 1);
  if (t_ns >= newest.t_ns) return newest;
  // Search from the newest entry: the latency spans only a few fixes. Terminates because at(0) <
  // t_ns.
  std::size_t i = history_size_ - 2;
  while (at(i).t_ns > t_ns) --i;
  const Truth& a = at(i);
  if (a.t_ns == t_ns) return a;  // exact past fix: no interpolation

  // Cubic Hermite between a and b from positions and velocities at both ends; velocity linear.
  const Truth& b = at(i + 1);
  const double h = engine::ToSeconds(b.t_ns - a.t_ns);
  const double s = static_cast<double>(t_ns - a.t_ns) / static_cast<double>(b.t_ns - a.t_ns);
  const double s2 = s * s;
  const double s3 = s2 * s;
  Truth out;
  out.t_ns = t_ns;
  out.p_W = (2 * s3 - 3 * s2 + 1) * a.p_W + (s3 - 2 * s2 + s) * h * a.v_W +
            (-2 * s3 + 3 * s2) * b.p_W + (s3 - s2) * h * b.v_W;
  out.v_W = (1.0 - s) * a.v_W + s * b.v_W;
  return out;
}

void Gps::Sample(const engine::SensorContext& context) {
  AIRIS_DEMAND(context.state != nullptr && context.environment != nullptr);
  const engine::RigidBodyState& s = *context.state;
  const TimeNs now = context.now_ns;

  // Record the antenna's truth now (lever arm included), dropping the oldest entry when full.
  Truth truth;
  truth.t_ns = now;
  truth.p_W = s.p_W + s.q_WB * config_.mount.position_m;
  truth.v_W = s.v_W + s.q_WB * s.w_B.cross(config_.mount.position_m);
  if (history_size_ == history_.size()) {
    history_head_ = (history_head_ + 1) % history_.size();
    --history_size_;
  }
  history_[(history_head_ + history_size_) % history_.size()] = truth;
  ++history_size_;

  if (first_truth_ns_ < 0) first_truth_ns_ = now;

  // Position error: unit-variance slow Gauss-Markov part advanced over the time since the last fix,
  // plus white, scaled by the current accuracy estimates. Every sample draws the same numbers in a
  // fixed order, fix or not, so a fix's noise does not depend on how many came before without one.
  // The step's coefficients (an exp and an expm1) are kept while the fixes stay evenly spaced.
  const TimeNs dt_ns = previous_fix_ns_ < 0 ? 0 : now - previous_fix_ns_;
  previous_fix_ns_ = now;
  if (dt_ns != slow_error_step_ns_) {
    slow_error_step_ =
        GaussMarkovStep::Make(1.0, config_.position_error_correlation_s, engine::ToSeconds(dt_ns));
    slow_error_step_ns_ = dt_ns;
  }
  slow_error_ = slow_error_step_.Next(slow_error_, stream_);
  const Vec3 white = GaussianVec3(stream_, 1.0);
  const double vn_noise = config_.velocity_noise_m_s * engine::StandardNormal(stream_);
  const double ve_noise = config_.velocity_noise_m_s * engine::StandardNormal(stream_);
  const double vd_noise =
      config_.velocity_down_noise_m_s * engine::StandardNormal(vertical_stream_);
  const double eph = CalcEph_m(now);
  const double epv = CalcEpv_m(now);

  latest_.time_ns = now;
  latest_.eph_m = eph;
  latest_.epv_m = epv;
  latest_.fix_type = CalcFixType(now, eph);
  if (latest_.fix_type == engine::GnssFixType::kNoFix) {
    // No fix, no position: a receiver without one has nothing to report but its status.
    constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    latest_.position_time_ns = -1;
    latest_.latitude_rad = latest_.longitude_rad = latest_.altitude_m = kNone;
    latest_.p_W = Vec3::Constant(kNone);
    latest_.velocity_north_m_s = latest_.velocity_east_m_s = latest_.velocity_down_m_s = kNone;
    latest_.ground_speed_m_s = latest_.course_rad = kNone;
    return;
  }

  // A fix reports the state a latency ago, recorded (CalcFixType made sure) at or after the first
  // sample.
  const Truth past = Lookup(now - latency_ns_);
  const double w = config_.position_white_fraction;
  const Vec3 unit_error = std::sqrt(1.0 - w) * slow_error_ + std::sqrt(w) * white;
  const double sigma_h = eph / std::sqrt(2.0);
  const Vec3 error_W =
      Vec3(sigma_h * unit_error.x(), sigma_h * unit_error.y(), epv * unit_error.z());
  const Vec3 p_W = config_.position_noise ? Vec3(past.p_W + error_W) : past.p_W;
  const double vn = past.v_W.x() + vn_noise;
  const double ve = past.v_W.y() + ve_noise;
  const double vd = past.v_W.z() + vd_noise;
  latest_.position_time_ns = past.t_ns;
  const engine::GeodeticPosition g = context.environment->frame().ToGeodetic(p_W);
  latest_.latitude_rad = g.latitude_rad;
  latest_.longitude_rad = g.longitude_rad;
  latest_.altitude_m = g.altitude_m;
  latest_.p_W = p_W;
  latest_.velocity_north_m_s = vn;
  latest_.velocity_east_m_s = ve;
  latest_.velocity_down_m_s = vd;
  latest_.ground_speed_m_s = std::hypot(vn, ve);
  latest_.course_rad = std::atan2(ve, vn);
}

}  // namespace airis::sensors
