#pragma once

#include <cstdint>
#include <vector>

#include "engine/core/static_scene.h"
#include "engine/environment/environment.h"
#include "engine/physics/rigid_body_state.h"
#include "engine/world/sensor.h"

namespace airis::sensors::testing {

/// The reference implementation's default geodetic origin (47.641468 N, -122.140165 E, 122 m).
engine::GeodeticPosition ReferenceOrigin();

/// A real Environment about ReferenceOrigin() with the given magnetic model and no wind.
engine::Environment MakeEnvironment(
    engine::MagneticModelKind magnetic = engine::MagneticModelKind::kWmm);

/// Accelerations of a body at rest at p_W: a_W = 0 and gravity from the environment.
engine::RigidBodyAccelerations AtRest(const engine::Environment& environment,
                                      const engine::Vec3& p_W);

/// Everything a sensor reads, owned in one place so tests can build SensorContexts at chosen times.
struct Truth {
  engine::RigidBodyState state;
  engine::RigidBodyAccelerations accelerations;
  engine::SensorContext At(engine::TimeNs now_ns, const engine::Environment& environment,
                           const engine::RayCaster* rays = nullptr) const;
};

/// A unit box centred on its origin (24 vertices, 12 triangles counter-clockwise seen from
/// outside).
engine::TriangleMesh MakeUnitBoxMesh();

/// A box of the scene: centre, size, rotation (yaw about world z, then pitch about the box's y) and
/// labels.
struct BoxSpec {
  engine::Vec3 center_W = engine::Vec3::Zero();
  engine::Vec3 size_m = engine::Vec3::Ones();
  double yaw_rad = 0.0;
  double pitch_rad = 0.0;
  std::uint8_t class_id = 1;
  std::uint32_t instance_id = 1;
  engine::CollisionShape collision = engine::CollisionShape::kAuto;
};

/// A StaticScene whose objects are scaled instances of one unit-box mesh and one model.
engine::StaticScene MakeBoxScene(const std::vector<BoxSpec>& boxes);

/// `count` boxes (2-20 m wide, 5-60 m tall, standing on z = 0, random yaw) scattered over a square
/// of side `extent_m` centred on the origin; fixed seed. Instance ids 1..count, classes 1 + i % 4.
engine::StaticScene MakeCityOfBoxes(int count, double extent_m, std::uint64_t seed);

}  // namespace airis::sensors::testing
