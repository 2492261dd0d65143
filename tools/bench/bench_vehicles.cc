#include "tools/bench/bench_vehicles.h"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "engine/core/config.h"
#include "scenes/scene.h"
#include "scenes/world_builder.h"
#include "vehicles/multirotor/multirotor.h"

namespace airis::tools {
namespace {

using engine::Vec3;

// The formation: a square grid this far apart, this high, from this corner (NE): over the low
// blocks of scenes/city.yaml (6-14 m), away from its towers.
constexpr double kFormationSpacing_m = 3.0;
constexpr double kFormationHeight_m = 25.0;
constexpr double kFormationCorner_m = -400.0;
// The parking: rows across the east-west street through the origin (12 m wide; cars park from
// 4 m off its centre line), columns along it from past the crossing.
constexpr int kParkingRows = 11;
constexpr double kParkingSpacing_m = 0.5;
constexpr double kParkingStartNorth_m = 8.0;

double ProcessCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

SwarmScenario::SwarmScenario(const SwarmOptions& o) {
  engine::Require(o.flying >= 0 && o.resting >= 0 && o.flying + o.resting >= 1, "vehicles",
                  "need at least one vehicle (got " + std::to_string(o.flying) + " flying, " +
                      std::to_string(o.resting) + " resting)");
  scenes::Scene scene = scenes::LoadScene(o.scene);
  engine::Require(!scene.vehicles.empty(), "vehicles",
                  "the scene " + o.scene + " has no vehicle to copy");
  scenes::VehicleDescription prototype = scene.vehicles.front();
  std::erase_if(prototype.sensors, [](const scenes::SensorDescription& s) {
    return !s.spec->ImageStreamNames(s.name).empty();  // cameras are measured apart
  });
  scene.vehicles.clear();
  const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(o.flying))));
  for (int k = 0; k < o.flying; ++k) {
    scenes::VehicleDescription v = prototype;
    v.name = "flyer" + std::to_string(k);
    v.start = engine::RigidBodyState{};
    v.start.p_W = Vec3(kFormationCorner_m + kFormationSpacing_m * (k % side),
                       kFormationCorner_m + kFormationSpacing_m * (k / side), -kFormationHeight_m);
    v.on_ground = false;
    scene.vehicles.push_back(std::move(v));
  }
  for (int k = 0; k < o.resting; ++k) {
    scenes::VehicleDescription v = prototype;
    v.name = "parked" + std::to_string(k);
    v.start = engine::RigidBodyState{};
    v.start.p_W = Vec3(kParkingStartNorth_m + kParkingSpacing_m * (k / kParkingRows),
                       kParkingSpacing_m * (k % kParkingRows - kParkingRows / 2), -1.0);
    v.on_ground = true;
    scene.vehicles.push_back(std::move(v));
  }
  std::unique_ptr<engine::World> world = scenes::BuildWorld(scene);
  // The flyers start hovering (motors at the hover command) and hold where they are.
  for (int k = 0; k < o.flying; ++k) {
    auto& quad = dynamic_cast<vehicles::Multirotor&>(world->vehicle(static_cast<std::size_t>(k)));
    const Vec3 p_W = quad.state().p_W;
    const double hover = quad.CalcHoverCommand(world->environment().CalcAir(p_W).density_kg_m3,
                                               world->environment().CalcGravity_m_s2(p_W));
    quad.ResetActuators(
        std::vector<double>(static_cast<std::size_t>(quad.actuator_count()), hover));
    engine::VehicleCommand hold;
    hold.mode = engine::CommandMode::kPosition;
    hold.position_W = p_W;
    quad.SetCommand(hold);
  }
  simulation_ = std::make_unique<engine::Simulation>(
      std::move(world), engine::SimulationConfig{scene.physics.rate_hz, o.threads});
}

SwarmScenario::~SwarmScenario() = default;

void SwarmScenario::Tick() { simulation_->Step(); }

int SwarmScenario::sleeping() const {
  const engine::World& world = simulation_->world();
  int n = 0;
  for (std::size_t i = 0; i < world.vehicle_count(); ++i) n += world.asleep(i) ? 1 : 0;
  return n;
}

nlohmann::json RunVehicleBench(const VehicleBenchOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto built = Clock::now();
  SwarmScenario swarm(options.swarm);
  const double build_s = std::chrono::duration<double>(Clock::now() - built).count();
  engine::Simulation& sim = swarm.simulation();
  sim.RunFor(options.warm_up_s);

  const auto start = Clock::now();
  const double cpu_start = ProcessCpuSeconds();
  std::int64_t ticks = 0;
  double wall_s = 0.0;
  do {
    for (int i = 0; i < 100; ++i) swarm.Tick();
    ticks += 100;
    wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  } while (wall_s < options.min_seconds);
  const double cpu_s = ProcessCpuSeconds() - cpu_start;

  const int vehicles = options.swarm.flying + options.swarm.resting;
  const double ticks_per_s = static_cast<double>(ticks) / wall_s;
  nlohmann::json out;
  out["scene"] = options.swarm.scene;
  out["flying"] = options.swarm.flying;
  out["resting"] = options.swarm.resting;
  out["vehicles"] = vehicles;
  out["threads"] = options.swarm.threads;
  const double rate_hz = 1.0 / sim.clock().step_s();
  out["physics_rate_hz"] = rate_hz;
  out["ticks_per_s"] = ticks_per_s;
  out["real_time_factor"] = ticks_per_s / rate_hz;
  out["ns_per_tick"] = 1e9 / ticks_per_s;
  out["ns_per_vehicle_tick"] = 1e9 / ticks_per_s / vehicles;
  out["cpu_ns_per_tick"] = 1e9 * cpu_s / static_cast<double>(ticks);
  out["cpu_utilisation"] = cpu_s / wall_s;
  out["sleeping"] = swarm.sleeping();
  out["build_s"] = build_s;
  return out;
}

}  // namespace airis::tools
