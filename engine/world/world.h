#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/clock.h"
#include "engine/core/worker_pool.h"
#include "engine/environment/environment.h"
#include "engine/physics/body_contact_solver.h"
#include "engine/physics/body_neighbour_list.h"
#include "engine/physics/collision_world.h"
#include "engine/physics/contact_solver.h"
#include "engine/physics/rigid_body_integrator.h"
#include "engine/physics/sleep_config.h"
#include "engine/scene/static_scene.h"
#include "engine/world/ray_caster.h"
#include "engine/world/sensor.h"
#include "engine/world/vehicle.h"

namespace airis::engine {

/// A vehicle touching a static object, or another vehicle, that it was not touching the tick
/// before. When two vehicles meet, each of them gets an event naming the other.
struct CollisionEvent {
  TimeNs time_ns = 0;       ///< end of the tick in which the contact began
  std::size_t vehicle = 0;  ///< index in the world
  std::string vehicle_name;
  std::string object_name;           ///< the static object's name, or the other vehicle's
  std::uint8_t class_id = kNoClass;  ///< the object's semantic label (kNoClass for a vehicle)
  std::uint32_t instance_id = kNoInstance;  ///< the object's (kNoInstance for a vehicle)
  /// Index in the world of the other vehicle for a vehicle-vehicle contact; -1 for a static object.
  int other_vehicle = -1;
  Vec3 point_W = Vec3::Zero();    ///< contact point on the object (or other vehicle), world NED (m)
  Vec3 normal_W = Vec3::UnitZ();  ///< unit, from the object (or other vehicle) toward the vehicle
  double impulse_Ns = 0.0;        ///< magnitude of the contact impulse applied in that tick
};

/// Physics settings of a world (a scene's `physics:` block).
struct PhysicsConfig {
  double rate_hz = 1000.0;      ///< ticks per simulated second, 100 to 10000, whole ns per tick
  int contact_iterations = 12;  ///< sequential-impulse sweeps per tick
  double penetration_slop_m = 1e-4;  ///< penetration left uncorrected (stable resting contact)
  /// A step that moves a body farther than this fraction of its smallest half-extent is swept first
  /// (continuous collision: nothing tunnels through thin walls).
  double sweep_fraction = 0.5;
  double max_speed_m_s = 10000.0;  ///< a body faster than this stops the run (diverged)
  SleepConfig sleep;               ///< bodies at rest on a static surface sleep

  template <class V>
  void Visit(V& v) {
    v.Field("rate_hz", rate_hz,
            "physics ticks per simulated second (100 to 10000); sensors may not sample faster");
    v.Field("contact_iterations", contact_iterations, "contact solver iterations per tick");
    v.Field("penetration_slop_m", penetration_slop_m, "penetration left uncorrected (m)");
    v.Field("sweep_fraction", sweep_fraction,
            "sweep a step longer than this fraction of the body's smallest half-extent");
    v.Field("max_speed_m_s", max_speed_m_s, "speed above which the run stops as diverged (m/s)");
    v.Field("sleep", sleep,
            "bodies at rest on a static surface stop being simulated (docs/physics.md)");
  }
  /// Throws InvalidField naming the field (`sleep.delay_s` for a nested one).
  void Validate() const;
};

/// Everything that exists in a run: the static scene (and its collision world), the environment,
/// the vehicles with their sensors, and an optional ray caster. The World moves bodies
/// (StepPhysics); the Simulation owns the clock and the tick order.
class World {
 public:
  /// Builds the collision world from `scene`. Throws InvalidField on a bad config or scene indices.
  World(std::shared_ptr<const StaticScene> scene, Environment environment,
        const PhysicsConfig& physics = {});
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Adds a vehicle; returns its index. Throws InvalidField("vehicles") when the name is taken.
  std::size_t AddVehicle(std::unique_ptr<Vehicle> vehicle);
  /// Mounts `sensor` on vehicle `vehicle`. Throws InvalidField("sensors") on a duplicate sensor
  /// name.
  Sensor& AddSensor(std::size_t vehicle, std::unique_ptr<Sensor> sensor);
  /// Same, by vehicle name; throws InvalidField("vehicle") on an unknown name (closest name
  /// suggested).
  Sensor& AddSensor(std::string_view vehicle_name, std::unique_ptr<Sensor> sensor);
  /// Lowers (or keeps) vehicle `i` along world z onto the first surface below it, level as it is,
  /// and counts that surface as already touched (resting there is no collision). False when no
  /// surface lies within `search_m` below it, or it starts overlapping one.
  bool RestOnSurfaceBelow(std::size_t i, double search_m = 1000.0);
  /// What vehicle `i` overlaps where it stands: a static object or another vehicle that its body
  /// box penetrates deeper than `tolerance_m`. Surfaces it rests on (RestOnSurfaceBelow) do not
  /// count. Used to refuse starts that would collide at the first tick.
  struct Overlap {
    std::string name;      ///< the object's or the other vehicle's
    bool vehicle = false;  ///< true: another vehicle
    double depth_m = 0.0;
  };
  std::optional<Overlap> FindOverlap(std::size_t i, double tolerance_m);
  /// Index of the vehicle named `name`, or -1.
  int FindVehicle(std::string_view name) const;

  std::size_t vehicle_count() const { return slots_.size(); }
  Vehicle& vehicle(std::size_t i) { return *slots_[i].vehicle; }
  const Vehicle& vehicle(std::size_t i) const { return *slots_[i].vehicle; }
  /// Writes T_WB (body FRD -> world NED) of every vehicle, in vehicle order, into `T_WB` (resized).
  void CalcVehiclePoses(std::vector<Eigen::Isometry3d>& T_WB) const;
  /// Holds vehicle `i` kinematically where its state puts it (true) or simulates it again (false).
  /// A held vehicle is not moved, pushed or collided by StepPhysics; its velocities are zeroed and
  /// its accelerations read as at rest (gravity only). For placing cameras at chosen poses (mission
  /// step random_poses). Either way it is awake.
  void SetHeld(std::size_t i, bool held);
  bool held(std::size_t i) const { return slots_[i].held; }
  /// Whether vehicle `i` sleeps (PhysicsConfig::sleep: at rest on a static surface, not simulated
  /// until something wakes it).
  bool asleep(std::size_t i) const { return slots_[i].asleep; }
  /// Wakes vehicle `i` (if asleep): it is simulated from the next step on, and must rest for the
  /// whole sleep delay again before it sleeps. Changing its state from outside wakes it as well.
  void WakeUp(std::size_t i);
  /// Air density (kg/m^3) and gravity (m/s^2) at vehicle `i`'s current position, from the same
  /// cached local model the physics step uses (no atmosphere evaluation unless the vehicle has not
  /// been stepped yet).
  void CalcLocalConditions(std::size_t i, double* air_density_kg_m3, double* gravity_m_s2) const;
  /// A number that changes (grows) whenever vehicle `i`'s state or accelerations may have changed
  /// since the previous step: every step of a vehicle that is awake or held, a wake-up. It stays
  /// the same while the vehicle sleeps undisturbed (SensorContext::motion_serial). Never 0.
  std::uint64_t motion_serial(std::size_t i) const { return slots_[i].motion_serial; }
  /// Accelerations of vehicle `i` over the last step (contacts included).
  const RigidBodyAccelerations& accelerations(std::size_t i) const {
    return slots_[i].accelerations;
  }
  /// Contacts of vehicle `i` with the static scene found in the last step (after the sweep, before
  /// their resolution); while it sleeps, those it fell asleep on.
  std::span<const Contact> contacts(std::size_t i) const { return slots_[i].contacts; }
  /// Vehicle-vehicle contacts found in the last step, before their resolution: `a` and `b` are
  /// vehicle indices (a < b), the normal points from b toward a.
  std::span<const BodyContact> vehicle_contacts() const { return vehicle_contacts_; }
  std::span<const std::unique_ptr<Sensor>> sensors(std::size_t i) const {
    return slots_[i].sensors;
  }
  /// The sensors of vehicle `i` that produce rows, not images (Sensor::image() is null), in the
  /// order they were mounted: what the Simulation samples on its threads.
  std::span<Sensor* const> row_sensors(std::size_t i) const { return slots_[i].row_sensors; }
  /// Whether vehicle `i` carries an image sensor (a camera).
  bool has_image_sensors(std::size_t i) const { return slots_[i].has_image_sensors; }
  /// Sensors on all vehicles together.
  std::size_t sensor_count() const { return sensor_count_; }
  /// Number of sensors that produce images (cameras), over all vehicles.
  std::size_t image_sensor_count() const { return image_sensor_count_; }

  /// Sets the ray caster for rangefinders and lidar (built by whoever builds the world, which may
  /// share it between the worlds of one scene; may be null).
  void set_ray_caster(std::shared_ptr<const RayCaster> caster) { ray_caster_ = std::move(caster); }
  const RayCaster* ray_caster() const { return ray_caster_.get(); }

  /// Calls `listener` for every collision event (on the thread that calls StepPhysics, during it,
  /// in vehicle order whatever the number of threads).
  void AddCollisionListener(std::function<void(const CollisionEvent&)> listener) {
    collision_listeners_.push_back(std::move(listener));
  }

  /// Moves every vehicle over one step [now_ns, now_ns + dt]: actuators -> integrator -> swept and
  /// discrete collision detection -> contact response, each vehicle against the static scene (on
  /// `pool`'s threads when given: each vehicle is independent here); then, with several vehicles,
  /// contacts between vehicles (a broadphase over the vehicles' swept bounds finds the pairs; swept
  /// when they close fast) resolved together with those vehicles' static contacts, on the calling
  /// thread in the order of the vehicle indices. Results do not depend on the pool. A sleeping
  /// vehicle only advances its actuators (PhysicsConfig::sleep). Throws SimulationError naming the
  /// vehicle, the time and the cause when a state becomes non-finite or absurd, or a body leaves
  /// the atmosphere model's range (with several failing, the one of least index).
  void StepPhysics(TimeNs now_ns, double dt_s, WorkerPool* pool = nullptr);

  const StaticScene& scene() const { return *scene_; }
  Environment& environment() { return environment_; }
  const Environment& environment() const { return environment_; }
  CollisionWorld& collision_world() { return collision_; }
  const PhysicsConfig& physics_config() const { return physics_; }

 private:
  // Air density and gravity about a reference altitude, as value and slope (first-order Taylor
  // model), refreshed when the body moves more than kEnvironmentRefresh_m from it. Both vary on
  // kilometre scales: the model is good to ~1e-8 relative and spares the atmosphere model on most
  // ticks.
  struct LocalEnvironment {
    double altitude_m = std::numeric_limits<double>::quiet_NaN();
    double density_kg_m3 = 0.0, density_slope_kg_m4 = 0.0;  // per metre of altitude
    double gravity_m_s2 = 0.0, gravity_slope_1_s2 = 0.0;    // per metre of altitude
  };
  struct Slot {
    std::unique_ptr<Vehicle> vehicle;
    bool held = false;                // SetHeld: kinematic, skipped by StepPhysics
    std::uint64_t motion_serial = 1;  // see motion_serial()
    LocalEnvironment local;
    int body = -1;  // handle in collision_
    std::vector<std::unique_ptr<Sensor>> sensors;
    std::vector<Sensor*> row_sensors;  // those of sensors that make no images
    bool has_image_sensors = false;
    RigidBodyAccelerations accelerations;
    std::vector<Contact> contacts;
    std::vector<std::uint32_t> touching;       // colliders in contact in the last tick
    std::vector<std::uint32_t> touching_next;  // scratch
    ContactSolver solver;                      // its own: vehicles step in parallel
    std::vector<CollisionEvent> events;        // of this step, for the listeners
    Vec3 p_start_W = Vec3::Zero();  // position at the start of the tick (several vehicles)
    // Sleeping (PhysicsConfig::sleep): ticks at rest in a row, and the state it fell asleep in.
    int rest_ticks = 0;
    bool asleep = false;
    RigidBodyState rest_state;
    // Asleep, from its first tick asleep on: the actuators' wrench and the forcing there (the
    // body's air and gravity do not change while it keeps its place), and the wind speed squared
    // below which the wind cannot wake it (CalcQuietWind2).
    bool has_rest_wrench = false;
    Wrench rest_wrench;
    StepForcing rest_forcing;
    double quiet_wind2_m2_s2 = 0.0;
  };
  // The vehicle-vehicle contacts of one pair of vehicles in vehicle_contacts_.
  struct VehiclePair {
    std::size_t a, b;          // vehicle indices, a < b
    std::size_t first, count;  // range in vehicle_contacts_
  };
  // Steps one vehicle, unless it is held or surely stays asleep (StaysAsleep: then it returns
  // false and nothing of the vehicle changed).
  bool StepSlot(Slot& slot, std::size_t index, TimeNs now_ns, double dt_s);
  void StepVehicle(Slot& slot, std::size_t index, TimeNs now_ns, double dt_s);
  void SetSleepDelay(double dt_s);
  void ReportEvents();  // the vehicles' new static contacts, to the listeners
  // Whether the forces on the body other than gravity and contacts (the actuator wrench, the
  // wind's drag at rest) are within the sleep bound.
  bool IsQuiet(const Slot& slot, const Wrench& wrench, const StepForcing& forcing) const;
  // Counts a tick at rest (or resets the count) and puts the body to sleep after the delay.
  void CountRest(Slot& slot, const Wrench& wrench, const StepForcing& forcing);
  // Whether the state of a sleeping body is the one it fell asleep in, to the bit (a sleeping
  // body's state is never changed by the physics: anything else changed it from outside).
  bool IsRestState(const Slot& slot) const;
  // Whether a sleeping body surely stays asleep this tick without its actuators being advanced:
  // its state is its rest state, its actuators have settled (so they would give rest_wrench
  // again), and the wind cannot lift it (quiet_wind2_m2_s2, else IsQuiet with the wind of now).
  bool StaysAsleep(const Slot& slot) const;
  // The largest wind speed squared (m^2/s^2) whose drag on the body at rest, with `wrench`, surely
  // keeps it within the sleep bound; negative when the wrench alone may not.
  double CalcQuietWind2(const Slot& slot, const Wrench& wrench, const StepForcing& forcing) const;
  void Wake(Slot& slot) const;
  void RefreshLocalEnvironment(Slot& slot, TimeNs now_ns, const Vec3& p_W) const;
  [[noreturn]] void Fail(const Slot& slot, TimeNs now_ns, const std::string& cause) const;
  void ReportNewContacts(Slot& slot, std::size_t index, TimeNs end_ns,
                         const ContactResolution& resolution);
  // Finds the contacts between vehicles i < j (sweeping when they close fast) into
  // vehicle_contacts_; returns their number.
  std::size_t FindVehiclePairContacts(std::size_t i, std::size_t j);
  // The box vehicle `slot` swept over this tick (its start and end), grown by its bounding radius.
  static BodyBounds CalcSweptBounds(const Slot& slot);
  void ResolveVehicleContacts(TimeNs now_ns, double dt_s);
  void ReportNewVehicleContacts(TimeNs end_ns);

  std::shared_ptr<const StaticScene> scene_;
  Environment environment_;
  PhysicsConfig physics_;
  CollisionWorld collision_;
  BodyContactSolver body_solver_;
  int sleep_delay_ticks_ = 0;  // sleep.delay_s in ticks of sleep_dt_s_
  double sleep_dt_s_ = 0.0;
  std::vector<Slot> slots_;
  std::size_t sensor_count_ = 0;
  std::size_t image_sensor_count_ = 0;
  std::shared_ptr<const RayCaster> ray_caster_;  // worlds built from one scene share it
  std::vector<std::function<void(const CollisionEvent&)>> collision_listeners_;
  // Vehicle-vehicle contact state (used only with several vehicles).
  BodyNeighbourList neighbours_;          // the broadphase between vehicles, kept from tick to tick
  std::vector<BodyBounds> swept_bounds_;  // per vehicle, over this tick (CalcSweptBounds)
  // Set this tick by a vehicle whose new box the neighbour list does not hold (Holds).
  std::atomic<bool> bounds_escaped_{false};
  std::vector<BodyPair> near_pairs_;  // the broadphase's pairs
  std::vector<BodyContact> vehicle_contacts_;
  std::vector<VehiclePair> pairs_;                                   // touching pairs of this tick
  std::vector<std::pair<std::size_t, std::size_t>> touching_pairs_;  // of the last tick
  std::vector<std::pair<std::size_t, std::size_t>> touching_pairs_next_;
  std::vector<Contact> pair_scratch_;
  std::vector<BodyContact> solve_contacts_;
  std::vector<ContactBody> solve_bodies_;
  std::vector<std::size_t> solve_vehicles_;    // vehicle index of each of solve_bodies_
  std::vector<int> solve_index_;               // per vehicle: index in solve_bodies_, or -1
  std::vector<Vec3> v_before_W_, w_before_B_;  // per solve body
};

}  // namespace airis::engine
