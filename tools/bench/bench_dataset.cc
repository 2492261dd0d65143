#include "tools/bench/bench_dataset.h"

#include <unistd.h>

#include <filesystem>
#include <stdexcept>

#include "engine/core/error.h"
#include "engine/dataset/file_io.h"
#include "tools/jobs/dataset_job.h"

namespace airis::tools {
namespace {

namespace fs = std::filesystem;

// A fresh folder under the system's temporary directory, removed when this goes out of scope.
class TemporaryFolder {
 public:
  TemporaryFolder() {
    std::string pattern = (fs::temp_directory_path() / "airis_bench_dataset_XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr)
      throw std::runtime_error("cannot create a folder under " + pattern);
    path_ = pattern;
  }
  ~TemporaryFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

}  // namespace

nlohmann::json RunDatasetBenchmark(const DatasetBenchOptions& options) {
  for (const std::string& file : {options.scene, options.mission}) {
    if (!fs::exists(file)) {
      throw engine::ConfigError(
          {}, "bench dataset",
          "'" + file +
              "' not found: run it from the airis repository root (it flies the README demo)");
    }
  }
  const TemporaryFolder folder;
  DatasetJobOptions job;
  job.scene.path = options.scene;
  job.mission = options.mission;
  job.out = (folder.path() / "dataset").string();
  job.workers = options.workers;
  const DatasetJobResult r = RunDatasetJob(job);
  if (!r.succeeded) throw std::runtime_error("the benchmark mission failed: " + r.failure);
  const auto bytes = engine::ReadFileBytes(fs::path(job.out) / "manifest.json");
  const nlohmann::json manifest = nlohmann::json::parse(bytes.begin(), bytes.end());
  nlohmann::json out;
  out["city_640x480_frames_per_s"] = static_cast<double>(r.frames) / r.wall_s;
  out["frames"] = r.frames;
  out["wall_s"] = r.wall_s;
  out["simulated_s"] = r.simulated_s;
  out["scene"] = options.scene;
  out["mission"] = options.mission;
  out["workers"] = options.workers;
  out["outputs"] = "rgb png + depth png (mm) + class and instance png + coco_instances.json";
  if (!manifest["cameras"].empty()) {
    const auto& cam = manifest["cameras"][0];
    out["frame_size"] =
        std::to_string(cam["width"].get<int>()) + "x" + std::to_string(cam["height"].get<int>());
  }
  out["gl_renderer"] = manifest["renderer"]["gl_renderer"];
  return out;
}

}  // namespace airis::tools
