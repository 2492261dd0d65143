#include "tools/jobs/dataset_job.h"

#include <algorithm>
#include <vector>

#include "engine/mission/mission_estimate.h"
#include "engine/mission/steps/host_steps.h"
#include "scenes/mission_file.h"
#include "tools/jobs/autopilots.h"

namespace airis::tools {
namespace {

// For each track of `mission`, the index of its last step that starts recording, -1 if none.
std::vector<int> LastCaptureSteps(const engine::Mission& mission) {
  std::vector<int> last;
  for (const engine::MissionTrack& track : mission.tracks) {
    int index = -1;
    for (std::size_t i = 0; i < track.steps.size(); ++i) {
      const engine::CaptureStep* capture = track.steps[i].As<engine::CaptureStep>();
      if (capture && capture->enabled) index = static_cast<int>(i);
    }
    last.push_back(index);
  }
  return last;
}

}  // namespace

DatasetJobResult RunDatasetJob(const DatasetJobOptions& o,
                               const std::function<void(const JobProgress&)>& progress) {
  CheckDatasetWriteOptions(o);
  SimulationJob job(o.scene, o.threads);
  const engine::Mission mission = scenes::LoadMissionFile(o.mission);
  const std::vector<std::size_t> vehicles = job.CheckMission(mission);
  AttachAutopilots(job, o.log);  // PX4 vehicles: their links open before anything is written
  DatasetSession dataset(job, o, o.scene.path, &mission, vehicles);

  // The tracks fly at once: the mission lasts as long as its longest track.
  double nominal_s = 0.0;
  for (std::size_t t = 0; t < vehicles.size(); ++t) {
    nominal_s =
        std::max(nominal_s, engine::EstimateTrackDuration_s(
                                mission.tracks[t], job.world().vehicle(vehicles[t]).state().p_W,
                                job.world().environment().frame(),
                                job.world().scene().terrain.heightfield.get()));
  }
  MissionFlight flight;
  flight.progress_every_ns = 100'000'000;
  flight.stop = o.stop;
  flight.callbacks.after_tick = [&](engine::TimeNs now_ns) { dataset.telemetry().OnTick(now_ns); };
  flight.callbacks.on_capture = [&](std::size_t vehicle, const engine::CaptureStep& c) {
    dataset.recorder().SetCapture(vehicle, c);
    dataset.telemetry().SetRecording(dataset.recorder().recording());
  };
  flight.callbacks.on_event = [&](const engine::MissionEvent& e) {
    dataset.telemetry().RecordMissionEvent(e.time_ns, e.vehicle, e.step_index, e.step_kind, e.what);
  };
  // Every shard writes the whole flight's log alike, except what follows the mission's last
  // capture: there the first shard flies on alone and the others stop (their frames, scans and
  // streams are complete; the merge takes the rest of mission_events.csv and collisions.csv and
  // the mission's outcome from the first). With --streams flight every shard flies to the end.
  const std::vector<int> last_capture = LastCaptureSteps(mission);
  if (o.shard.count > 1 && o.shard.index > 1 && !o.full_streams) {
    flight.done = [&](const engine::MissionSession& session) {
      if (dataset.recorder().recording()) return false;
      for (std::size_t t = 0; t < session.track_count(); ++t) {
        if (session.runner(t).current_step() <= last_capture[t]) return false;
      }
      return true;
    };
  }
  if (progress) {
    flight.progress = [&](JobProgress p) {
      p.frames = dataset.recorder().frames_written();
      const double done = p.simulated_s / std::max(nominal_s, 1e-9);
      if (done > 0.02 && done < 1.0) p.eta_s = p.wall_s * (1.0 - done) / done;
      progress(p);
    };
  }
  const MissionOutcome outcome = job.FlyMission(mission, flight);
  const bool complete = outcome.succeeded() || outcome.done_early;
  if (outcome.done_early) dataset.MarkStoppedAfterLastCapture();
  dataset.Finish(complete, outcome.interrupted_by, outcome.simulated_s);
  DatasetJobResult r;
  r.succeeded = complete;
  r.stopped_after_last_capture = outcome.done_early;
  r.interrupted_by = outcome.interrupted_by;
  if (!r.succeeded) r.failure = outcome.failure;
  r.simulated_s = outcome.simulated_s;
  r.frames = dataset.frames();
  r.cameras = dataset.recorder().cameras().size();
  for (const auto& l : dataset.recorder().lidars()) r.scans += l.scans;
  r.lidars = dataset.recorder().lidars().size();
  r.redone = dataset.recorder().redone();
  r.wall_s = job.wall_s();
  return r;
}

}  // namespace airis::tools
