#include "engine/mavlink/px4/hil_sensor_feed.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/core/frames.h"
#include "engine/mavlink/enums.h"

namespace airis::engine::mavlink {
namespace {

constexpr double kStandardGravity = 9.80665;  // m/s^2, for mG

constexpr std::uint32_t kAccelFields =
    kHilSensorUpdatedXacc | kHilSensorUpdatedYacc | kHilSensorUpdatedZacc;
constexpr std::uint32_t kGyroFields =
    kHilSensorUpdatedXgyro | kHilSensorUpdatedYgyro | kHilSensorUpdatedZgyro;
constexpr std::uint32_t kMagFields =
    kHilSensorUpdatedXmag | kHilSensorUpdatedYmag | kHilSensorUpdatedZmag;
// PX4 takes the barometer only with all three (0x200 alone means no barometer).
constexpr std::uint32_t kBaroFields =
    kHilSensorUpdatedAbsPressure | kHilSensorUpdatedPressureAlt | kHilSensorUpdatedTemperature;

// MAV_SENSOR_ORIENTATION of the body axis nearest a beam direction.
std::uint8_t Orientation(const Vec3& beam_B) {
  struct Axis {
    Vec3 direction;
    std::uint8_t orientation;
  };
  static const Axis kAxes[] = {{{1, 0, 0}, 0},  {{0, 1, 0}, 2},   {{-1, 0, 0}, 4},
                               {{0, -1, 0}, 6}, {{0, 0, -1}, 24}, {{0, 0, 1}, 25}};
  const Axis* best = &kAxes[0];
  for (const Axis& a : kAxes) {
    if (a.direction.dot(beam_B) > best->direction.dot(beam_B)) best = &a;
  }
  return best->orientation;
}

template <class T>
T ClampTo(double v) {
  const double lo = static_cast<double>(std::numeric_limits<T>::min());
  const double hi = static_cast<double>(std::numeric_limits<T>::max());
  return static_cast<T>(std::clamp(std::round(v), lo, hi));
}

std::int32_t DegE7(double rad) { return ClampTo<std::int32_t>(RadToDeg(rad) * 1e7); }

}  // namespace

std::uint64_t UnixTimeUsFromDecimalYear(double decimal_year) {
  const int year = static_cast<int>(std::floor(decimal_year));
  const auto leap = [](int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; };
  std::int64_t days = 0;
  for (int y = 1970; y < year; ++y) days += leap(y) ? 366 : 365;
  const double seconds = static_cast<double>(days) * 86400.0 +
                         (decimal_year - year) * (leap(year) ? 366 : 365) * 86400.0;
  return static_cast<std::uint64_t>(std::llround(seconds * 1e6));
}

HilSensorFeed::HilSensorFeed(std::span<const std::unique_ptr<Sensor>> sensors,
                             std::uint64_t utc_start_us, int satellites_visible)
    : utc_start_us_(utc_start_us), satellites_visible_(satellites_visible) {
  for (const auto& owned : sensors) {
    Sensor* s = owned.get();
    if (s->inertial() && !imu_) {
      imu_ = s;
      s->AddListener([this](const Sensor& imu) {
        const Quat q_BS = imu.q_BS();
        gyro_sum_B_ += q_BS * imu.inertial()->angular_velocity_S_rad_s;
        accel_sum_B_ += q_BS * imu.inertial()->specific_force_S_m_s2;
        ++imu_samples_;
      });
    } else if (s->barometric() && !barometer_) {
      barometer_ = s;
      s->AddListener([this](const Sensor&) { new_baro_ = true; });
    } else if (s->magnetic() && !magnetometer_) {
      magnetometer_ = s;
      s->AddListener([this](const Sensor&) { new_mag_ = true; });
    } else if (s->gnss() && !gps_) {
      gps_ = s;
      s->AddListener([this](const Sensor&) { new_gps_ = true; });
    } else if (s->range() && !rangefinder_) {
      rangefinder_ = s;
      s->AddListener([this](const Sensor&) { new_range_ = true; });
    }
  }
}

std::string HilSensorFeed::DescribeMissing() const {
  std::string out;
  if (!imu_) out += "no IMU (PX4 has no clock without HIL_SENSOR accelerometer and gyroscope)\n";
  if (!magnetometer_) out += "no magnetometer (PX4: 'Compass Sensor 0 missing')\n";
  if (!barometer_) out += "no barometer (PX4: 'barometer 0 missing')\n";
  if (!gps_) out += "no GPS (PX4 has no global position and refuses to take off)\n";
  return out;
}

bool HilSensorFeed::TakeHilSensor(std::uint64_t time_usec, HilSensor* out) {
  if (imu_samples_ == 0) return false;
  *out = HilSensor{};
  out->time_usec = time_usec;
  const Vec3 gyro = gyro_sum_B_ / imu_samples_;
  const Vec3 accel = accel_sum_B_ / imu_samples_;
  out->xacc = static_cast<float>(accel.x());
  out->yacc = static_cast<float>(accel.y());
  out->zacc = static_cast<float>(accel.z());
  out->xgyro = static_cast<float>(gyro.x());
  out->ygyro = static_cast<float>(gyro.y());
  out->zgyro = static_cast<float>(gyro.z());
  out->fields_updated = kAccelFields | kGyroFields;
  gyro_sum_B_.setZero();
  accel_sum_B_.setZero();
  imu_samples_ = 0;
  if (new_mag_) {
    const Vec3 m_B = magnetometer_->q_BS() * magnetometer_->magnetic()->field_S_gauss;
    out->xmag = static_cast<float>(m_B.x());
    out->ymag = static_cast<float>(m_B.y());
    out->zmag = static_cast<float>(m_B.z());
    out->fields_updated |= kMagFields;
    new_mag_ = false;
  }
  if (new_baro_) {
    const BarometricSample& b = *barometer_->barometric();
    out->abs_pressure = static_cast<float>(b.pressure_pa / 100.0);
    out->pressure_alt = static_cast<float>(b.altitude_m);
    out->temperature = static_cast<float>(b.temperature_k - 273.15);
    out->fields_updated |= kBaroFields;
    new_baro_ = false;
  }
  out->id = 0;
  return true;
}

bool HilSensorFeed::TakeHilGps(HilGps* out) {
  if (!new_gps_) return false;
  new_gps_ = false;
  const GnssSample& g = *gps_->gnss();
  *out = HilGps{};
  out->time_usec = utc_start_us_ + static_cast<std::uint64_t>(g.time_ns / 1000);
  out->eph = ClampTo<std::uint16_t>(g.eph_m * 100.0);  // PX4 reads cm of accuracy
  out->epv = ClampTo<std::uint16_t>(g.epv_m * 100.0);
  out->vel = std::uint16_t{65535};  // unknown (HIL_GPS: UINT16_MAX)
  out->cog = std::uint16_t{65535};
  out->fix_type = static_cast<std::uint8_t>(g.fix_type);
  if (g.fix_type != GnssFixType::kNoFix) {  // without a fix the receiver has no position: zeros
    out->lat = DegE7(g.latitude_rad);
    out->lon = DegE7(g.longitude_rad);
    out->alt = ClampTo<std::int32_t>(g.altitude_m * 1000.0);  // the ellipsoid height (docs/px4.md)
    out->vel = ClampTo<std::uint16_t>(g.ground_speed_m_s * 100.0);
    out->vn = ClampTo<std::int16_t>(g.velocity_north_m_s * 100.0);
    out->ve = ClampTo<std::int16_t>(g.velocity_east_m_s * 100.0);
    out->vd = ClampTo<std::int16_t>(g.velocity_down_m_s * 100.0);
    double course_deg = RadToDeg(g.course_rad);
    if (course_deg < 0) course_deg += 360.0;
    if (g.ground_speed_m_s > 0.1) {  // else unknown when hovering
      out->cog = ClampTo<std::uint16_t>(std::fmod(course_deg, 360.0) * 100.0);
    }
  }
  out->satellites_visible =
      g.fix_type == GnssFixType::k3D ? static_cast<std::uint8_t>(satellites_visible_) : 0;
  out->id = 0;
  return true;
}

bool HilSensorFeed::TakeDistanceSensor(std::uint32_t time_boot_ms, DistanceSensor* out) {
  if (!new_range_) return false;
  new_range_ = false;
  const RangeSample& r = *rangefinder_->range();
  *out = DistanceSensor{};
  out->time_boot_ms = time_boot_ms;
  out->min_distance = ClampTo<std::uint16_t>(r.min_range_m * 100.0);
  out->max_distance = ClampTo<std::uint16_t>(r.max_range_m * 100.0);
  // Without a return PX4 expects a reading beyond max_distance (out of range).
  out->current_distance = ClampTo<std::uint16_t>(
      (r.hit ? static_cast<double>(r.distance_m) : r.max_range_m + 1.0) * 100.0);
  out->type = kMavDistanceSensorLaser;
  out->id = 0;
  out->orientation = Orientation(rangefinder_->q_BS() * Vec3::UnitX());
  out->covariance = 255;  // unknown
  return true;
}

HilStateQuaternion HilSensorFeed::MakeState(std::uint64_t time_usec, const RigidBodyState& s,
                                            const RigidBodyAccelerations& a,
                                            const LocalNedFrame& frame, const Vec3& gravity_W,
                                            const Vec3& wind_W) {
  HilStateQuaternion m;
  m.time_usec = time_usec;
  m.attitude_quaternion = {static_cast<float>(s.q_WB.w()), static_cast<float>(s.q_WB.x()),
                           static_cast<float>(s.q_WB.y()), static_cast<float>(s.q_WB.z())};
  m.rollspeed = static_cast<float>(s.w_B.x());
  m.pitchspeed = static_cast<float>(s.w_B.y());
  m.yawspeed = static_cast<float>(s.w_B.z());
  const GeodeticPosition g = frame.ToGeodetic(s.p_W);
  m.lat = DegE7(g.latitude_rad);
  m.lon = DegE7(g.longitude_rad);
  m.alt = ClampTo<std::int32_t>(g.altitude_m * 1000.0);
  m.vx = ClampTo<std::int16_t>(s.v_W.x() * 100.0);
  m.vy = ClampTo<std::int16_t>(s.v_W.y() * 100.0);
  m.vz = ClampTo<std::int16_t>(s.v_W.z() * 100.0);
  const double airspeed = (s.v_W - wind_W).norm() * 100.0;
  m.ind_airspeed = ClampTo<std::uint16_t>(airspeed);
  m.true_airspeed = ClampTo<std::uint16_t>(airspeed);
  const Vec3 f_B = s.q_WB.conjugate() * (a.a_W - gravity_W);  // specific force, body axes
  m.xacc = ClampTo<std::int16_t>(f_B.x() / kStandardGravity * 1000.0);
  m.yacc = ClampTo<std::int16_t>(f_B.y() / kStandardGravity * 1000.0);
  m.zacc = ClampTo<std::int16_t>(f_B.z() / kStandardGravity * 1000.0);
  return m;
}

}  // namespace airis::engine::mavlink
