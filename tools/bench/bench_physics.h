#pragma once

#include <Eigen/Geometry>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "engine/physics/rigid_body_state.h"
#include "engine/scene/static_scene.h"

namespace airis::tools {

/// What `airis bench physics` measures.
struct PhysicsBenchOptions {
  int boxes = 10000;         ///< static boxes in the city scene
  double extent_m = 1000.0;  ///< side of the square they are spread over
  double min_seconds = 1.0;  ///< wall-clock time per measurement (at least)
  std::uint64_t seed = 1;    ///< layout and route
};

/// A ground plane (2 x extent) plus `box_count` boxes 2-8 m wide and 5-30 m tall standing on it,
/// spread uniformly over `extent_m` x `extent_m` about the origin (random yaw).
engine::StaticScene MakeBoxFieldScene(int box_count, double extent_m, std::uint64_t seed);

/// Start states of the legs the quad flies: 1.5-4 m up at random points of the field (the middle
/// 90 % of it), 4-12 m/s level in a random direction, level attitude, so it passes near boxes and
/// sometimes hits them.
std::vector<engine::RigidBodyState> MakeRoute(int legs, double extent_m, std::uint64_t seed);

/// The same over `area_ne` (north, east; m), 1.5-4 m above `ground_m(north, east)` (m, up).
std::vector<engine::RigidBodyState> MakeRouteOver(
    int legs, const Eigen::AlignedBox2d& area_ne,
    const std::function<double(double, double)>& ground_m, std::uint64_t seed);

/// Calls of `tick` per wall-clock second, in rounds of 1,000 after 1,000 for warming up, for at
/// least `min_seconds` (a template: the call costs nothing next to a tick).
template <class F>
double TicksPerSecond(F&& tick, double min_seconds) {
  for (int i = 0; i < 1000; ++i) tick();  // warm-up: caches, pools, first contacts
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  std::int64_t n = 0;
  double elapsed = 0.0;
  do {
    for (int i = 0; i < 1000; ++i) tick();
    n += 1000;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  } while (elapsed < min_seconds);
  return static_cast<double>(n) / elapsed;
}

/// Rolling hills (up to 60 m of relief, slopes under 20 degrees) sampled every 10 m over
/// `extent_m` x `extent_m` about the origin, as a scene's terrain (chunks, class 15, friction 0.8),
/// with nothing else.
engine::StaticScene MakeHillsScene(double extent_m);

/// Height of MakeHillsScene's surface at (north, east) (m, up).
double HillsHeight_m(const engine::StaticScene& hills, double north_m, double east_m);

/// Puts the reference quad-x at rest on the ground under `state`'s position, keeping its heading:
/// lying on MakeHillsScene's surface `hills` (tilted with the triangle under it), or on the ground
/// plane where `hills` is null.
void ParkOnSurface(const engine::StaticScene* hills, engine::RigidBodyState& state);

/// Ticks the reference quad-x in our World (rotors with lag at hover, drag, gravity and atmosphere
/// at its altitude, RK4, collision query and contact response) through a box field. Every
/// kTicksPerLeg ticks it restarts from the next leg of the route.
class PhysicsTickScenario {
 public:
  static constexpr int kTicksPerLeg = 500;
  /// `box_count` = 0: the empty world (ground plane only).
  PhysicsTickScenario(int box_count, double extent_m, std::uint64_t seed);
  /// The quad in `scene`, restarted every kTicksPerLeg ticks from the next state of `route`, its
  /// rotors at hover (`rotors_on`) or stopped (a parked quad: see ParkOnSurface).
  PhysicsTickScenario(std::shared_ptr<const engine::StaticScene> scene,
                      std::vector<engine::RigidBodyState> route, bool rotors_on);
  ~PhysicsTickScenario();
  /// One simulation tick.
  void Tick();
  /// Ticks so far in which the quad had at least one contact.
  std::int64_t contact_ticks() const { return contact_ticks_; }
  std::int64_t ticks() const { return ticks_; }

 private:
  struct State;
  std::unique_ptr<State> s_;
  std::int64_t contact_ticks_ = 0;
  std::int64_t ticks_ = 0;
};

/// The same body, forces and route stepped by Bullet's btDiscreteDynamicsWorld in the same box
/// field (all boxes static rigid bodies). `static_aabbs_fixed`: setForceUpdateAllAabbs(false)
/// (Bullet's own setting that stops it recomputing every static AABB each step); false = Bullet's
/// defaults.
class BulletTickScenario {
 public:
  BulletTickScenario(int box_count, double extent_m, std::uint64_t seed, bool static_aabbs_fixed);
  ~BulletTickScenario();
  void Tick();

 private:
  struct State;
  std::unique_ptr<State> s_;
};

/// Runs the physics benchmarks on the calling thread (wall-clock, this machine) and returns:
///   empty_ticks_per_s, empty_ns_per_tick           our tick, one quad, ground plane only
///   boxes10k_ticks_per_s, boxes10k_ns_per_tick     our tick among `boxes` static boxes
///   boxes10k_contact_tick_fraction                 fraction of those ticks with a contact
///   bullet_boxes10k_ticks_per_s                    btDiscreteDynamicsWorld, Bullet's defaults
///   bullet_tuned_boxes10k_ticks_per_s              btDiscreteDynamicsWorld, static AABB updates
///   off speedup_vs_bullet, speedup_vs_bullet_tuned     ratios of ticks per second (ours /
///   Bullet's) collision_world_build_s                        time to build our collision world of
///   the field
nlohmann::json RunPhysicsBench(const PhysicsBenchOptions& options = {});

}  // namespace airis::tools
