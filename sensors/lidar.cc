#include "sensors/lidar.h"

#include <algorithm>
#include <cmath>

#include "engine/core/config.h"
#include "engine/core/standard_normal.h"
#include "sensors/sensor_checks.h"

namespace airis::sensors {

namespace {
const std::string kColumns[] = {"point_count", "hit_count", "nearest_m"};
const std::string_view kColumnDocs[] = {
    "beams per scan: channels x columns",
    "beams that returned (the points of the scan file)",
    "range of the nearest return, 0 without one",
};
static_assert(std::size(kColumnDocs) == std::size(kColumns));
}  // namespace

void LidarConfig::Validate() const {
  engine::RequireRate("rotation_rate_hz", rotation_rate_hz, engine::kMaxPhysicsRate_hz);
  ValidateNested("mount", mount);
  engine::RequireInRange("channels", channels, 1, 1024);
  engine::RequireInRange("vertical_fov_upper_deg", vertical_fov_upper_deg, -90.0, 90.0);
  engine::RequireInRange("vertical_fov_lower_deg", vertical_fov_lower_deg, -90.0,
                         vertical_fov_upper_deg);
  engine::RequireInRange("horizontal_fov_deg", horizontal_fov_deg, 0.0, 360.0);
  engine::RequirePositive("horizontal_fov_deg", horizontal_fov_deg);
  engine::RequireInRange("horizontal_resolution_deg", horizontal_resolution_deg, 1e-3, 360.0);
  engine::RequireNonNegative("min_range_m", min_range_m);
  engine::RequirePositive("max_range_m", max_range_m);
  engine::Require(max_range_m > min_range_m, "max_range_m",
                  "must be > min_range_m (got " + engine::FormatNumber(max_range_m) +
                      " <= " + engine::FormatNumber(min_range_m) + ")");
  engine::RequireNonNegative("range_noise_m", range_noise_m);
  engine::Require(channel_elevations_deg.size() <= 1024, "channel_elevations_deg",
                  "must list at most 1024 channels");
  for (std::size_t i = 0; i < channel_elevations_deg.size(); ++i) {
    engine::RequireInRange("channel_elevations_deg[" + std::to_string(i) + "]",
                           channel_elevations_deg[i], -90.0, 90.0);
  }
  const double rays = static_cast<double>(CalcElevations_deg().size()) * CalcColumns();
  engine::Require(
      rays <= static_cast<double>(engine::kMaxLidarRaysPerScan), "horizontal_resolution_deg",
      "gives " + engine::FormatNumber(rays) + " rays per scan, more than the limit of " +
          std::to_string(engine::kMaxLidarRaysPerScan) + " (docs/limits.md)");
}

void LidarConfig::ValidateForPhysicsRate(double physics_rate_hz) const {
  Validate();
  RequireRateWithinPhysics("rotation_rate_hz", rotation_rate_hz, physics_rate_hz);
}

std::vector<double> LidarConfig::CalcElevations_deg() const {
  if (!channel_elevations_deg.empty()) return channel_elevations_deg;
  std::vector<double> out(static_cast<std::size_t>(std::max(channels, 0)));
  const double step =
      channels > 1 ? (vertical_fov_upper_deg - vertical_fov_lower_deg) / (channels - 1) : 0.0;
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = vertical_fov_lower_deg + step * k;
  return out;
}

int LidarConfig::CalcColumns() const {
  return std::max(1, static_cast<int>(std::lround(horizontal_fov_deg / horizontal_resolution_deg)));
}

Lidar::Lidar(std::string name, const LidarConfig& config, engine::RandomStream stream)
    : Sensor(std::move(name), (config.Validate(), config.rotation_rate_hz)),
      config_(config),
      stream_(stream) {
  const int columns = config.CalcColumns();
  const std::vector<double> elevations_deg = config.CalcElevations_deg();
  const auto channels = static_cast<int>(elevations_deg.size());
  const std::size_t n = static_cast<std::size_t>(columns) * elevations_deg.size();
  // Full turns start at azimuth 0; partial sweeps are centred on the sensor's x axis.
  const double step_deg = config.horizontal_fov_deg / columns;
  const double first_azimuth_deg =
      config.horizontal_fov_deg >= 360.0 ? 0.0 : -0.5 * config.horizontal_fov_deg + 0.5 * step_deg;
  directions_S_.reserve(n);
  for (int c = 0; c < columns; ++c) {
    const double azimuth = engine::DegToRad(first_azimuth_deg + c * step_deg);
    for (double elevation_deg : elevations_deg) {
      const double elevation = engine::DegToRad(elevation_deg);
      directions_S_.emplace_back(static_cast<float>(std::cos(elevation) * std::cos(azimuth)),
                                 static_cast<float>(std::cos(elevation) * std::sin(azimuth)),
                                 static_cast<float>(-std::sin(elevation)));
    }
  }
  rays_.resize(n);
  hits_.resize(n);
  scan_.channels = channels;
  scan_.columns = columns;
  scan_.points.resize(n);
  engine::ScanPattern& pattern = cloud_.pattern;
  pattern.mount = config.mount;
  pattern.ring_elevations_deg = elevations_deg;
  pattern.columns = columns;
  pattern.horizontal_fov_deg = config.horizontal_fov_deg;
  pattern.min_range_m = config.min_range_m;
  pattern.max_range_m = config.max_range_m;
  pattern.motion_distortion = config.motion_distortion;
  cloud_.points.reserve(n);
}

double Lidar::points_per_second() const {
  return static_cast<double>(scan_.points.size()) * config_.rotation_rate_hz;
}

std::span<const std::string> Lidar::columns() const { return kColumns; }

std::string_view Lidar::column_doc(std::size_t column) const { return kColumnDocs[column]; }

engine::LogType Lidar::column_type(std::size_t column) const {
  return column != 2 ? engine::LogType::kInt64 : engine::LogType::kFloat32;
}

void Lidar::CopyLatestRow(std::span<double> out) const {
  AIRIS_DEMAND(out.size() == std::size(kColumns));
  float nearest = 0.0f;
  bool any = false;
  for (const LidarPoint& p : scan_.points) {
    if (p.hit && (!any || p.range_m < nearest)) {
      nearest = p.range_m;
      any = true;
    }
  }
  out[0] = static_cast<double>(scan_.points.size());
  out[1] = static_cast<double>(scan_.hit_count);
  out[2] = any ? nearest : 0.0;
}

double Lidar::column_time_offset_s(int column) const {
  if (!config_.motion_distortion) return 0.0;
  // The head sweeps horizontal_fov_deg of each full turn; the last column fires at the scan time.
  const double sweep_s = config_.horizontal_fov_deg / 360.0 / config_.rotation_rate_hz;
  return sweep_s * static_cast<double>(scan_.columns - 1 - column) / scan_.columns;
}

void Lidar::Sample(const engine::SensorContext& context) {
  AIRIS_DEMAND(context.state != nullptr);
  const engine::RigidBodyState& s = *context.state;
  const engine::Vec3& p_BS = config_.mount.position_m;
  const engine::Quat q_BS = config_.mount.q_BS();
  scan_.time_ns = context.now_ns;
  scan_.p_WS = s.p_W + s.q_WB * p_BS;
  scan_.q_WS = s.q_WB * q_BS;
  const engine::Vec3 v_WS = s.v_W + s.q_WB * s.w_B.cross(p_BS);
  const auto min_range = static_cast<float>(config_.min_range_m);
  const auto max_range = static_cast<float>(config_.max_range_m);

  // Each column is cast from the pose the sensor had when it fired, dt earlier: the body moved back
  // at its current velocity and angular velocity (q_WB(t - dt) = q_WB(t) exp(-w_B dt)).
  const auto channels = static_cast<std::size_t>(scan_.channels);
  for (int c = 0; c < scan_.columns; ++c) {
    const double dt_s = column_time_offset_s(c);
    const engine::Vec3 p_WS = scan_.p_WS - dt_s * v_WS;
    const engine::Mat3 R_WS =
        (s.q_WB * engine::QuatExp(-dt_s * s.w_B) * q_BS).normalized().toRotationMatrix();
    for (std::size_t i = c * channels; i < (c + 1) * channels; ++i) {
      engine::Ray& ray = rays_[i];
      ray.origin_W = p_WS;
      ray.direction_W = R_WS * directions_S_[i].cast<double>();
      ray.min_range_m = min_range;
      ray.max_range_m = max_range;
    }
  }
  if (context.rays != nullptr) {
    context.rays->Cast(rays_, hits_);
  } else {
    std::fill(hits_.begin(), hits_.end(), engine::RayHit{});
  }

  // One draw per point whether or not it returns, so the stream does not depend on the scene.
  std::size_t hit_count = 0;
  cloud_.points.clear();  // keeps its capacity: no allocation
  for (std::size_t i = 0; i < hits_.size(); ++i) {
    const engine::RayHit& hit = hits_[i];
    LidarPoint& point = scan_.points[i];
    const double noise_m = config_.range_noise_m * engine::StandardNormal(stream_);
    point.hit = hit.hit();
    point.class_id = hit.class_id;
    point.instance_id = hit.instance_id;
    if (!point.hit) {
      point.range_m = 0.0f;
      continue;
    }
    point.range_m = std::clamp(static_cast<float>(hit.distance_m + noise_m), min_range, max_range);
    ++hit_count;
    const auto column = static_cast<int>(i / channels);
    engine::PointReturn& r = cloud_.points.emplace_back();
    r.p_S_m = CalcPoint_S(i);
    r.range_m = point.range_m;
    // Lambertian: the normal faces the ray origin, so -n . d is the cosine of the incidence.
    const float cos_incidence = -hit.normal_W.dot(rays_[i].direction_W.cast<float>());
    r.intensity = hit.reflectivity * std::clamp(cos_incidence, 0.0f, 1.0f);
    r.time_offset_s = static_cast<float>(-column_time_offset_s(column));
    r.instance_id = hit.instance_id;
    r.ring = static_cast<std::uint16_t>(i % channels);
    r.column = static_cast<std::uint32_t>(column);
    r.class_id = hit.class_id;
  }
  scan_.hit_count = hit_count;
  cloud_.time_ns = scan_.time_ns;
  cloud_.p_WS = scan_.p_WS;
  cloud_.q_WS = scan_.q_WS;
  cloud_.v_WS_m_s = v_WS;
  cloud_.w_S_rad_s = q_BS.conjugate() * s.w_B;
}

}  // namespace airis::sensors
