// Loading and generating scenes of about 10,000 objects (DESIGN.md principle 5: "well under a
// second"). Counters: objects placed and the static scene's heap (EstimateMemoryBytes).
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "engine/core/random.h"
#include "scenes/builtin_classes.h"
#include "scenes/generators.h"
#include "scenes/scene.h"
#include "scenes/scene_stats.h"
#include "scenes/terrain.h"
#include "tests/scenes/dem_test_files.h"

namespace airis::scenes {
namespace {

// 36 ha at 280 trees/ha: about 10,000 trees.
ForestConfig TenThousandTrees() {
  ForestConfig c;
  c.name = "bench";
  c.area.size_m = Eigen::Vector2d(600, 600);
  c.density_per_ha = 280;
  c.min_spacing_m = 3.0;
  return c;
}

// A 1.7 km x 1.7 km grid: about 10,000 buildings, sidewalks, lamps and cars.
CityConfig TenThousandObjectCity() {
  CityConfig c;
  c.name = "bench";
  c.area.size_m = Eigen::Vector2d(1700, 1700);
  c.lot_size_m = Eigen::Vector2d(24, 24);
  return c;
}

void ReportScene(benchmark::State& state, const engine::StaticScene& s) {
  state.counters["objects"] = static_cast<double>(s.objects.size());
  state.counters["memory_MiB"] = static_cast<double>(EstimateMemoryBytes(s)) / (1024.0 * 1024.0);
  state.counters["models"] = static_cast<double>(s.models.size());
  state.counters["meshes"] = static_cast<double>(s.meshes.size());
}

void BM_GenerateForest10k(benchmark::State& state) {
  const ForestConfig config = TenThousandTrees();
  auto run = [&] {
    engine::StaticSceneBuilder b(BuiltInClasses());
    engine::RandomStream stream(1);
    GenerateForest(config, {5, 6}, config.name, stream, b);
    return b.Finish();
  };
  const engine::StaticScene warm = run();  // warm-up, and the numbers for the counters
  for (auto _ : state) {
    engine::StaticScene s = run();
    benchmark::DoNotOptimize(s.objects.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(warm.objects.size()));
  ReportScene(state, warm);
}
BENCHMARK(BM_GenerateForest10k)->Unit(benchmark::kMillisecond);

// Generated terrain of 10 km x 10 km at 10 m (1,001 x 1,001 samples, 6 octaves): the heights,
// then the 256 chunks of 64 x 64 cells (meshes with normals and materials) the scene gets.
TerrainConfig TenKilometreTerrain() {
  TerrainConfig c;
  c.extent_m = Eigen::Vector2d(10000, 10000);
  c.resolution_m = 10.0;
  c.relief_m = 400.0;
  c.feature_size_m = 3000.0;
  c.octaves = 6;
  return c;
}

void BM_GenerateTerrain10km(benchmark::State& state) {
  const TerrainConfig config = TenKilometreTerrain();
  for (auto _ : state) {
    engine::RandomStream stream(1);
    engine::Heightfield field = GenerateTerrain(config, stream);
    benchmark::DoNotOptimize(field.max_height_m());
  }
  state.SetItemsProcessed(state.iterations() * 1001 * 1001);
}
BENCHMARK(BM_GenerateTerrain10km)->Unit(benchmark::kMillisecond);

void BM_TerrainChunks10km(benchmark::State& state) {
  const TerrainConfig config = TenKilometreTerrain();
  engine::RandomStream stream(1);
  const engine::Heightfield field = GenerateTerrain(config, stream);
  for (auto _ : state) {
    engine::StaticSceneBuilder b(BuiltInClasses());
    AddTerrain(config, field, 15, b);
    benchmark::DoNotOptimize(b.scene().objects.data());
  }
  state.SetItemsProcessed(state.iterations() * 1001 * 1001);
}
BENCHMARK(BM_TerrainChunks10km)->Unit(benchmark::kMillisecond);

// A 1,000 x 1,000 DEM of 10 m pixels in UTM zone 32N (a 10 km tile, rolling hills), read and
// reprojected onto the scene's NED grid at its own pixel size (about 990 x 990 samples of the
// inscribed rectangle): the file read, two fixed-point passes of WGS84 <-> UTM per sample and the
// bilinear sampling; with the argument 1, heights above mean sea level (the EGM96 geoid's grid
// interpolated at every sample too). Written to the temporary folder outside the timed loop.
void BM_LoadDem1000(benchmark::State& state) {
  constexpr double kLat_deg = 47.3769, kLon_deg = 8.5417;
  double x0 = kLon_deg, y0 = kLat_deg;
  testing::TransformPoint("EPSG:4326", "EPSG:32632", &x0, &y0);
  testing::DemSpec spec;
  spec.width = spec.height = 1000;
  spec.pixel = 10.0;
  spec.x0 = x0 - 5000.0;
  spec.y0 = y0 + 5000.0;
  spec.height_at = [x0, y0](double x, double y) {
    return 450.0 + 40.0 * std::sin((x - x0) / 700.0) * std::cos((y - y0) / 900.0);
  };
  const std::string path =
      (std::filesystem::temp_directory_path() / "airis-bench-dem-1000.tif").string();
  if (!testing::WriteDem(path, spec)) {
    state.SkipWithError("cannot write the DEM");
    return;
  }
  DemSampling sampling;
  sampling.path = path;
  sampling.heights = state.range(0) == 1 ? DemHeights::kMsl : DemHeights::kEllipsoid;
  const engine::LocalNedFrame frame({engine::DegToRad(kLat_deg), engine::DegToRad(kLon_deg), 408});
  std::size_t samples = 0;
  for (auto _ : state) {
    const engine::Heightfield field = LoadDemTerrain(sampling, frame);
    samples = static_cast<std::size_t>(field.rows()) * static_cast<std::size_t>(field.cols());
    benchmark::DoNotOptimize(field.max_height_m());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(samples));
  state.counters["samples"] = static_cast<double>(samples);
  std::filesystem::remove(path);
}
BENCHMARK(BM_LoadDem1000)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The Poisson-disc sampling alone (Bridson, r = 3 m over 36 ha, before thinning to the density).
void BM_PoissonDisc36ha(benchmark::State& state) {
  std::size_t points = 0;
  {
    engine::RandomStream warm(1);
    points =
        PoissonDiscSample(Eigen::Vector2d(-300, -300), Eigen::Vector2d(300, 300), 3.0, warm).size();
  }
  for (auto _ : state) {
    engine::RandomStream stream(1);
    auto p = PoissonDiscSample(Eigen::Vector2d(-300, -300), Eigen::Vector2d(300, 300), 3.0, stream);
    benchmark::DoNotOptimize(p.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points));
  state.counters["points"] = static_cast<double>(points);
}
BENCHMARK(BM_PoissonDisc36ha)->Unit(benchmark::kMillisecond);

// A wide area (5 km x 5 km at r = 7.5 m, the 10 km forest's spacing): five bands of 1 km, on 1 or
// 2 threads (the points are the same).
void BM_PoissonDisc5km(benchmark::State& state) {
  const auto threads = static_cast<int>(state.range(0));
  const Eigen::Vector2d lo(0, 0), hi(5000, 5000);
  std::size_t points = 0;
  for (auto _ : state) {
    engine::RandomStream stream(1);
    auto p = PoissonDiscSample(lo, hi, 7.5, stream, threads);
    points = p.size();
    benchmark::DoNotOptimize(p.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points));
  state.counters["points"] = static_cast<double>(points);
}
BENCHMARK(BM_PoissonDisc5km)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_GenerateCity10k(benchmark::State& state) {
  const CityConfig config = TenThousandObjectCity();
  auto run = [&] {
    engine::StaticSceneBuilder b(BuiltInClasses());
    engine::RandomStream stream(1);
    GenerateCity(config, {4, 2, 3, 10, 7, std::nullopt}, config.name, stream, b);
    return b.Finish();
  };
  const engine::StaticScene warm = run();
  for (auto _ : state) {
    engine::StaticScene s = run();
    benchmark::DoNotOptimize(s.objects.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(warm.objects.size()));
  ReportScene(state, warm);
}
BENCHMARK(BM_GenerateCity10k)->Unit(benchmark::kMillisecond);

// The whole path: YAML text -> parse -> validate -> generate -> whole-scene checks, with a vehicle
// whose start is tested against every object.
void BM_LoadForestScene10k(benchmark::State& state) {
  const std::string text =
      "scene: {name: bench, seed: 1}\n"
      "generators:\n"
      "  - forest: {area: {size_ne_m: [600, 600]}, density_per_ha: 280, clearings: [{center_ne_m: "
      "[0, "
      "0], radius_m: 10}]}\n"
      "vehicles:\n"
      "  - {name: d, preset: quad_x, start: {position_ned_m: [0, 0, -0.2]}}\n";
  const Scene warm = LoadSceneFromString(text, "bench.yaml");
  for (auto _ : state) {
    Scene s = LoadSceneFromString(text, "bench.yaml");
    benchmark::DoNotOptimize(s.static_scene->objects.data());
  }
  state.SetItemsProcessed(state.iterations() *
                          static_cast<std::int64_t>(warm.static_scene->objects.size()));
  ReportScene(state, *warm.static_scene);
}
BENCHMARK(BM_LoadForestScene10k)->Unit(benchmark::kMillisecond);

// Objects listed one by one in the file (no `repeat`): loading must stay linear in the list. The
// time per object is the same at every size when it is.
void BM_LoadObjectsListedOneByOne(benchmark::State& state) {
  const auto objects = static_cast<int>(state.range(0));
  std::string text = "scene: {name: bench}\nobjects:\n";
  for (int i = 0; i < objects; ++i) {
    text += "  - {primitive: box, position_ned_m: [" + std::to_string(i % 200) + ", " +
            std::to_string(i / 200) + ", -1]}\n";
  }
  const Scene warm = LoadSceneFromString(text, "bench.yaml");
  for (auto _ : state) {
    Scene s = LoadSceneFromString(text, "bench.yaml");
    benchmark::DoNotOptimize(s.static_scene->objects.data());
  }
  state.SetItemsProcessed(state.iterations() * objects);
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(text.size()));
  ReportScene(state, *warm.static_scene);
}
BENCHMARK(BM_LoadObjectsListedOneByOne)
    ->Arg(10'000)
    ->Arg(20'000)
    ->Arg(40'000)
    ->Arg(60'000)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace airis::scenes
