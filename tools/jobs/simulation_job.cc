#include "tools/jobs/simulation_job.h"

#include <algorithm>

#include "engine/core/error.h"
#include "engine/core/random.h"
#include "engine/world/image_sensor.h"
#include "scenes/mission_limits.h"
#include "scenes/world_builder.h"

namespace airis::tools {
scenes::Scene LoadSceneSource(const SceneSource& source) {
  const scenes::SceneLoadOptions options{source.seed, source.overrides};
  return source.text.empty() ? scenes::LoadScene(source.path, options)
                             : scenes::LoadSceneFromString(source.text, source.path, options);
}

SimulationJob::SimulationJob(const SceneSource& source, int threads)
    : SimulationJob(source, threads, true) {}

SimulationJob SimulationJob::WithoutCameras(const SceneSource& source) {
  return SimulationJob(source, 1, false);
}

SimulationJob::SimulationJob(const SceneSource& source, int threads, bool cameras)
    : wall_start_(std::chrono::steady_clock::now()), scene_(LoadSceneSource(source)) {
  simulation_ = std::make_unique<engine::Simulation>(
      cameras ? scenes::BuildWorld(scene_) : scenes::BuildWorldWithoutCameras(scene_),
      engine::SimulationConfig{scene_.physics.rate_hz, threads});
}

double SimulationJob::wall_s() const {
  // Wall time is a report to the user, never an input to the simulation.
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start_).count();
}

std::vector<std::size_t> SimulationJob::MissionVehicles(const engine::Mission& mission) const {
  const engine::World& w = world();
  std::string names;
  for (std::size_t i = 0; i < w.vehicle_count(); ++i) {
    names += (names.empty() ? "" : ", ") + w.vehicle(i).name();
  }
  std::vector<std::size_t> out;
  for (const engine::MissionTrack& track : mission.tracks) {
    const std::string key = track.key_path.empty() ? "vehicle" : track.key_path;
    engine::SourceLocation where = track.where;
    if (where.file.empty()) where.file = mission.file;
    if (w.vehicle_count() == 0) {
      throw engine::ConfigError(where, key,
                                "the scene " + scene_.path + " has no vehicle to fly the mission");
    }
    if (track.vehicle.empty()) {
      out.push_back(0);
      continue;
    }
    const int index = w.FindVehicle(track.vehicle);
    if (index < 0) {
      throw engine::ConfigError(
          where, key, "no vehicle '" + track.vehicle + "' in the scene (it has " + names + ")");
    }
    out.push_back(static_cast<std::size_t>(index));
  }
  return out;
}

std::vector<std::size_t> SimulationJob::CheckMission(const engine::Mission& mission) const {
  const std::vector<std::size_t> vehicles = MissionVehicles(mission);
  // From where the vehicles are (on the surface, for those the scene starts on_ground).
  std::vector<engine::Vec3> starts_W;
  for (const std::size_t v : vehicles) starts_W.push_back(world().vehicle(v).state().p_W);
  scenes::CheckMissionInScene(mission, scene_, vehicles, starts_W);
  return vehicles;
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
  const std::vector<std::size_t> vehicles = CheckMission(mission);
  const engine::RandomStreams streams(scene_.seed);
  std::vector<engine::MissionSession::TrackBinding> bindings;
  for (std::size_t t = 0; t < vehicles.size(); ++t) {
    const engine::MissionTrack& track = mission.tracks[t];
    // The single-vehicle form keeps the stream it always had.
    const std::string stream = track.key_path.empty() ? "mission" : "mission/" + track.vehicle;
    bindings.push_back({vehicles[t], streams.Stream(stream)});
  }
  return std::make_unique<engine::MissionSession>(simulation(), mission, bindings,
                                                  std::move(callbacks));
}

MissionOutcome SimulationJob::FlyMission(const engine::Mission& mission,
                                         const MissionFlight& flight) {
  engine::Simulation& sim = simulation();
  const std::unique_ptr<engine::MissionSession> started = StartMission(mission, flight.callbacks);
  engine::MissionSession& session = *started;
  engine::MissionRunner::State state = engine::MissionRunner::State::kRunning;
  // Slices of ticks, so that the progress line can be refreshed between them.
  int interrupted_by = 0;
  bool done_early = false;
  while (state == engine::MissionRunner::State::kRunning &&
         sim.clock().now_ns() < flight.until_ns) {
    if (flight.stop && (interrupted_by = flight.stop->load()) != 0) break;
    const engine::TimeNs end =
        std::min(flight.until_ns, sim.clock().now_ns() + flight.progress_every_ns);
    state = session.Run(end);
    if (flight.progress) flight.progress(Progress(session));
    if (state == engine::MissionRunner::State::kRunning && flight.done && flight.done(session)) {
      done_early = true;
      break;
    }
  }
  MissionOutcome out;
  out.state = state;
  out.interrupted_by = interrupted_by;
  out.done_early = done_early;
  out.failure = session.failure();
  out.simulated_s = sim.clock().now_s();
  for (std::size_t t = 0; t < session.track_count(); ++t) {
    const engine::MissionRunner& r = session.runner(t);
    TrackOutcome track;
    track.vehicle = r.track().vehicle;
    track.state = r.state();
    track.steps_done = r.steps_done();
    track.steps = static_cast<int>(r.track().steps.size());
    track.distance_flown_m = session.distance_flown_m(t);
    track.max_tracking_error_m = r.max_tracking_error_m();
    track.contacts = r.contacts();
    track.collisions = r.collisions();
    out.ended_by_collision =
        out.ended_by_collision || (r.ended_by_collision() && r.failure() == out.failure);
    out.steps_done += track.steps_done;
    out.steps += track.steps;
    out.distance_flown_m += track.distance_flown_m;
    out.max_tracking_error_m = std::max(out.max_tracking_error_m, track.max_tracking_error_m);
    out.contacts += track.contacts;
    out.collisions += track.collisions;
    out.tracks.push_back(track);
  }
  return out;
}

JobProgress SimulationJob::Progress(const engine::MissionSession& session) const {
  JobProgress p;
  p.simulated_s = simulation().clock().now_s();
  p.wall_s = wall_s();
  // The first track still flying (the last one once all are done).
  std::size_t t = 0;
  while (t + 1 < session.track_count() &&
         session.runner(t).state() != engine::MissionRunner::State::kRunning) {
    ++t;
  }
  const engine::MissionRunner& r = session.runner(t);
  const int steps = static_cast<int>(r.track().steps.size());
  const int current = std::min(r.current_step(), steps - 1);
  p.vehicle = r.track().vehicle;
  p.steps = steps;
  p.step = current + 1;
  p.step_kind = std::string(r.track().steps[static_cast<std::size_t>(current)].kind());
  p.position_W = world().vehicle(session.vehicle(t)).state().p_W;
  return p;
}

}  // namespace airis::tools
