#include "scenes/mission_limits.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/limits.h"
#include "engine/mission/mission_check.h"
#include "scenes/scene_stats.h"

namespace airis::scenes {
namespace {

/// True when point `p` (in a unit primitive's frame) lies in that closed convex primitive.
bool InsideUnitPrimitive(engine::Primitive primitive, const Eigen::Vector3d& p) {
  switch (primitive) {
    case engine::Primitive::kBox:
      return p.cwiseAbs().maxCoeff() <= 0.5;
    case engine::Primitive::kSphere:
      return p.norm() <= 0.5;
    case engine::Primitive::kCylinder:
      return p.head<2>().norm() <= 0.5 && std::abs(p.z()) <= 0.5;
    default:
      return false;
  }
}

/// True when every corner of `box` (world NED) lies in object `o`: then, the shape being convex,
/// the whole box does.
bool BoxInsideObject(const engine::StaticScene& scene, const engine::StaticObject& o,
                     const Eigen::AlignedBox3d& box) {
  if (o.collision == engine::CollisionShape::kNone) return false;
  const engine::Model& model = scene.models[o.model];
  const Eigen::Affine3d T_OW = o.T_WO.inverse();
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d corner = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k));
    const Eigen::Vector3d p_O = T_OW * corner;
    if (o.collision == engine::CollisionShape::kBox) {
      if (!model.bounds.cast<double>().contains(p_O)) return false;
      continue;
    }
    if (model.parts.size() != 1) return false;
    const engine::ModelPart& part = model.parts.front();
    const engine::Primitive primitive = scene.meshes[part.mesh].primitive;
    const Eigen::Vector3d p_P = part.T_MP.cast<double>().inverse() * p_O;
    if (!InsideUnitPrimitive(primitive, p_P)) return false;
  }
  return true;
}

}  // namespace

engine::MissionLimits CalcMissionLimits(const Scene& scene, std::size_t vehicle) {
  engine::MissionLimits limits;
  Eigen::AlignedBox3d extent = CalcSceneStats(scene).bounds_W;
  for (const VehicleDescription& v : scene.vehicles) extent.extend(v.start.p_W);
  if (extent.isEmpty()) extent.extend(engine::Vec3::Zero());
  const engine::Vec3 margin(kFlightMargin_m, kFlightMargin_m, 0.0);
  limits.region_W =
      Eigen::AlignedBox3d(engine::Vec3(extent.min().x() - margin.x(), extent.min().y() - margin.y(),
                                       -engine::kMaxFlightHeight_m),
                          engine::Vec3(extent.max().x() + margin.x(), extent.max().y() + margin.y(),
                                       std::max(extent.max().z(), 0.0)));
  limits.has_ground = scene.has_ground;
  limits.terrain = scene.static_scene->terrain.heightfield;
  limits.max_speed_m_s = scene.vehicles.at(vehicle).spec->CalcMaxSpeed_m_s();
  limits.physics_rate_hz = scene.physics.rate_hz;
  limits.vehicle = scene.vehicles.at(vehicle).name;
  // A capture step names cameras of its own vehicle: a camera (rig) or one of its image streams.
  for (const SensorDescription& s : scene.vehicles.at(vehicle).sensors) {
    std::vector<std::string> streams = s.spec->ImageStreamNames(s.name);
    if (streams.empty()) continue;
    if (std::find(streams.begin(), streams.end(), s.name) == streams.end()) {
      limits.cameras.push_back(s.name);
    }
    for (std::string& name : streams) limits.cameras.push_back(std::move(name));
  }
  const engine::StaticScene* statics = scene.static_scene.get();
  limits.inside_object = [statics](const Eigen::AlignedBox3d& box) {
    for (const engine::StaticObject& o : statics->objects) {
      if (BoxInsideObject(*statics, o, box)) return true;
    }
    return false;
  };
  return limits;
}

void CheckMissionInScene(const engine::Mission& mission, const Scene& scene,
                         std::span<const std::size_t> vehicles,
                         std::span<const engine::Vec3> starts_W) {
  AIRIS_DEMAND(starts_W.empty() || starts_W.size() == vehicles.size());
  std::vector<engine::TrackLimits> tracks;
  for (std::size_t t = 0; t < vehicles.size(); ++t) {
    const std::size_t v = vehicles[t];
    tracks.push_back({CalcMissionLimits(scene, v),
                      starts_W.empty() ? scene.vehicles.at(v).start.p_W : starts_W[t]});
  }
  engine::CheckMission(mission, tracks, engine::LocalNedFrame(scene.origin));
  // A drawn value that changes nothing would still be written with every frame, as if it had.
  const engine::SkyModel sky = scene.static_scene->lighting.sky;
  if (mission.randomize.turbidity && sky != engine::SkyModel::kClear) {
    const std::string key = "randomize.turbidity";
    throw engine::ConfigError(
        mission.locate ? mission.locate(key) : engine::SourceLocation{mission.file, 0, 0}, key,
        "turbidity shapes the clear sky only, and the scene's sky is '" +
            std::string(engine::ToString(sky)) +
            "': set scene.lighting.sky: clear, or draw no turbidity");
  }
}

}  // namespace airis::scenes
