#include "tools/jobs/dataset_job.h"

#include <algorithm>
#include <filesystem>
#include <memory>

#include "engine/core/error.h"
#include "engine/dataset/file_io.h"
#include "engine/dataset/telemetry_recorder.h"
#include "engine/mission/mission_estimate.h"
#include "scenes/mission_file.h"
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
  SimulationJob job(o.scene);
  const engine::Mission mission = scenes::LoadMissionFile(o.mission);
  const std::size_t vehicle = job.MissionVehicle(mission);
  if (o.resume) {
    if (!fs::is_directory(o.out))
      throw engine::ConfigError({}, "--resume", "'" + o.out + "' is not a dataset folder");
    RemoveUnfinishedFiles(o.out);
  } else {
    PrepareEmptyOutputFolder(o.out, "--out");
  }

  DatasetRecorder::Options ro;
  ro.root = o.out;
  ro.resume = o.resume;
  ro.cameras = o.cameras;
  ro.outputs = o.outputs;
  ro.writer.workers = o.workers;
  ro.writer.annotations.min_area_px = o.min_object_area_px;
  ro.shard_index = o.shard.index - 1;
  ro.shard_count = o.shard.count;
  DatasetRecorder recorder(job.world(), ro);
  engine::TelemetryRecorder telemetry(job.world(), o.out, 100.0);
  const ManifestSource source{o.scene.path, o.mission, o.outputs, o.shard, o.min_object_area_px};
  const fs::path manifest_path = fs::path(o.out) / "manifest.json";
  engine::WriteFileAtomically(
      manifest_path,
      MakeDatasetManifest(source, job.scene(), mission, job.world(), recorder, false, 0.0).dump(1));
  telemetry.OnTick(0);

  const double nominal_s = engine::EstimateMissionDuration_s(
      mission, job.world().vehicle(vehicle).state().p_W, job.world().environment().frame());
  MissionFlight flight;
  flight.progress_every_ns = 100'000'000;
  flight.callbacks.after_tick = [&](engine::TimeNs now_ns) { telemetry.OnTick(now_ns); };
  flight.callbacks.on_capture = [&](const engine::CaptureStep& c) { recorder.SetCapture(c); };
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
  if (!r.succeeded) r.failure = outcome.failure;
  r.simulated_s = outcome.simulated_s;
  engine::WriteFileAtomically(
      manifest_path, MakeDatasetManifest(source, job.scene(), mission, job.world(), recorder,
                                         r.succeeded, r.simulated_s)
                         .dump(1));
  for (const auto& c : recorder.cameras()) r.frames += c.frames;
  r.cameras = recorder.cameras().size();
  r.wall_s = job.wall_s();
  return r;
}

}  // namespace airis::tools
