#include "sensors/rangefinder.h"

#include <algorithm>

#include "engine/core/config.h"
#include "engine/core/standard_normal.h"
#include "sensors/sensor_checks.h"

namespace airis::sensors {

namespace {
const std::string kColumns[] = {"hit", "distance_m", "class_id", "instance_id"};
const std::string_view kColumnDocs[] = {
    "1 when a surface was within the range limits, else 0",
    "measured distance along the beam; no_return_distance_m without a return",
    "semantic class of the surface hit, 0 for none",
    "instance of the surface hit, 0 for none",
};
static_assert(std::size(kColumnDocs) == std::size(kColumns));
}  // namespace

void RangefinderConfig::Validate() const {
  engine::RequireRate("rate_hz", rate_hz, engine::kMaxPhysicsRate_hz);
  ValidateNested("mount", mount);
  engine::RequireNonNegative("min_range_m", min_range_m);
  engine::RequirePositive("max_range_m", max_range_m);
  engine::Require(max_range_m > min_range_m, "max_range_m",
                  "must be > min_range_m (got " + engine::FormatNumber(max_range_m) +
                      " <= " + engine::FormatNumber(min_range_m) + ")");
  engine::RequireNonNegative("noise_m", noise_m);
  engine::RequireFinite("no_return_distance_m", no_return_distance_m);
}

void RangefinderConfig::ValidateForPhysicsRate(double physics_rate_hz) const {
  Validate();
  RequireRateWithinPhysics("rate_hz", rate_hz, physics_rate_hz);
}

Rangefinder::Rangefinder(std::string name, const RangefinderConfig& config,
                         engine::RandomStream stream)
    : Sensor(std::move(name), (config.Validate(), config.rate_hz)),
      config_(config),
      stream_(stream),
      beam_B_(config.mount.q_BS() * engine::Vec3::UnitX()) {}

std::span<const std::string> Rangefinder::columns() const { return kColumns; }

std::string_view Rangefinder::column_doc(std::size_t column) const { return kColumnDocs[column]; }

engine::LogType Rangefinder::column_type(std::size_t column) const {
  return column != 1 ? engine::LogType::kInt64 : engine::LogType::kFloat32;
}

void Rangefinder::CopyLatestRow(std::span<double> out) const {
  AIRIS_DEMAND(out.size() == std::size(kColumns));
  out[0] = latest_.hit ? 1.0 : 0.0;
  out[1] = latest_.distance_m;
  out[2] = latest_.class_id;
  out[3] = latest_.instance_id;
}

void Rangefinder::Sample(const engine::SensorContext& context) {
  AIRIS_DEMAND(context.state != nullptr);
  const engine::RigidBodyState& s = *context.state;
  engine::Ray ray;
  ray.origin_W = s.p_W + s.q_WB * config_.mount.position_m;
  ray.direction_W = s.q_WB * beam_B_;
  ray.min_range_m = static_cast<float>(config_.min_range_m);
  ray.max_range_m = static_cast<float>(config_.max_range_m);
  engine::RayHit hit;
  if (context.rays != nullptr) context.rays->Cast({&ray, 1}, {&hit, 1});

  // One draw per sample whether or not there is a return, so the stream does not depend on the
  // scene.
  const double noise_m = config_.noise_m * engine::StandardNormal(stream_);
  latest_.time_ns = context.now_ns;
  latest_.hit = hit.hit();
  latest_.min_range_m = static_cast<float>(config_.min_range_m);
  latest_.max_range_m = static_cast<float>(config_.max_range_m);
  if (latest_.hit) {
    latest_.distance_m = static_cast<float>(std::clamp(
        static_cast<double>(hit.distance_m) + noise_m, config_.min_range_m, config_.max_range_m));
  } else {
    latest_.distance_m = static_cast<float>(config_.no_return_distance_m);
  }
  latest_.class_id = hit.class_id;
  latest_.instance_id = hit.instance_id;
}

}  // namespace airis::sensors
