#include "tools/jobs/dataset_job.h"

#include <algorithm>
#include <filesystem>
#include <memory>

#include "engine/core/error.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/telemetry_recorder.h"
#include "engine/mission/mission_estimate.h"
#include "scenes/mission_file.h"
#include "tools/jobs/autopilots.h"
#include "tools/jobs/dataset_manifest.h"
#include "tools/jobs/dataset_recorder.h"
#include "tools/jobs/output_folder.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

// Removes what an interrupted run leaves half-written (temporary images, unfinished CSVs).
void RemoveUnfinishedFiles(const fs::path& root) {
  std::vector<fs::path> doomed;
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    const std::string name = e.path().filename().string();
    if (name.ends_with(".tmp") || name.ends_with(".partial")) doomed.push_back(e.path());
  }
  for (const auto& p : doomed) fs::remove(p);
}

}  // namespace

DatasetJobResult RunDatasetJob(const DatasetJobOptions& o,
                               const std::function<void(const JobProgress&)>& progress) {
  if (o.min_object_area_px < 1) {
    throw engine::ConfigError(
        {}, "--min-object-area-px",
        "must be at least 1 (got " + std::to_string(o.min_object_area_px) + ")");
  }
  if (o.workers < 1 || o.workers > 64) {
    throw engine::ConfigError({}, "--workers",
                              "must be 1 to 64 (got " + std::to_string(o.workers) + ")");
  }
  SimulationJob job(o.scene, o.threads);
  const engine::Mission mission = scenes::LoadMissionFile(o.mission);
  const std::size_t vehicle = job.MissionVehicle(mission);
  AttachAutopilots(job, o.log);  // PX4 vehicles: their links open before anything is written
  const fs::path manifest_path = fs::path(o.out) / "manifest.json";
  nlohmann::json existing;
  if (o.resume) existing = ReadDatasetManifest(o.out);

  DatasetRecorder::Options ro;
  ro.root = o.out;
  ro.resume = o.resume;
  ro.cameras = o.cameras;
  ro.outputs = o.outputs;
  ro.writer.workers = o.workers;
  ro.writer.annotations.min_area_px = o.min_object_area_px;
  for (const auto& c : job.world().scene().classes) ro.writer.annotations.stuff[c.id] = c.stuff;
  ro.shard_index = o.shard.index - 1;
  ro.shard_count = o.shard.count;
  DatasetRecorder recorder(job.world(),
                           ro);  // refuses outputs a camera cannot give; writes nothing
  if (!o.resume) PrepareEmptyOutputFolder(o.out, "--out");
  ManifestSource source{o.scene.path,         o.mission,      o.outputs,      o.shard,
                        o.min_object_area_px, o.full_streams, o.stream_format};
  const nlohmann::json start =
      MakeDatasetManifest(source, job.scene(), mission, job.world(), recorder, false, 0.0);
  if (o.resume) {
    // Frames of another scene, mission, seed, shard or camera must not be mixed in: refuse,
    // naming the difference, before anything in the folder changes.
    if (const std::string diff = FindResumeMismatch(existing, start); !diff.empty()) {
      throw engine::ConfigError({}, "--resume",
                                "'" + o.out + "' holds another dataset than this run makes: its " +
                                    "manifest differs in " + diff);
    }
    RemoveUnfinishedFiles(o.out);
  }
  engine::WriteFileAtomically(manifest_path, start.dump(1));
  engine::TelemetryOptions t;
  t.window_only = !o.full_streams;
  t.format = o.stream_format;
  engine::TelemetryRecorder telemetry(job.world(), o.out, t);
  telemetry.OnTick(0);

  const double nominal_s = engine::EstimateMissionDuration_s(
      mission, job.world().vehicle(vehicle).state().p_W, job.world().environment().frame());
  MissionFlight flight;
  flight.progress_every_ns = 100'000'000;
  flight.stop = o.stop;
  flight.callbacks.after_tick = [&](engine::TimeNs now_ns) { telemetry.OnTick(now_ns); };
  flight.callbacks.on_capture = [&](const engine::CaptureStep& c) {
    recorder.SetCapture(c);
    telemetry.SetRecording(c.enabled);
  };
  flight.callbacks.on_event = [&](const engine::MissionEvent& e) {
    telemetry.RecordMissionEvent(e.time_ns, e.step_index, e.step_kind, e.what);
  };
  if (progress) {
    flight.progress = [&](JobProgress p) {
      p.frames = recorder.frames_written();
      const double done = p.simulated_s / std::max(nominal_s, 1e-9);
      if (done > 0.02 && done < 1.0) p.eta_s = p.wall_s * (1.0 - done) / done;
      progress(p);
    };
  }
  const MissionOutcome outcome = job.FlyMission(mission, flight);
  recorder.Finish();
  telemetry.Close();
  DatasetJobResult r;
  r.succeeded = outcome.succeeded();
  r.interrupted_by = outcome.interrupted_by;
  if (!r.succeeded) r.failure = outcome.failure;
  r.simulated_s = outcome.simulated_s;
  ManifestSource end = source;
  end.interrupted_by = r.interrupted_by;
  engine::WriteFileAtomically(manifest_path,
                              MakeDatasetManifest(end, job.scene(), mission, job.world(), recorder,
                                                  r.succeeded, r.simulated_s)
                                  .dump(1));
  for (const auto& c : recorder.cameras()) r.frames += c.frames;
  r.cameras = recorder.cameras().size();
  r.redone = recorder.redone();
  r.wall_s = job.wall_s();
  return r;
}

}  // namespace airis::tools
