// Per-sample cost of each sensor, the reference quad's sensors per 1 kHz tick, and lidar rays per
// second through Embree in a 10,000-box city (1 km x 1 km).

#include <benchmark/benchmark.h>

#include <memory>

#include "engine/world/embree_ray_caster.h"
#include "engine/world/simulation.h"
#include "sensors/barometer.h"
#include "sensors/gps.h"
#include "sensors/imu.h"
#include "sensors/lidar.h"
#include "sensors/magnetometer.h"
#include "sensors/rangefinder.h"
#include "tests/sensors/sensor_test_util.h"
#include "tools/bench/bench_sensors.h"

namespace airis::sensors {
namespace {

using engine::Vec3;

struct Rig {
  engine::Environment environment = testing::MakeEnvironment();
  testing::Truth truth;
  Rig() {
    truth.state.p_W = Vec3(10, 20, -30);
    truth.state.v_W = Vec3(3, 1, 0);
    truth.state.w_B = Vec3(0.1, -0.2, 0.05);
    truth.state.q_WB = engine::QuatFromEuler({0.05, -0.1, 0.7});
    truth.accelerations = testing::AtRest(environment, truth.state.p_W);
  }
};

const engine::EmbreeRayCaster& City() {
  static const auto* caster =
      new engine::EmbreeRayCaster(testing::MakeCityOfBoxes(10000, 1000.0, 2026));
  return *caster;
}

// Each Update at the sensor's own period, so every call samples.
template <class SensorT, class Config>
void RunSampled(benchmark::State& state, const Config& config,
                const engine::RayCaster* rays = nullptr) {
  Rig rig;
  SensorT sensor("s", config, engine::RandomStream(1));
  const auto period = static_cast<engine::TimeNs>(1e9 / sensor.schedule().rate_hz());
  engine::TimeNs now = 0;
  for (int i = 0; i < 100; ++i, now += period)
    sensor.Update(rig.truth.At(now, rig.environment, rays));
  for (auto _ : state) {
    benchmark::DoNotOptimize(sensor.Update(rig.truth.At(now, rig.environment, rays)));
    now += period;
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_ImuSample(benchmark::State& state) { RunSampled<Imu>(state, ImuConfig{}); }
void BM_BarometerSample(benchmark::State& state) {
  RunSampled<Barometer>(state, BarometerConfig{});
}
void BM_MagnetometerSampleWmm(benchmark::State& state) {
  RunSampled<Magnetometer>(state, MagnetometerConfig{});
}
void BM_MagnetometerSampleWmmEveryTime(benchmark::State& state) {
  MagnetometerConfig config;
  config.field_update_distance_m = 0.0;  // evaluate WMM2025 on every sample
  RunSampled<Magnetometer>(state, config);
}
void BM_GpsSample(benchmark::State& state) { RunSampled<Gps>(state, GpsConfig{}); }
void BM_RangefinderSampleCity(benchmark::State& state) {
  RunSampled<Rangefinder>(state, RangefinderConfig{}, &City());
}

// IMU 1 kHz + barometer 50 Hz + magnetometer 50 Hz + GPS 10 Hz through Sensor::Update on every 1
// kHz tick; one iteration = one tick, so the time per iteration is the amortised cost the sensors
// add to a tick.
void BM_ReferenceQuadSensorsPerTick(benchmark::State& state) {
  Rig rig;
  Imu imu("imu", {}, engine::RandomStream(1));
  Barometer baro("baro", {}, engine::RandomStream(2));
  Magnetometer mag("mag", {}, engine::RandomStream(3));
  Gps gps("gps", {}, engine::RandomStream(4));
  engine::Sensor* sensors[] = {&imu, &baro, &mag, &gps};
  std::int64_t tick = 0;
  for (; tick < 1000; ++tick) {
    for (engine::Sensor* s : sensors) s->Update(rig.truth.At(tick * 1'000'000, rig.environment));
  }
  for (auto _ : state) {
    const engine::SensorContext context = rig.truth.At(tick * 1'000'000, rig.environment);
    for (engine::Sensor* s : sensors) s->Update(context);
    ++tick;
  }
  state.SetItemsProcessed(state.iterations());
}

// One VLP-16 scan (10,000 rays) from changing poses 20-80 m up over the city; items = rays.
void BM_LidarScanCity(benchmark::State& state) {
  Rig rig;
  const engine::EmbreeRayCaster& caster = City();
  Lidar lidar("lidar", {}, engine::RandomStream(1));
  engine::RandomStream poses(3);
  engine::TimeNs now = 0;
  std::size_t rays = 0;
  std::size_t hits = 0;
  const auto move = [&] {
    rig.truth.state.p_W =
        Vec3(poses.Uniform(-400, 400), poses.Uniform(-400, 400), -poses.Uniform(20, 80));
    now += 100'000'000;
  };
  move();
  lidar.Update(rig.truth.At(now, rig.environment, &caster));
  for (auto _ : state) {
    state.PauseTiming();
    move();
    state.ResumeTiming();
    lidar.Update(rig.truth.At(now, rig.environment, &caster));
    rays += lidar.latest().points.size();
    hits += lidar.latest().hit_count;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(rays));
  state.counters["hit_fraction"] = static_cast<double>(hits) / static_cast<double>(rays);
}

// Raw caster throughput on 4096 incoherent rays (random origins and directions) per iteration.
void BM_EmbreeIncoherentRaysCity(benchmark::State& state) {
  const engine::EmbreeRayCaster& caster = City();
  engine::RandomStream random(9);
  std::vector<engine::Ray> rays(4096);
  for (engine::Ray& r : rays) {
    r.origin_W = Vec3(random.Uniform(-500, 500), random.Uniform(-500, 500), -random.Uniform(2, 80));
    r.direction_W =
        Vec3(random.Uniform(-1, 1), random.Uniform(-1, 1), random.Uniform(-0.5, 0.5)).normalized();
    r.max_range_m = 100.0f;
  }
  std::vector<engine::RayHit> hits(rays.size());
  caster.Cast(rays, hits);
  for (auto _ : state) {
    caster.Cast(rays, hits);
    benchmark::DoNotOptimize(hits.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(rays.size()));
}

// Whole simulation ticks of the reference quad hovering in an empty world, without and with its
// four sensors; the ratio is what the sensors add to a tick. Reported as ticks per second via
// items.
void BM_QuadTickRates(benchmark::State& state) {
  tools::QuadTickRates rates;
  for (auto _ : state) rates = tools::MeasureReferenceQuadTicks(200.0);
  state.counters["bare_ticks_per_s"] = rates.bare_ticks_per_s;
  state.counters["with_sensors_ticks_per_s"] = rates.with_sensors_ticks_per_s;
  state.counters["bare_ns_per_tick"] = 1e9 / rates.bare_ticks_per_s;
  state.counters["with_sensors_ns_per_tick"] = 1e9 / rates.with_sensors_ticks_per_s;
}

// One tick of the reference quad without (argument 0) and with (1) its four sensors, for
// instruction counts under callgrind (docs/performance.md has the command): the instructions of
// Simulation::Step called from here over its calls.
void BM_ReferenceQuadTick(benchmark::State& state) {
  const std::unique_ptr<engine::Simulation> simulation =
      tools::MakeReferenceQuadSimulation(state.range(0) != 0);
  simulation->RunFor(5.0);  // past the GPS's first fix (4.0 s): the steady state
  for (auto _ : state) simulation->Step();
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK(BM_ImuSample);
BENCHMARK(BM_BarometerSample);
BENCHMARK(BM_MagnetometerSampleWmm);
BENCHMARK(BM_MagnetometerSampleWmmEveryTime);
BENCHMARK(BM_GpsSample);
BENCHMARK(BM_RangefinderSampleCity);
BENCHMARK(BM_ReferenceQuadSensorsPerTick);
BENCHMARK(BM_LidarScanCity)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EmbreeIncoherentRaysCity)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ReferenceQuadTick)->Arg(0)->Arg(1);
BENCHMARK(BM_QuadTickRates)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
}  // namespace airis::sensors
