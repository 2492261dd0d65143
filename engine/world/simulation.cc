#include "engine/world/simulation.h"

#include <cstring>

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
                       i,
                       world.motion_serial(i)};
}

// Vehicle i's sensors other than cameras sample when due (on whichever thread steps it). Returns
// whether one of them sampled and has listeners to tell.
bool SampleSensors(World& world, std::size_t i, TimeNs now_ns) {
  const auto sensors = world.row_sensors(i);
  if (sensors.empty()) return false;
  const SensorContext context = MakeSensorContext(world, i, now_ns);
  bool heard = false;
  for (Sensor* sensor : sensors) {
    if (sensor->SampleIfDue(context) && sensor->has_listeners()) heard = true;
  }
  return heard;
}

// Sets vehicle i's flag of NotifySensorListeners. The threads write the flags of neighbouring
// vehicles, which share cache lines: written only when it changes (rarely: a sensor with listeners
// at the physics rate samples every tick), a flag keeps its line in both cores' caches instead of
// moving it from core to core a few times a tick.
void SetHeard(std::vector<char>& heard, std::size_t i, bool value) {
  if (heard[i] != static_cast<char>(value)) heard[i] = static_cast<char>(value);
}

// On the calling thread, in the order of vehicles and sensors: images render (the GL context is
// this thread's), and every listener hears of its sensor's sample of this tick. Vehicles without
// cameras whose samples nobody listens to this tick (`heard` false) are passed over.
void NotifySensorListeners(World& world, TimeNs now_ns, const std::vector<char>& heard) {
  // A swarm whose samples nobody records, on most ticks: one scan of the flags.
  if (world.image_sensor_count() == 0 && std::memchr(heard.data(), 1, heard.size()) == nullptr) {
    return;
  }
  for (std::size_t i = 0; i < world.vehicle_count(); ++i) {
    if (!heard[i] && !world.has_image_sensors(i)) continue;
    const auto sensors = world.sensors(i);
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
  if (heard_.size() != n) heard_.resize(n);
  if (autopilots_.empty()) {
    // Without an autopilot to read the samples first, a vehicle's controller needs only its own
    // vehicle's state and sensors, and what runs on this thread after the sensors (cameras
    // render the poses, listeners record samples) neither reads nor changes the commands it
    // sets: each vehicle samples and controls in one pass, one fork and join a tick fewer, with
    // the same results.
    ParallelFor(pool_.get(), n, [&](std::size_t i) {
      SetHeard(heard_, i, SampleSensors(*world_, i, now_ns));
      Vehicle& vehicle = world_->vehicle(i);
      if (vehicle.has_active_controller()) vehicle.UpdateControl(control_context(i));
    });
    if (world_->sensor_count() > 0) NotifySensorListeners(*world_, now_ns, heard_);
    return;
  }
  if (world_->sensor_count() > 0) UpdateSensors(now_ns);
  for (std::size_t i = 0; i < autopilots_.size(); ++i) {
    if (autopilots_[i]) autopilots_[i]->Publish(control_context(i));
  }
  for (std::size_t i = 0; i < autopilots_.size(); ++i) {
    if (autopilots_[i]) autopilots_[i]->Collect(world_->vehicle(i));
  }
  ParallelFor(pool_.get(), n, [&](std::size_t i) {
    Vehicle& vehicle = world_->vehicle(i);
    if (vehicle.has_active_controller()) vehicle.UpdateControl(control_context(i));
  });
}

void Simulation::UpdateSensors(TimeNs now_ns) {
  ParallelFor(pool_.get(), world_->vehicle_count(),
              [&](std::size_t i) { SetHeard(heard_, i, SampleSensors(*world_, i, now_ns)); });
  NotifySensorListeners(*world_, now_ns, heard_);
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
