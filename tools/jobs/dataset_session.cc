#include "tools/jobs/dataset_session.h"

#include "engine/core/error.h"
#include "engine/core/random.h"
#include "engine/dataset/file_io.h"
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

DatasetRecorder::Options RecorderOptions(const engine::World& world, const DatasetWriteOptions& o) {
  DatasetRecorder::Options ro;
  ro.root = o.out;
  ro.resume = o.resume;
  ro.cameras = o.cameras;
  ro.outputs = o.outputs;
  ro.writer.workers = o.workers;
  ro.writer.annotations.min_area_px = o.min_object_area_px;
  for (const auto& c : world.scene().classes) ro.writer.annotations.stuff[c.id] = c.stuff;
  ro.shard_index = o.shard.index - 1;
  ro.shard_count = o.shard.count;
  return ro;
}

}  // namespace

void CheckDatasetWriteOptions(const DatasetWriteOptions& o) {
  if (o.min_object_area_px < 1) {
    throw engine::ConfigError(
        {}, "--min-object-area-px",
        "must be at least 1 (got " + std::to_string(o.min_object_area_px) + ")");
  }
  if (o.workers < 1 || o.workers > 64) {
    throw engine::ConfigError({}, "--encode-threads",
                              "must be 1 to 64 (got " + std::to_string(o.workers) + ")");
  }
}

DatasetSession::DatasetSession(SimulationJob& job, const DatasetWriteOptions& o,
                               const std::string& scene_file, const engine::Mission* mission,
                               const std::vector<std::size_t>& mission_vehicles,
                               const nlohmann::json& px4)
    : job_(job), mission_(mission), manifest_path_(fs::path(o.out) / "manifest.json") {
  source_.scene_file = scene_file;
  source_.mission_file = mission ? mission->file : "";
  source_.outputs = o.outputs;
  source_.shard = o.shard;
  source_.min_object_area_px = o.min_object_area_px;
  source_.full_streams = o.full_streams;
  source_.stream_format = o.stream_format;
  source_.px4 = px4;
  nlohmann::json existing;
  if (o.resume) existing = ReadDatasetManifest(o.out);
  // Refuses outputs a camera cannot give and capture steps its cameras cannot follow; writes
  // nothing.
  recorder_ = std::make_unique<DatasetRecorder>(job.world(), RecorderOptions(job.world(), o));
  if (mission) recorder_->PlanCaptures(*mission, mission_vehicles);
  if (mission && mission->randomize.any()) {
    recorder_->SetRandomization(
        *mission, engine::RandomStreams(job.scene().seed).SeedFor("dataset/randomize"));
  }
  if (!o.resume) PrepareEmptyOutputFolder(o.out, "--out");
  const nlohmann::json start =
      MakeDatasetManifest(source_, job.scene(), mission, job.world(), *recorder_, false, 0.0);
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
  engine::WriteFileAtomically(manifest_path_, start.dump(1));
  engine::TelemetryOptions t;
  t.window_only = !o.full_streams;
  t.format = o.stream_format;
  telemetry_ = std::make_unique<engine::TelemetryRecorder>(job.world(), o.out, t);
  telemetry_->OnTick(0);
}

DatasetSession::~DatasetSession() = default;

void DatasetSession::Finish(bool succeeded, int interrupted_by, double simulated_s,
                            const nlohmann::json& px4) {
  recorder_->Finish();
  telemetry_->Close();
  ManifestSource end = source_;
  end.interrupted_by = interrupted_by;
  if (!px4.is_null()) end.px4 = px4;
  engine::WriteFileAtomically(
      manifest_path_, MakeDatasetManifest(end, job_.scene(), mission_, job_.world(), *recorder_,
                                          succeeded, simulated_s)
                          .dump(1));
}

std::int64_t DatasetSession::frames() const {
  std::int64_t n = 0;
  for (const auto& c : recorder_->cameras()) n += c.frames;
  return n;
}

}  // namespace airis::tools
