#include "engine/world/simulation.h"

#include "engine/core/config.h"
#include "engine/core/error.h"

namespace airis::engine {

void SimulationConfig::Validate() const {
  (void)SimClock::FromRateHz(physics_rate_hz);
  RequireInRange("threads", threads, 1, 64);
}

Simulation::Simulation(std::unique_ptr<World> world, const SimulationConfig& config)
    : world_(std::move(world)), clock_(SimClock::FromRateHz(config.physics_rate_hz)) {
  AIRIS_DEMAND(world_ != nullptr);
  config.Validate();
  if (config.threads > 1) pool_ = std::make_unique<WorkerPool>(config.threads);
}

void Simulation::Step() {
  const TimeNs start_ns = clock_.now_ns();
  const double dt_s = clock_.step_s();
  Environment& environment = world_->environment();
  environment.wind().Advance(start_ns);
  world_->StepPhysics(start_ns, dt_s, pool_.get());
  clock_.Advance();

  const TimeNs now_ns = clock_.now_ns();
  if (world_->sensor_count() > 0) UpdateSensors(now_ns);
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
  ParallelFor(pool_.get(), world_->vehicle_count(),
              [&](std::size_t i) { world_->vehicle(i).UpdateControl(control_context(i)); });
}

void Simulation::UpdateSensors(TimeNs now_ns) {
  const std::size_t n = world_->vehicle_count();
  const auto sensor_context = [&](std::size_t i) {
    return SensorContext{now_ns,
                         &world_->vehicle(i).state(),
                         &world_->accelerations(i),
                         &world_->environment(),
                         world_->ray_caster(),
                         world_.get(),
                         i};
  };
  ParallelFor(pool_.get(), n, [&](std::size_t i) {
    const auto sensors = world_->sensors(i);
    if (sensors.empty()) return;
    const SensorContext context = sensor_context(i);
    for (const auto& sensor : sensors) {
      if (sensor->image() == nullptr) sensor->SampleIfDue(context);
    }
  });
  // Images render here (the GL context is this thread's), and every listener hears of its
  // sensor's sample here, in the order of vehicles and sensors.
  for (std::size_t i = 0; i < n; ++i) {
    const auto sensors = world_->sensors(i);
    if (sensors.empty()) continue;
    const SensorContext context = sensor_context(i);
    for (const auto& sensor : sensors) {
      if (sensor->image() != nullptr) {
        sensor->Update(context);
      } else if (sensor->has_listeners() && sensor->last_sample_ns() == now_ns) {
        sensor->NotifyListeners();
      }
    }
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
