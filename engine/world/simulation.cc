#include "engine/world/simulation.h"

#include "engine/core/error.h"

namespace airis::engine {

void SimulationConfig::Validate() const { (void)SimClock::FromRateHz(physics_rate_hz); }

Simulation::Simulation(std::unique_ptr<World> world, const SimulationConfig& config)
    : world_(std::move(world)), clock_(SimClock::FromRateHz(config.physics_rate_hz)) {
  AIRIS_DEMAND(world_ != nullptr);
}

void Simulation::Step() {
  const TimeNs start_ns = clock_.now_ns();
  const double dt_s = clock_.step_s();
  Environment& environment = world_->environment();
  environment.wind().Advance(start_ns);
  world_->StepPhysics(start_ns, dt_s);
  clock_.Advance();

  const TimeNs now_ns = clock_.now_ns();
  for (std::size_t i = 0; i < world_->vehicle_count(); ++i) {
    const auto sensors = world_->sensors(i);
    if (sensors.empty()) continue;
    const SensorContext context{now_ns,
                                &world_->vehicle(i).state(),
                                &world_->accelerations(i),
                                &environment,
                                world_->ray_caster(),
                                world_.get(),
                                i};
    for (const auto& sensor : sensors) sensor->Update(context);
  }
  const auto control_context = [&](std::size_t i) {
    Vehicle& vehicle = world_->vehicle(i);
    ControlContext context{now_ns,           dt_s,
                           &vehicle.state(), &world_->accelerations(i),
                           &environment,     world_->sensors(i)};
    world_->CalcLocalConditions(i, &context.air_density_kg_m3, &context.gravity_m_s2);
    return context;
  };
  if (!autopilots_.empty()) {
    for (std::size_t i = 0; i < autopilots_.size(); ++i) {
      if (autopilots_[i]) autopilots_[i]->Publish(control_context(i));
    }
    for (std::size_t i = 0; i < autopilots_.size(); ++i) {
      if (autopilots_[i]) autopilots_[i]->Collect(world_->vehicle(i));
    }
  }
  for (std::size_t i = 0; i < world_->vehicle_count(); ++i) {
    world_->vehicle(i).UpdateControl(control_context(i));
  }
}

void Simulation::SetAutopilot(std::size_t vehicle, std::unique_ptr<Autopilot> autopilot) {
  AIRIS_DEMAND(vehicle < world_->vehicle_count());
  if (autopilots_.size() <= vehicle) autopilots_.resize(world_->vehicle_count());
  autopilots_[vehicle] = std::move(autopilot);
}

void Simulation::RunUntil(TimeNs end_ns) {
  while (clock_.now_ns() < end_ns) Step();
}

void Simulation::RunFor(double seconds) {
  RunUntil(clock_.now_ns() + SecondsToNs(seconds, "seconds"));
}

}  // namespace airis::engine
