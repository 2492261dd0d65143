#include "tools/python/python_simulation.h"

#include <algorithm>
#include <cstdio>

#include "scenes/mission_file.h"
#include "tools/jobs/autopilots.h"

namespace airis::python {

PythonSimulation::PythonSimulation(const tools::SceneSource& source, std::size_t max_rows,
                                   int threads)
    : job_(source, threads) {
  job_.DisableImageSensors();
  // A vehicle with `autopilot: {kind: px4}` is PX4's here too (its link opens now; PX4 connects
  // on the first step), so that a scene flies the same from Python as from `airis run`.
  tools::AttachAutopilots(
      job_, [](const std::string& line) { std::fprintf(stderr, "airis: %s\n", line.c_str()); });
  engine::World& w = world();
  buffers_.resize(w.vehicle_count());
  collisions_.resize(w.vehicle_count());
  dropped_.assign(w.vehicle_count(), 0);
  for (std::size_t v = 0; v < w.vehicle_count(); ++v) {
    for (const auto& sensor : w.sensors(v)) {
      if (sensor->image()) {
        buffers_[v].push_back(nullptr);
        continue;
      }
      buffers_[v].push_back(std::make_unique<SampleBuffer>(*sensor, max_rows));
      SampleBuffer* buffer = buffers_[v].back().get();
      sensor->AddListener([buffer](const engine::Sensor& s) { buffer->Append(s); });
    }
  }
  w.AddCollisionListener([this](const engine::CollisionEvent& e) {
    std::vector<engine::CollisionEvent>& list = collisions_[e.vehicle];
    if (list.size() >= kMaxCollisions) {
      ++dropped_[e.vehicle];
      return;
    }
    list.push_back(e);
  });
}

SampleBuffer* PythonSimulation::samples(std::size_t vehicle, std::size_t sensor) {
  return buffers_.at(vehicle).at(sensor).get();
}

std::int64_t PythonSimulation::RunTicks(std::int64_t ticks,
                                        const std::function<bool()>& should_stop) {
  engine::Simulation& sim = simulation();
  std::int64_t done = 0;
  while (done < ticks) {
    const std::int64_t slice = std::min(kCheckEveryTicks, ticks - done);
    if (session_ && mission_state() == engine::MissionRunner::State::kRunning) {
      const engine::TimeNs start = sim.clock().now_ns();
      session_->Run(start + slice * sim.clock().step_ns());
      // A mission that ends inside the slice hands the vehicle back: the rest are plain ticks.
      const std::int64_t flown = (sim.clock().now_ns() - start) / sim.clock().step_ns();
      for (std::int64_t k = flown; k < slice; ++k) sim.Step();
    } else {
      for (std::int64_t k = 0; k < slice; ++k) sim.Step();
    }
    done += slice;
    if (should_stop && done < ticks && should_stop()) break;
  }
  return done;
}

void PythonSimulation::StartMission(const std::string& mission_file) {
  std::unique_ptr<engine::MissionSession> session =
      job_.StartMission(scenes::LoadMissionFile(mission_file));
  // A session listens to the world's collisions for as long as the world lives, so a mission that
  // is replaced stays allocated (retired) instead of being destroyed.
  if (session_) retired_sessions_.push_back(std::move(session_));
  session_ = std::move(session);
}

engine::MissionRunner::State PythonSimulation::RunMission(
    engine::TimeNs until_ns, const std::function<bool()>& should_stop) {
  engine::Simulation& sim = simulation();
  const engine::TimeNs slice_ns = kCheckEveryTicks * sim.clock().step_ns();
  engine::MissionRunner::State state = mission_state();
  while (state == engine::MissionRunner::State::kRunning && sim.clock().now_ns() < until_ns) {
    const engine::TimeNs end = std::min(until_ns, sim.clock().now_ns() + slice_ns);
    state = session_->Run(end);
    if (state == engine::MissionRunner::State::kRunning && should_stop && should_stop()) break;
  }
  return state;
}

}  // namespace airis::python
