#include "tests/sensors/sensor_test_util.h"

#include "engine/core/random.h"

namespace airis::sensors::testing {

using engine::Vec3;

engine::GeodeticPosition ReferenceOrigin() {
  return {engine::DegToRad(47.641468), engine::DegToRad(-122.140165), 122.0};
}

engine::Environment MakeEnvironment(engine::MagneticModelKind magnetic) {
  engine::EnvironmentConfig config;
  config.magnetic_model = magnetic;
  return engine::Environment(config, ReferenceOrigin(), engine::RandomStream(7));
}

engine::RigidBodyAccelerations AtRest(const engine::Environment& environment, const Vec3& p_W) {
  engine::RigidBodyAccelerations a;
  a.gravity_W = Vec3(0.0, 0.0, environment.CalcGravity_m_s2(p_W));
  return a;
}

engine::SensorContext Truth::At(engine::TimeNs now_ns, const engine::Environment& environment,
                                const engine::RayCaster* rays) const {
  engine::SensorContext c;
  c.now_ns = now_ns;
  c.state = &state;
  c.accelerations = &accelerations;
  c.environment = &environment;
  c.rays = rays;
  return c;
}

}  // namespace airis::sensors::testing
