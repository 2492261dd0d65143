// World: the contacts between vehicles (StepPhysics, after every vehicle has been stepped against
// the static scene): the broadphase over the vehicles' swept bounds, the swept and discrete tests
// of each near pair, one solve over the vehicles in contact, and their collision events.
#include <algorithm>
#include <cmath>

#include "engine/core/error.h"
#include "engine/physics/box_sweep.h"
#include "engine/world/world.h"

namespace airis::engine {

std::size_t World::FindVehiclePairContacts(std::size_t i, std::size_t j) {
  Slot& a = slots_[i];
  Slot& b = slots_[j];
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

BodyBounds World::CalcSweptBounds(const Slot& slot) {
  // Each vehicle's bounding sphere over its path of the tick, as a box. A pair whose spheres come
  // within reach along their relative path has overlapping boxes (each centre stays on its own
  // path, even when a sweep below takes it back), so the pairs tested are the all-pairs loop's,
  // less pairs that cannot touch, in the same order. Held and sleeping vehicles do not move: two
  // of them cannot come into contact.
  const Vec3& p_W = slot.vehicle->state().p_W;
  const Vec3 reach = Vec3::Constant(slot.vehicle->body().bounding_radius_m());
  return BodyBounds{p_W.cwiseMin(slot.p_start_W) - reach, p_W.cwiseMax(slot.p_start_W) + reach,
                    slot.held || slot.asleep};
}

void World::ResolveVehicleContacts(TimeNs now_ns, double dt_s) {
  vehicle_contacts_.clear();
  pairs_.clear();
  const std::size_t n = slots_.size();
  AIRIS_DEMAND(swept_bounds_.size() == n);
  // Broadphase over the swept bounds of the vehicles (CalcSweptBounds, from StepPhysics).
  // The threads tested the boxes that changed (StepPhysics); the join ordered their flag before
  // this read.
  neighbours_.FindPairs(swept_bounds_, !bounds_escaped_.load(std::memory_order_relaxed),
                        near_pairs_);
  for (const auto& [i, j] : near_pairs_) {
    const std::size_t first = vehicle_contacts_.size();
    const std::size_t count = FindVehiclePairContacts(i, j);
    if (count > 0) pairs_.push_back(VehiclePair{i, j, first, count});
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
    // Touching another vehicle wakes a sleeping one (its static contacts are those it fell
    // asleep on: it has not moved since) and keeps any from falling asleep.
    Wake(slot);
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
