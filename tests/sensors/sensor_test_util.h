#pragma once

#include <cstdint>
#include <vector>

#include "engine/environment/environment.h"
#include "engine/physics/rigid_body_state.h"
#include "engine/scene/static_scene.h"
#include "engine/world/sensor.h"
#include "tests/fixtures/box_scenes.h"

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

// The box scenes of tests/fixtures, by their old names here.
using airis::testing::BoxSpec;
using airis::testing::MakeBoxScene;
using airis::testing::MakeCityOfBoxes;

}  // namespace airis::sensors::testing
