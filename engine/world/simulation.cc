#include "engine/world/simulation.h"

#include "engine/core/config.h"
#include "engine/core/error.h"

namespace airis::engine {
namespace {

SensorContext MakeSensorContext(World& world, std::size_t i, TimeNs now_ns) {
  return SensorContext{now_ns,
                       &world.vehicle(i).state(),
                       &world.accelerations(i),
                       &world.environment(),
                       world.ray_caster(),
                       &world,
                       i};
}

// Vehicle i's sensors other than cameras sample when due (on whichever thread steps it).
void SampleSensors(World& world, std::size_t i, TimeNs now_ns) {
  const auto sensors = world.sensors(i);
  if (sensors.empty()) return;
  const SensorContext context = MakeSensorContext(world, i, now_ns);
  for (const auto& sensor : sensors) {
    if (sensor->image() == nullptr) sensor->SampleIfDue(context);
  }
}

// On the calling thread, in the order of vehicles and sensors: images render (the GL context is
// this thread's), and every listener hears of its sensor's sample of this tick.
void NotifySensorListeners(World& world, TimeNs now_ns) {
  for (std::size_t i = 0; i < world.vehicle_count(); ++i) {
    const auto sensors = world.sensors(i);
    if (sensors.empty()) continue;
    const SensorContext context = MakeSensorContext(world, i, now_ns);
    for (const auto& sensor : sensors) {
      if (sensor->image() != nullptr) {
        sensor->Update(context);
      } else if (sensor->has_listeners() && sensor->last_sample_ns() == now_ns) {
        sensor->NotifyListeners();
      }
    }
  }
}

}  // namespace

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
  const auto control_context = [&](std::size_t i) {
    Vehicle& vehicle = world_->vehicle(i);
    ControlContext context{now_ns,           dt_s,
                           &vehicle.state(), &world_->accelerations(i),
                           &environment,     world_->sensors(i)};
    world_->CalcLocalConditions(i, &context.air_density_kg_m3, &context.gravity_m_s2);
    return context;
  };
  const std::size_t n = world_->vehicle_count();
  if (autopilots_.empty()) {
    // Without an autopilot to read the samples first, a vehicle's controller needs only its own
    // vehicle's state and sensors, and what runs on this thread after the sensors (cameras
    // render the poses, listeners record samples) neither reads nor changes the commands it
    // sets: each vehicle samples and controls in one pass, one fork and join a tick fewer, with
    // the same results.
    ParallelFor(pool_.get(), n, [&](std::size_t i) {
      SampleSensors(*world_, i, now_ns);
      world_->vehicle(i).UpdateControl(control_context(i));
    });
    if (world_->sensor_count() > 0) NotifySensorListeners(*world_, now_ns);
    return;
  }
  if (world_->sensor_count() > 0) UpdateSensors(now_ns);
  for (std::size_t i = 0; i < autopilots_.size(); ++i) {
    if (autopilots_[i]) autopilots_[i]->Publish(control_context(i));
  }
  for (std::size_t i = 0; i < autopilots_.size(); ++i) {
    if (autopilots_[i]) autopilots_[i]->Collect(world_->vehicle(i));
  }
  ParallelFor(pool_.get(), n,
              [&](std::size_t i) { world_->vehicle(i).UpdateControl(control_context(i)); });
}

void Simulation::UpdateSensors(TimeNs now_ns) {
  ParallelFor(pool_.get(), world_->vehicle_count(),
              [&](std::size_t i) { SampleSensors(*world_, i, now_ns); });
  NotifySensorListeners(*world_, now_ns);
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
