#include "tools/jobs/simulation_job.h"

#include <algorithm>

#include "engine/core/error.h"
#include "engine/core/random.h"
#include "engine/world/image_sensor.h"
#include "scenes/world_builder.h"

namespace airis::tools {
scenes::Scene LoadSceneSource(const SceneSource& source) {
  const scenes::SceneLoadOptions options{source.seed};
  return source.text.empty() ? scenes::LoadScene(source.path, options)
                             : scenes::LoadSceneFromString(source.text, source.path, options);
}

SimulationJob::SimulationJob(const SceneSource& source, int threads)
    : wall_start_(std::chrono::steady_clock::now()), scene_(LoadSceneSource(source)) {
  simulation_ = std::make_unique<engine::Simulation>(
      scenes::BuildWorld(scene_), engine::SimulationConfig{scene_.physics.rate_hz, threads});
}

double SimulationJob::wall_s() const {
  // Wall time is a report to the user, never an input to the simulation.
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start_).count();
}

std::size_t SimulationJob::MissionVehicle(const engine::Mission& mission) const {
  const engine::World& w = world();
  std::string names;
  for (std::size_t i = 0; i < w.vehicle_count(); ++i) {
    names += (names.empty() ? "" : ", ") + w.vehicle(i).name();
  }
  if (w.vehicle_count() == 0) {
    throw engine::ConfigError({mission.file, 0, 0}, "vehicle",
                              "the scene has no vehicle to fly the mission");
  }
  if (mission.vehicle.empty()) return 0;
  const int index = w.FindVehicle(mission.vehicle);
  if (index < 0) {
    throw engine::ConfigError(
        {mission.file, 0, 0}, "vehicle",
        "no vehicle '" + mission.vehicle + "' in the scene (it has " + names + ")");
  }
  return static_cast<std::size_t>(index);
}

void SimulationJob::DisableImageSensors() {
  engine::World& w = world();
  for (std::size_t v = 0; v < w.vehicle_count(); ++v) {
    for (const auto& sensor : w.sensors(v)) {
      if (sensor->image()) sensor->set_enabled(false);
    }
  }
}

std::unique_ptr<engine::MissionSession> SimulationJob::StartMission(
    const engine::Mission& mission, engine::MissionSession::Callbacks callbacks) {
  const std::size_t vehicle = MissionVehicle(mission);
  return std::make_unique<engine::MissionSession>(
      simulation(), mission, vehicle, engine::RandomStreams(scene_.seed).Stream("mission"),
      std::move(callbacks));
}

MissionOutcome SimulationJob::FlyMission(const engine::Mission& mission,
                                         const MissionFlight& flight) {
  engine::Simulation& sim = simulation();
  const std::size_t vehicle = MissionVehicle(mission);
  const std::unique_ptr<engine::MissionSession> started = StartMission(mission, flight.callbacks);
  engine::MissionSession& session = *started;
  const engine::Vehicle& flyer = sim.world().vehicle(vehicle);
  const int steps = static_cast<int>(mission.steps.size());
  engine::MissionRunner::State state = engine::MissionRunner::State::kRunning;
  // Slices of ticks, so that the progress line can be refreshed between them.
  int interrupted_by = 0;
  while (state == engine::MissionRunner::State::kRunning &&
         sim.clock().now_ns() < flight.until_ns) {
    if (flight.stop && (interrupted_by = flight.stop->load()) != 0) break;
    const engine::TimeNs end =
        std::min(flight.until_ns, sim.clock().now_ns() + flight.progress_every_ns);
    state = session.Run(end);
    if (!flight.progress || steps == 0) continue;
    JobProgress p;
    p.steps = steps;
    const int current = std::min(session.runner().current_step(), steps - 1);
    p.step = current + 1;
    p.step_kind = std::string(mission.steps[current].kind());
    p.simulated_s = sim.clock().now_s();
    p.wall_s = wall_s();
    p.position_W = flyer.state().p_W;
    flight.progress(p);
  }
  MissionOutcome out;
  out.state = state;
  out.interrupted_by = interrupted_by;
  out.failure = session.runner().failure();
  for (const auto& e : session.runner().events()) out.steps_done += e.what == "done";
  out.steps = steps;
  out.distance_flown_m = session.distance_flown_m();
  out.max_tracking_error_m = session.runner().max_tracking_error_m();
  out.simulated_s = sim.clock().now_s();
  return out;
}

}  // namespace airis::tools
