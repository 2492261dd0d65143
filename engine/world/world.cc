#include "engine/world/world.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "engine/core/config.h"
#include "engine/core/error.h"
#include "engine/physics/drag.h"
#include "engine/physics/rigid_body_integrator.h"
#include "engine/world/simulation.h"

namespace airis::engine {
namespace {

ContactSolverConfig SolverConfig(const PhysicsConfig& physics) {
  physics.Validate();
  ContactSolverConfig c;
  c.iterations = physics.contact_iterations;
  c.penetration_slop_m = physics.penetration_slop_m;
  return c;
}

// The local environment model is refreshed when the body is this far from its reference altitude
// (m), and its slopes are finite differences over the same height: with density scale heights of ~8
// km and gravity's of ~3000 km, the curvature left out is below 1e-8 relative.
constexpr double kEnvironmentRefresh_m = 1.0;

}  // namespace

void PhysicsConfig::Validate() const {
  SimulationConfig{rate_hz}.Validate();
  RequireInRange("contact_iterations", contact_iterations, 1, 1000);
  RequireNonNegative("penetration_slop_m", penetration_slop_m);
  RequirePositive("sweep_fraction", sweep_fraction);
  RequirePositive("max_speed_m_s", max_speed_m_s);
  ValidateNested(sleep, "sleep");
}

World::World(std::shared_ptr<const StaticScene> scene, Environment environment,
             const PhysicsConfig& physics)
    : scene_(std::move(scene)),
      environment_(std::move(environment)),
      physics_(physics),
      collision_(*scene_),
      body_solver_(SolverConfig(physics)) {}

World::~World() = default;

std::size_t World::AddVehicle(std::unique_ptr<Vehicle> vehicle) {
  AIRIS_DEMAND(vehicle != nullptr);
  Require(FindVehicle(vehicle->name()) < 0, "vehicles",
          "duplicate vehicle name '" + vehicle->name() + "'");
  Slot slot;
  slot.body = collision_.AddBody(vehicle->body().config().box_size_m);
  slot.solver = ContactSolver(SolverConfig(physics_));
  slot.vehicle = std::move(vehicle);
  slot.contacts.reserve(16);
  slot.touching.reserve(8);
  slot.touching_next.reserve(8);
  slots_.push_back(std::move(slot));
  return slots_.size() - 1;
}

bool World::RestOnSurfaceBelow(std::size_t i, double search_m) {
  AIRIS_DEMAND(i < slots_.size() && search_m > 0.0);
  Slot& slot = slots_[i];
  RigidBodyState& state = slot.vehicle->state();
  collision_.FindContacts(slot.body, state.p_W, state.q_WB, 0.0, slot.contacts);
  if (!slot.contacts.empty()) return false;  // overlapping something where it stands
  Contact hit;
  const Vec3 from = state.p_W;
  const Vec3 to = from + Vec3(0.0, 0.0, search_m);
  const double fraction = collision_.Sweep(slot.body, state.q_WB, from, to, &hit);
  if (fraction >= 1.0) return false;
  // On the surface, within the solver's slop, so that the contact persists from the first tick.
  state.p_W = from + fraction * (to - from) + Vec3(0.0, 0.0, 0.5 * physics_.penetration_slop_m);
  collision_.FindContacts(slot.body, state.p_W, state.q_WB, 0.0, slot.contacts);
  slot.touching.clear();
  for (const Contact& c : slot.contacts) {
    if (std::find(slot.touching.begin(), slot.touching.end(), c.collider) == slot.touching.end())
      slot.touching.push_back(c.collider);
  }
  slot.contacts.clear();
  return !slot.touching.empty();
}

std::optional<World::Overlap> World::FindOverlap(std::size_t i, double tolerance_m) {
  AIRIS_DEMAND(i < slots_.size());
  Slot& slot = slots_[i];
  const RigidBodyState& state = slot.vehicle->state();
  std::vector<Contact> contacts;
  collision_.FindContacts(slot.body, state.p_W, state.q_WB, 0.0, contacts);
  std::optional<Overlap> deepest;
  for (const Contact& c : contacts) {
    const bool rests_on =
        std::find(slot.touching.begin(), slot.touching.end(), c.collider) != slot.touching.end();
    if (rests_on || c.depth_m <= tolerance_m) continue;
    if (!deepest || c.depth_m > deepest->depth_m) {
      deepest = Overlap{scene_->objects[collision_.colliders()[c.collider].object_index].name,
                        false, c.depth_m};
    }
  }
  for (std::size_t j = 0; j < slots_.size(); ++j) {
    if (j == i) continue;
    const Slot& other = slots_[j];
    const RigidBodyState& o = other.vehicle->state();
    const double reach_m =
        slot.vehicle->body().bounding_radius_m() + other.vehicle->body().bounding_radius_m();
    if ((state.p_W - o.p_W).squaredNorm() > reach_m * reach_m) continue;
    contacts.clear();
    collision_.FindBodyContacts(slot.body, state.p_W, state.q_WB, other.body, o.p_W, o.q_WB,
                                contacts);
    for (const Contact& c : contacts) {
      if (c.depth_m <= tolerance_m) continue;
      if (!deepest || c.depth_m > deepest->depth_m) {
        deepest = Overlap{other.vehicle->name(), true, c.depth_m};
      }
    }
  }
  return deepest;
}

Sensor& World::AddSensor(std::size_t vehicle, std::unique_ptr<Sensor> sensor) {
  AIRIS_DEMAND(vehicle < slots_.size() && sensor != nullptr);
  auto& sensors = slots_[vehicle].sensors;
  for (const auto& s : sensors) {
    Require(s->name() != sensor->name(), "sensors",
            "duplicate sensor name '" + sensor->name() + "' on vehicle '" +
                slots_[vehicle].vehicle->name() + "'");
  }
  if (sensor->image() == nullptr) {
    slots_[vehicle].row_sensors.push_back(sensor.get());
  } else {
    slots_[vehicle].has_image_sensors = true;
    ++image_sensor_count_;
  }
  sensors.push_back(std::move(sensor));
  ++sensor_count_;
  return *sensors.back();
}

Sensor& World::AddSensor(std::string_view vehicle_name, std::unique_ptr<Sensor> sensor) {
  const int index = FindVehicle(vehicle_name);
  if (index < 0) {
    std::vector<std::string> names;
    for (const auto& s : slots_) names.push_back(s.vehicle->name());
    std::string problem = "unknown vehicle '" + std::string(vehicle_name) + "'";
    if (const auto guess = ClosestMatch(vehicle_name, names)) {
      problem += " (did you mean '" + *guess + "'?)";
    }
    throw InvalidField("vehicle", problem);
  }
  return AddSensor(static_cast<std::size_t>(index), std::move(sensor));
}

int World::FindVehicle(std::string_view name) const {
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    if (slots_[i].vehicle->name() == name) return static_cast<int>(i);
  }
  return -1;
}

void World::StepPhysics(TimeNs now_ns, double dt_s, WorkerPool* pool) {
  if (dt_s != sleep_dt_s_) SetSleepDelay(dt_s);
  if (slots_.size() == 1) {
    StepSlot(slots_[0], 0, now_ns, dt_s);
  } else {
    // A vehicle added since the last tick has no bounds yet: all are worked out this tick.
    const bool added = swept_bounds_.size() != slots_.size();
    swept_bounds_.resize(slots_.size());
    bounds_escaped_.store(false, std::memory_order_relaxed);
    ParallelFor(pool, slots_.size(), [&](std::size_t i) {
      Slot& slot = slots_[i];
      slot.p_start_W = slot.vehicle->state().p_W;
      // Here, on the thread that stepped the vehicle, not in the serial pass after: there each
      // vehicle would be read from the other core's cache. A vehicle that stays asleep keeps
      // its bounds (its state, so its start and end, are those of the last tick), which the
      // neighbour list held at the last tick.
      if (StepSlot(slot, i, now_ns, dt_s) || added) {
        swept_bounds_[i] = CalcSweptBounds(slot);
        if (!neighbours_.Holds(i, swept_bounds_[i])) {
          bounds_escaped_.store(true, std::memory_order_relaxed);
        }
      }
    });
  }
  if (!collision_listeners_.empty()) ReportEvents();
  if (slots_.size() > 1) ResolveVehicleContacts(now_ns, dt_s);
}

void World::SetSleepDelay(double dt_s) {
  sleep_dt_s_ = dt_s;
  // Whole ticks covering the delay (a delay of 0.5 s at 1 ms is 500, not 501 by rounding).
  sleep_delay_ticks_ =
      std::max(1, static_cast<int>(std::ceil(physics_.sleep.delay_s / dt_s - 1e-9)));
}

void World::ReportEvents() {
  // The listeners hear of the new static contacts on this thread, in vehicle order.
  bool heard = false;
  for (Slot& slot : slots_) {
    for (const CollisionEvent& event : slot.events) {
      for (const auto& listener : collision_listeners_) listener(event);
      heard = true;
    }
    slot.events.clear();
  }
  if (!heard) return;
  // A listener may have moved a sleeping vehicle (a reset from a callback): it wakes now, so that
  // its sensors sample this tick where it is, not the rest they keep while it sleeps.
  for (Slot& slot : slots_) {
    if (slot.asleep && !IsRestState(slot)) Wake(slot);
  }
}

void World::CalcLocalConditions(std::size_t i, double* air_density_kg_m3,
                                double* gravity_m_s2) const {
  const Slot& slot = slots_[i];
  const Vec3& p_W = slot.vehicle->state().p_W;
  const LocalEnvironment& local = slot.local;
  const double dh = environment_.AltitudeOf(p_W) - local.altitude_m;
  if (!(std::abs(dh) <= kEnvironmentRefresh_m)) {  // not stepped yet (NaN), or moved by hand
    *air_density_kg_m3 = environment_.CalcAir(p_W).density_kg_m3;
    *gravity_m_s2 = environment_.CalcGravity_m_s2(p_W);
    return;
  }
  *air_density_kg_m3 = local.density_kg_m3 + local.density_slope_kg_m4 * dh;
  *gravity_m_s2 = local.gravity_m_s2 + local.gravity_slope_1_s2 * dh;
}

void World::CalcVehiclePoses(std::vector<Eigen::Isometry3d>& T_WB) const {
  T_WB.resize(slots_.size());
  for (std::size_t i = 0; i < slots_.size(); ++i) T_WB[i] = slots_[i].vehicle->state().CalcPose();
}

void World::SetHeld(std::size_t i, bool held) {
  Slot& slot = slots_[i];
  slot.held = held;
  Wake(slot);
  if (!held) return;
  RigidBodyState& s = slot.vehicle->state();
  s.v_W.setZero();
  s.w_B.setZero();
  slot.accelerations.a_W.setZero();
  slot.accelerations.alpha_B.setZero();
  slot.accelerations.gravity_W = Vec3(0.0, 0.0, environment_.CalcGravity_m_s2(s.p_W));
  slot.contacts.clear();
}

void World::WakeUp(std::size_t i) { Wake(slots_[i]); }

void World::Wake(Slot& slot) const {
  ++slot.motion_serial;
  slot.asleep = false;
  slot.rest_ticks = 0;
  slot.has_rest_wrench = false;
}

void World::Fail(const Slot& slot, TimeNs now_ns, const std::string& cause) const {
  const RigidBodyState& s = slot.vehicle->state();
  std::ostringstream out;
  out.precision(9);
  out << "vehicle '" << slot.vehicle->name() << "' at t = " << ToSeconds(now_ns) << " s: " << cause
      << " (p_W = [" << s.p_W.transpose() << "] m, v_W = [" << s.v_W.transpose() << "] m/s, w_B = ["
      << s.w_B.transpose() << "] rad/s)";
  throw SimulationError(out.str());
}

bool World::StepSlot(Slot& slot, std::size_t index, TimeNs now_ns, double dt_s) {
  if (slot.asleep && StaysAsleep(slot)) return false;
  // A held vehicle's state may be set by hand between steps; any other may move now.
  ++slot.motion_serial;
  if (!slot.held) StepVehicle(slot, index, now_ns, dt_s);
  return true;
}

void World::StepVehicle(Slot& slot, std::size_t index, TimeNs now_ns, double dt_s) {
  Vehicle& vehicle = *slot.vehicle;
  const RigidBodyModel& body = vehicle.body();
  RigidBodyState& state = vehicle.state();
  const Vec3 p0 = state.p_W;
  const Vec3 v0 = state.v_W;
  const Vec3 w0 = state.w_B;

  // Environment at the start of the step (held over it; gravity is linearised in altitude within
  // it).
  const double altitude_m = environment_.AltitudeOf(p0);
  LocalEnvironment& local = slot.local;
  if (!(std::abs(altitude_m - local.altitude_m) <= kEnvironmentRefresh_m)) {
    RefreshLocalEnvironment(slot, now_ns, p0);
  }
  const double dh = altitude_m - local.altitude_m;
  StepForcing forcing;
  forcing.air_density_kg_m3 = local.density_kg_m3 + local.density_slope_kg_m4 * dh;
  forcing.gravity_m_s2 = local.gravity_m_s2 + local.gravity_slope_1_s2 * dh;
  forcing.gravity_gradient_1_s2 = -local.gravity_slope_1_s2;  // z_W points down: d/dz = -d/dh
  forcing.wind_W = environment_.wind().CalcVelocity_W(p0);

  const Wrench wrench =
      vehicle.UpdateActuators(ActuatorContext{now_ns, dt_s, forcing.air_density_kg_m3, &state});
  if (!std::isfinite(wrench.force_B.sum() + wrench.torque_B.sum())) {
    Fail(slot, now_ns, "actuator wrench is not finite");
  }
  forcing.force_B = wrench.force_B;
  forcing.torque_B = wrench.torque_B;
  if (slot.asleep) [[unlikely]] {
    // Asleep it stays where it fell asleep, unless the forces on it grew or its state was changed
    // from outside. What it rests with is kept for the ticks to come (StaysAsleep).
    if (IsRestState(slot) && IsQuiet(slot, wrench, forcing)) {
      slot.rest_wrench = wrench;
      slot.rest_forcing = forcing;
      slot.quiet_wind2_m2_s2 = CalcQuietWind2(slot, wrench, forcing);
      slot.has_rest_wrench = true;
      return;
    }
    Wake(slot);
  }

  StepRigidBody(body, forcing, dt_s, state, slot.accelerations);
  if (!IsFinite(state)) Fail(slot, now_ns, "state became non-finite in the integrator");
  if (state.v_W.squaredNorm() > physics_.max_speed_m_s * physics_.max_speed_m_s) {
    Fail(slot, now_ns, "speed above max_speed_m_s = " + FormatNumber(physics_.max_speed_m_s));
  }

  // Continuous collision: a long step is swept first and stopped where it meets a surface.
  const Vec3 motion = state.p_W - p0;
  Contact swept_hit;
  bool swept = false;
  const double sweep_beyond_m = physics_.sweep_fraction * body.min_half_extent_m();
  if (motion.squaredNorm() > sweep_beyond_m * sweep_beyond_m) {
    const double fraction = collision_.Sweep(slot.body, state.q_WB, p0, state.p_W, &swept_hit);
    if (fraction < 1.0) {
      state.p_W = p0 + fraction * motion;
      swept = true;
    }
  }

  collision_.FindContacts(slot.body, state.p_W, state.q_WB, 0.0, slot.contacts);
  if (swept) slot.contacts.push_back(swept_hit);
  if (slot.contacts.empty()) {
    slot.rest_ticks = 0;
    if (!slot.touching.empty()) slot.touching.clear();
    return;
  }
  const ContactResolution resolution = slot.solver.Resolve(
      body, slot.contacts, collision_.colliders(), forcing.gravity_m_s2, dt_s, state);
  // Contact impulses are part of the step's acceleration (an accelerometer feels the landing).
  slot.accelerations.a_W = (state.v_W - v0) / dt_s;
  slot.accelerations.alpha_B = (state.w_B - w0) / dt_s;
  ReportNewContacts(slot, index, now_ns + SecondsToNs(dt_s), resolution);
  if (physics_.sleep.enabled) CountRest(slot, wrench, forcing);
}

bool World::IsRestState(const Slot& slot) const {
  // Bitwise (memcmp of each vector): stricter than == only for -0.0 against 0.0, which counts as a
  // change and wakes the body; a sleeping body's state is finite.
  const RigidBodyState& state = slot.vehicle->state();
  const RigidBodyState& rest = slot.rest_state;
  return std::memcmp(state.p_W.data(), rest.p_W.data(), sizeof(Vec3)) == 0 &&
         std::memcmp(state.v_W.data(), rest.v_W.data(), sizeof(Vec3)) == 0 &&
         std::memcmp(state.w_B.data(), rest.w_B.data(), sizeof(Vec3)) == 0 &&
         std::memcmp(state.q_WB.coeffs().data(), rest.q_WB.coeffs().data(), 4 * sizeof(double)) ==
             0;
}

bool World::StaysAsleep(const Slot& slot) const {
  if (!slot.has_rest_wrench || !slot.vehicle->AreActuatorsSettled() || !IsRestState(slot)) {
    return false;
  }
  const Vec3 wind_W = environment_.wind().CalcVelocity_W(slot.vehicle->state().p_W);
  if (wind_W.squaredNorm() <= slot.quiet_wind2_m2_s2) return true;
  StepForcing forcing = slot.rest_forcing;
  forcing.wind_W = wind_W;
  return IsQuiet(slot, slot.rest_wrench, forcing);
}

double World::CalcQuietWind2(const Slot& slot, const Wrench& wrench,
                             const StepForcing& forcing) const {
  // IsQuiet's force is F + D with D_i = rho k_i a_i |a_i| for the air a relative to the body at
  // rest (the wind in body axes), so |D| <= rho max(k) |a|^2 = rho max(k) |wind|^2: a wind with
  // |F| + rho max(k) |wind|^2 within the bound is quiet. A thousandth is kept for rounding.
  const RigidBodyModel& body = slot.vehicle->body();
  const double limit_N = physics_.sleep.force_fraction * body.mass_kg() * forcing.gravity_m_s2;
  const double limit_Nm = limit_N * body.bounding_radius_m();
  const double force_N = wrench.force_B.norm();
  if (wrench.torque_B.squaredNorm() > limit_Nm * limit_Nm || !(force_N < limit_N)) return -1.0;
  const double drag_per_speed2 =
      forcing.air_density_kg_m3 * body.linear_drag_factor_m2().maxCoeff();
  if (!(drag_per_speed2 > 0.0)) return std::numeric_limits<double>::infinity();
  return 0.999 * (limit_N - force_N) / drag_per_speed2;
}

bool World::IsQuiet(const Slot& slot, const Wrench& wrench, const StepForcing& forcing) const {
  const RigidBodyModel& body = slot.vehicle->body();
  const Vec3 air_B = slot.vehicle->state().q_WB.conjugate() * forcing.wind_W;
  const Vec3 force_B =
      wrench.force_B + CalcLinearDrag_B(body, forcing.air_density_kg_m3, Vec3(-air_B));
  const double limit_N = physics_.sleep.force_fraction * body.mass_kg() * forcing.gravity_m_s2;
  const double limit_Nm = limit_N * body.bounding_radius_m();
  return force_B.squaredNorm() <= limit_N * limit_N &&
         wrench.torque_B.squaredNorm() <= limit_Nm * limit_Nm;
}

void World::CountRest(Slot& slot, const Wrench& wrench, const StepForcing& forcing) {
  RigidBodyState& state = slot.vehicle->state();
  const SleepConfig& sleep = physics_.sleep;
  const bool at_rest =
      state.v_W.squaredNorm() < sleep.linear_speed_m_s * sleep.linear_speed_m_s &&
      state.w_B.squaredNorm() < sleep.angular_speed_rad_s * sleep.angular_speed_rad_s &&
      IsQuiet(slot, wrench, forcing);
  if (!at_rest) {
    slot.rest_ticks = 0;
    return;
  }
  if (++slot.rest_ticks < sleep_delay_ticks_) return;
  // Asleep: still, and its sensors read it at rest (gravity only), until something wakes it.
  slot.asleep = true;
  state.v_W.setZero();
  state.w_B.setZero();
  slot.accelerations.a_W.setZero();
  slot.accelerations.alpha_B.setZero();
  slot.rest_state = state;
}

void World::RefreshLocalEnvironment(Slot& slot, TimeNs now_ns, const Vec3& p_W) const {
  LocalEnvironment& local = slot.local;
  const Vec3 above_W = p_W - Vec3(0.0, 0.0, kEnvironmentRefresh_m);
  try {
    local.density_kg_m3 = environment_.CalcAir(p_W).density_kg_m3;
    local.density_slope_kg_m4 =
        (environment_.CalcAir(above_W).density_kg_m3 - local.density_kg_m3) / kEnvironmentRefresh_m;
  } catch (const std::out_of_range& e) {
    Fail(slot, now_ns, std::string("outside the atmosphere model: ") + e.what());
  }
  local.gravity_m_s2 = environment_.CalcGravity_m_s2(p_W);
  local.gravity_slope_1_s2 =
      (environment_.CalcGravity_m_s2(above_W) - local.gravity_m_s2) / kEnvironmentRefresh_m;
  local.altitude_m = environment_.AltitudeOf(p_W);
}

void World::ReportNewContacts(Slot& slot, std::size_t index, TimeNs end_ns,
                              const ContactResolution& resolution) {
  slot.touching_next.clear();
  for (const Contact& c : slot.contacts) {
    if (std::find(slot.touching_next.begin(), slot.touching_next.end(), c.collider) ==
        slot.touching_next.end()) {
      slot.touching_next.push_back(c.collider);
    }
  }
  if (!collision_listeners_.empty()) {
    for (std::uint32_t collider : slot.touching_next) {
      if (std::find(slot.touching.begin(), slot.touching.end(), collider) != slot.touching.end()) {
        continue;
      }
      // Point and normal: the strongest contact on this collider (the first one if none pushed).
      const Contact* best = nullptr;
      for (std::size_t k = 0; k < slot.contacts.size(); ++k) {
        if (slot.contacts[k].collider != collider) continue;
        if (best == nullptr || static_cast<int>(k) == resolution.strongest)
          best = &slot.contacts[k];
      }
      const Collider& info = collision_.colliders()[collider];
      CollisionEvent event;
      event.time_ns = end_ns;
      event.vehicle = index;
      event.vehicle_name = slot.vehicle->name();
      event.object_name = scene_->objects[info.object_index].name;
      event.class_id = info.class_id;
      event.instance_id = info.instance_id;
      event.point_W = best->point_W;
      event.normal_W = best->normal_W;
      event.impulse_Ns = resolution.impulse_W.norm();
      slot.events.push_back(std::move(event));
    }
  }
  std::swap(slot.touching, slot.touching_next);
}

}  // namespace airis::engine
