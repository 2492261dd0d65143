#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>

#include "engine/world/ray_caster.h"
#include "engine/world/world.h"
#include "scenes/scene.h"

namespace airis::engine {
class RenderScene;
}  // namespace airis::engine

namespace airis::scenes {

/// Builds the World of a loaded scene: the static scene (shared with collision and ray casting),
/// the environment about the scene's origin, an Embree ray caster over the collidable geometry
/// (SceneRayCaster: built when a sensor casts rays), each vehicle (of its kind and preset, in its
/// start state) and its sensors. Random streams derive from the scene seed by name:
/// `environment/wind`, `vehicles/NAME/SENSOR`. Throws ConfigError at the key of each config the
/// engine rejects (a sensor faster than the scene's physics rate, an on_ground vehicle with nothing
/// below it, a vehicle whose body overlaps an object or another vehicle where it starts, ...),
/// every vehicle's mistakes together.
std::unique_ptr<engine::World> BuildWorld(const Scene& scene);

/// As BuildWorld, without a GL context: every vehicle and sensor is built and checked as for a run
/// except the cameras, whose configs are checked (nothing renders). `airis scene check` builds
/// this, so that it refuses what a run would.
std::unique_ptr<engine::World> BuildWorldWithoutCameras(const Scene& scene);

/// The static scene's ray caster (Embree, engine/world/embree_ray_caster.h), built by Build or else
/// by the first Cast. BuildWorld builds it with the world when a vehicle has a sensor that casts
/// rays (rangefinder, lidar: SensorSpec::casts_rays), on a second thread while the collision world
/// is built, so that no flight stops at its first scan and `scene check` refuses what the run
/// would; a world without one never builds it, which spares a 10 km forest's check 1.4 to 3.3 s
/// and 450 MB (docs/performance.md). Thread-safe: concurrent first calls build it once; a build
/// that throws throws from that call, and the next one tries again.
class SceneRayCaster final : public engine::RayCaster {
 public:
  explicit SceneRayCaster(std::shared_ptr<const engine::StaticScene> scene);
  ~SceneRayCaster() override;
  /// Builds the acceleration structures now, unless built already.
  void Build() const;
  /// Whether they are built.
  bool built() const { return built_flag_.load(std::memory_order_acquire); }
  void Cast(std::span<const engine::Ray> rays, std::span<engine::RayHit> hits) const override;

 private:
  std::shared_ptr<const engine::StaticScene> scene_;
  mutable std::once_flag built_;
  mutable std::atomic<bool> built_flag_ = false;
  mutable std::unique_ptr<const engine::RayCaster> caster_;
};

/// The immutable parts of a scene's World, which worlds built again from the same loaded scene can
/// share instead of making each anew: the static scene, the ray caster over it (its Cast is const
/// and thread-safe; built only for worlds that cast rays: SceneRayCaster) and the cameras' GPU copy
/// of it (made by the first camera; rendering stays on one thread at a time). Empty members are
/// made by the first BuildWorld that needs them.
struct WorldResources {
  std::shared_ptr<const engine::StaticScene> static_scene;
  std::shared_ptr<const SceneRayCaster> ray_caster;
  std::shared_ptr<const engine::RenderScene> render_scene;
};

/// As BuildWorld(scene), with the random streams of `seed` in place of scene.seed and the
/// immutable parts taken from (or, while empty, stored into) `shared`. For front ends that build
/// many worlds of one scene: a learning environment rebuilds its world on every reset, each
/// episode with its own seed. The same scene and seed give the same world as BuildWorld does.
std::unique_ptr<engine::World> BuildWorld(const Scene& scene, std::uint64_t seed,
                                          WorldResources& shared);

}  // namespace airis::scenes
