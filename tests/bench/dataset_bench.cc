// Dataset writing speed: the DatasetWriter alone (PNG encoding of RGB, 16-bit depth, class and
// instance maps, and COCO annotation extraction, on its worker threads) and the whole `airis
// dataset` job of the README demo. docs/performance.md has the table.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "engine/dataset/dataset_writer.h"
#include "tools/bench/bench_dataset.h"

namespace airis {
namespace {

namespace fs = std::filesystem;

// A 640x480 labeled frame shaped like a street view: sky above the horizon, 48 façades of distinct
// instances (4 classes) with textured colour and depth growing with the column band, ground below.
std::shared_ptr<engine::CameraFrame> StreetFrame() {
  constexpr int kW = 640, kH = 480;
  auto f = std::make_shared<engine::CameraFrame>();
  f->rgba.Resize(kW, kH, 4);
  f->depth_planar_m.Resize(kW, kH, 1);
  f->class_id.Resize(kW, kH, 1);
  f->instance_id.Resize(kW, kH, 1);
  std::uint32_t noise = 12345;
  for (int v = 0; v < kH; ++v) {
    for (int u = 0; u < kW; ++u) {
      noise = noise * 1664525u + 1013904223u;  // texture, so PNG compression has real work to do
      const int band = u / 40 + 16 * (v / 160);
      const bool sky = v < 120, ground = v >= 420;
      f->depth_planar_m.at(u, v) = sky      ? engine::kSkyDepthM
                                   : ground ? 5.0f + 0.1f * (480 - v)
                                            : 10.0f + band;
      f->class_id.at(u, v) = sky ? 0 : ground ? 2 : static_cast<std::uint8_t>(1 + band % 4);
      f->instance_id.at(u, v) = sky ? 0 : ground ? 1 : static_cast<std::uint32_t>(2 + band);
      for (int c = 0; c < 3; ++c) {
        f->rgba.at(u, v, c) =
            static_cast<std::uint8_t>((sky ? 180 : 60 + 3 * band + c * 20) + (noise >> 29));
      }
      f->rgba.at(u, v, 3) = 255;
    }
  }
  return f;
}

void BM_DatasetWriter640x480(benchmark::State& state) {
  // This process's own folder: two benchmark runs never write into each other's.
  const fs::path root =
      fs::temp_directory_path() / ("airis_bench_dataset_writer_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  engine::DatasetWriter::Options options;
  options.workers = static_cast<int>(state.range(0));
  const auto frame = StreetFrame();
  std::int64_t index = 0;
  {
    engine::DatasetWriter writer(root, options);
    const int camera = writer.AddCamera("front", engine::DatasetOutputs{});
    writer.Submit(camera, index++, frame);  // warm-up: folders, encoder tables
    writer.Flush();
    for (auto _ : state) {
      writer.Submit(camera, index++, frame);
    }
    writer.Flush();  // the queued frames are part of the measured work
  }
  state.SetItemsProcessed(state.iterations());
  fs::remove_all(root);
}
BENCHMARK(BM_DatasetWriter640x480)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);

// The README demo end to end (scene load, mission flight, rendering, writing, COCO, contact sheet),
// once per iteration: items/s is labeled frames per wall second.
void BM_DatasetCitySurvey(benchmark::State& state) {
  tools::DatasetBenchOptions options;
  options.scene = std::string(AIRIS_BENCH_SOURCE_DIR) + "/scenes/city.yaml";
  options.mission = std::string(AIRIS_BENCH_SOURCE_DIR) + "/scenes/missions/city_survey.yaml";
  std::int64_t frames = 0;
  for (auto _ : state) {
    const auto r = tools::RunDatasetBenchmark(options);
    frames += r["frames"].get<std::int64_t>();
  }
  state.SetItemsProcessed(frames);
}
BENCHMARK(BM_DatasetCitySurvey)->Iterations(2)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace
}  // namespace airis
