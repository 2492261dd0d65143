#include "engine/world/world.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "engine/core/config.h"
#include "engine/core/error.h"
#include "engine/physics/box_sweep.h"
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
}

World::World(std::shared_ptr<const StaticScene> scene, Environment environment,
             const PhysicsConfig& physics)
    : scene_(std::move(scene)),
      environment_(std::move(environment)),
      physics_(physics),
      collision_(*scene_),
      solver_(SolverConfig(physics)),
      body_solver_(SolverConfig(physics)) {}

World::~World() = default;

std::size_t World::AddVehicle(std::unique_ptr<Vehicle> vehicle) {
  AIRIS_DEMAND(vehicle != nullptr);
  Require(FindVehicle(vehicle->name()) < 0, "vehicles",
          "duplicate vehicle name '" + vehicle->name() + "'");
  Slot slot;
  slot.body = collision_.AddBody(vehicle->body().config().box_size_m);
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
      deepest = Overlap{collision_.colliders()[c.collider].name, false, c.depth_m};
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
  sensors.push_back(std::move(sensor));
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

void World::StepPhysics(TimeNs now_ns, double dt_s) {
  const bool several = slots_.size() > 1;
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    Slot& slot = slots_[i];
    if (several) slot.p_start_W = slot.vehicle->state().p_W;
    if (!slot.held) StepVehicle(slot, i, now_ns, dt_s);
  }
  if (several) ResolveVehicleContacts(now_ns, dt_s);
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
  if (!held) return;
  RigidBodyState& s = slot.vehicle->state();
  s.v_W.setZero();
  s.w_B.setZero();
  slot.accelerations.a_W.setZero();
  slot.accelerations.alpha_B.setZero();
  slot.accelerations.gravity_W = Vec3(0.0, 0.0, environment_.CalcGravity_m_s2(s.p_W));
  slot.contacts.clear();
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
    if (!slot.touching.empty()) slot.touching.clear();
    return;
  }
  const ContactResolution resolution = solver_.Resolve(body, slot.contacts, collision_.colliders(),
                                                       forcing.gravity_m_s2, dt_s, state);
  // Contact impulses are part of the step's acceleration (an accelerometer feels the landing).
  slot.accelerations.a_W = (state.v_W - v0) / dt_s;
  slot.accelerations.alpha_B = (state.w_B - w0) / dt_s;
  ReportNewContacts(slot, index, now_ns + SecondsToNs(dt_s), resolution);
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
      event.object_name = info.name;
      event.class_id = info.class_id;
      event.instance_id = info.instance_id;
      event.point_W = best->point_W;
      event.normal_W = best->normal_W;
      event.impulse_Ns = resolution.impulse_W.norm();
      for (const auto& listener : collision_listeners_) listener(event);
    }
  }
  std::swap(slot.touching, slot.touching_next);
}

std::size_t World::FindVehiclePairContacts(std::size_t i, std::size_t j) {
  Slot& a = slots_[i];
  Slot& b = slots_[j];
  if (a.held && b.held) return 0;
  RigidBodyState& sa = a.vehicle->state();
  RigidBodyState& sb = b.vehicle->state();
  const RigidBodyModel& ma = a.vehicle->body();
  const RigidBodyModel& mb = b.vehicle->body();
  // Bounding spheres along the relative path of the tick (a held vehicle's start is its pose).
  const Vec3 start_W = a.p_start_W - b.p_start_W;
  const Vec3 motion_W = (sa.p_W - sb.p_W) - start_W;
  const double reach_m = ma.bounding_radius_m() + mb.bounding_radius_m();
  const double motion2 = motion_W.squaredNorm();
  const double closest =
      motion2 > 0.0 ? std::clamp(-start_W.dot(motion_W) / motion2, 0.0, 1.0) : 0.0;
  if ((start_W + closest * motion_W).squaredNorm() > reach_m * reach_m) return 0;

  // Continuous collision: when the two close by more than sweep_fraction of the thinner one's
  // smallest half-extent in one tick, the exact time of impact of their boxes (attitudes of the
  // end of the step) takes both back along their paths to where they have just met, leaving at
  // most that much overlap: nothing passes through, however fast.
  const double sweep_beyond_m =
      physics_.sweep_fraction * std::min(ma.min_half_extent_m(), mb.min_half_extent_m());
  if (motion2 > sweep_beyond_m * sweep_beyond_m) {
    const OrientedBox box_a{a.p_start_W, sa.q_WB.toRotationMatrix(), 0.5 * ma.config().box_size_m};
    const OrientedBox box_b{b.p_start_W, sb.q_WB.toRotationMatrix(), 0.5 * mb.config().box_size_m};
    const double impact = CalcBoxTimeOfImpact(box_a, box_b, motion_W);
    if (impact > 0.0 && impact <= 1.0) {
      const double back_to = std::min(1.0, impact + sweep_beyond_m / std::sqrt(motion2));
      if (back_to < 1.0) {
        sa.p_W = a.p_start_W + back_to * (sa.p_W - a.p_start_W);
        sb.p_W = b.p_start_W + back_to * (sb.p_W - b.p_start_W);
      }
    }
  }

  collision_.FindBodyContacts(a.body, sa.p_W, sa.q_WB, b.body, sb.p_W, sb.q_WB, pair_scratch_);
  // Material pairs combine by averaging, as with static colliders.
  const double restitution = 0.5 * (ma.config().restitution + mb.config().restitution);
  const double friction = 0.5 * (ma.config().friction + mb.config().friction);
  for (const Contact& c : pair_scratch_) {
    BodyContact contact;
    contact.a = static_cast<int>(i);
    contact.b = static_cast<int>(j);
    contact.point_W = c.point_W;
    contact.normal_W = c.normal_W;
    contact.depth_m = c.depth_m;
    contact.restitution = restitution;
    contact.friction = friction;
    vehicle_contacts_.push_back(contact);
  }
  return pair_scratch_.size();
}

void World::ResolveVehicleContacts(TimeNs now_ns, double dt_s) {
  vehicle_contacts_.clear();
  pairs_.clear();
  const std::size_t n = slots_.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const std::size_t first = vehicle_contacts_.size();
      const std::size_t count = FindVehiclePairContacts(i, j);
      if (count > 0) pairs_.push_back(VehiclePair{i, j, first, count});
    }
  }
  if (pairs_.empty()) {
    touching_pairs_.clear();
    return;
  }

  // One solve over the vehicles in contact: their contacts with each other, and their static
  // contacts of this tick (already resolved alone in StepVehicle; with them, a vehicle resting on
  // the ground carries one that lands on it instead of being pushed into the ground). The static
  // projection left those at most the slop deep.
  solve_index_.assign(n, -1);
  solve_bodies_.clear();
  solve_vehicles_.clear();
  auto add_body = [&](std::size_t k) {
    if (solve_index_[k] >= 0) return;
    solve_index_[k] = static_cast<int>(solve_bodies_.size());
    Slot& slot = slots_[k];
    solve_bodies_.push_back(ContactBody{&slot.vehicle->body(), &slot.vehicle->state(), slot.held});
    solve_vehicles_.push_back(k);
  };
  for (const VehiclePair& pair : pairs_) {
    add_body(pair.a);
    add_body(pair.b);
  }
  solve_contacts_.clear();
  for (BodyContact c : vehicle_contacts_) {
    c.a = solve_index_[static_cast<std::size_t>(c.a)];
    c.b = solve_index_[static_cast<std::size_t>(c.b)];
    solve_contacts_.push_back(c);
  }
  double gravity_m_s2 = 0.0;
  v_before_W_.resize(solve_bodies_.size());
  w_before_B_.resize(solve_bodies_.size());
  for (std::size_t s = 0; s < solve_bodies_.size(); ++s) {
    const Slot& slot = slots_[solve_vehicles_[s]];
    const RigidBodyState& state = *solve_bodies_[s].state;
    v_before_W_[s] = state.v_W;
    w_before_B_[s] = state.w_B;
    if (slot.held) continue;
    gravity_m_s2 = std::max(gravity_m_s2, slot.local.gravity_m_s2);
    const RigidBodyConfig& material = slot.vehicle->body().config();
    for (const Contact& c : slot.contacts) {
      const Collider& other = collision_.colliders()[c.collider];
      BodyContact contact;
      contact.a = static_cast<int>(s);
      contact.b = -1;
      contact.point_W = c.point_W;
      contact.normal_W = c.normal_W;
      contact.depth_m = std::min(c.depth_m, physics_.penetration_slop_m);
      contact.restitution = 0.5 * (material.restitution + other.restitution);
      contact.friction = 0.5 * (material.friction + other.friction);
      solve_contacts_.push_back(contact);
    }
  }
  body_solver_.Resolve(solve_bodies_, solve_contacts_, gravity_m_s2, dt_s);

  // The impulses are part of the step's acceleration (each vehicle's accelerometer feels them).
  for (std::size_t s = 0; s < solve_bodies_.size(); ++s) {
    Slot& slot = slots_[solve_vehicles_[s]];
    if (slot.held) continue;
    const RigidBodyState& state = *solve_bodies_[s].state;
    slot.accelerations.a_W += (state.v_W - v_before_W_[s]) / dt_s;
    slot.accelerations.alpha_B += (state.w_B - w_before_B_[s]) / dt_s;
  }
  ReportNewVehicleContacts(now_ns + SecondsToNs(dt_s));
}

void World::ReportNewVehicleContacts(TimeNs end_ns) {
  touching_pairs_next_.clear();
  for (const VehiclePair& pair : pairs_) {
    touching_pairs_next_.emplace_back(pair.a, pair.b);
    if (collision_listeners_.empty() ||
        std::find(touching_pairs_.begin(), touching_pairs_.end(), touching_pairs_next_.back()) !=
            touching_pairs_.end()) {
      continue;
    }
    // Point and normal: the contact that pushed hardest; impulse: all of the pair's together (the
    // solve's contacts begin with vehicle_contacts_, in the same order).
    std::size_t best = pair.first;
    Vec3 impulse_W = Vec3::Zero();
    for (std::size_t k = pair.first; k < pair.first + pair.count; ++k) {
      impulse_W += body_solver_.impulse_W(k);
      if (body_solver_.normal_impulse_Ns(k) > body_solver_.normal_impulse_Ns(best)) best = k;
    }
    const BodyContact& contact = vehicle_contacts_[best];
    for (const bool first : {true, false}) {
      const std::size_t self = first ? pair.a : pair.b;
      const std::size_t other = first ? pair.b : pair.a;
      CollisionEvent event;
      event.time_ns = end_ns;
      event.vehicle = self;
      event.vehicle_name = slots_[self].vehicle->name();
      event.object_name = slots_[other].vehicle->name();
      event.other_vehicle = static_cast<int>(other);
      event.point_W = contact.point_W;
      event.normal_W = first ? contact.normal_W : Vec3(-contact.normal_W);
      event.impulse_Ns = impulse_W.norm();
      for (const auto& listener : collision_listeners_) listener(event);
    }
  }
  std::swap(touching_pairs_, touching_pairs_next_);
}

}  // namespace airis::engine
