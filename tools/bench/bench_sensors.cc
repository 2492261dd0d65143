#include "tools/bench/bench_sensors.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <memory>
#include <vector>

#include "engine/core/random.h"
#include "engine/environment/environment.h"
#include "engine/world/embree_ray_caster.h"
#include "engine/world/simulation.h"
#include "engine/world/world.h"
#include "scenes/vehicle_kinds.h"
#include "sensors/barometer.h"
#include "sensors/gps.h"
#include "sensors/imu.h"
#include "sensors/lidar.h"
#include "sensors/magnetometer.h"
#include "sensors/rangefinder.h"
#include "vehicles/multirotor/multirotor.h"

namespace airis::tools {

namespace {

using engine::Vec3;
using Clock = std::chrono::steady_clock;

// CPU time of the calling thread (s): unaffected by other processes sharing the machine.
double ThreadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The sensors' world: the default environment at the paper's site (47.64 N, 122.14 W, 122 m).
engine::Environment MakeSensorBenchEnvironment(const engine::RandomStreams& streams) {
  return engine::Environment(engine::EnvironmentConfig{},
                             {engine::DegToRad(47.641468), engine::DegToRad(-122.140165), 122.0},
                             streams.Stream("env"));
}

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Boxes 2-20 m wide and 5-60 m tall with random yaw, standing on z = 0, all instances of one unit
// box.
engine::StaticScene MakeCity(int count, double extent_m) {
  engine::StaticScene scene;
  engine::TriangleMesh box;
  box.name = "primitive:box";
  box.primitive = engine::Primitive::kBox;
  for (int i = 0; i < 8; ++i) {
    box.positions.emplace_back((i & 1) ? 0.5f : -0.5f, (i & 2) ? 0.5f : -0.5f,
                               (i & 4) ? 0.5f : -0.5f);
    box.normals.push_back(box.positions.back().normalized());
    box.bounds.extend(box.positions.back());
  }
  // Two triangles per face, counter-clockwise seen from outside.
  box.indices = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  scene.meshes.push_back(box);
  scene.materials.emplace_back();
  engine::Model model;
  model.name = "box";
  model.parts.emplace_back();
  model.bounds = box.bounds;
  scene.models.push_back(model);
  engine::RandomStream random(2026);
  for (int i = 0; i < count; ++i) {
    const Vec3 size(random.Uniform(2, 20), random.Uniform(2, 20), random.Uniform(5, 60));
    const Vec3 center(random.Uniform(-0.5, 0.5) * extent_m, random.Uniform(-0.5, 0.5) * extent_m,
                      -0.5 * size.z());
    engine::StaticObject o;
    o.T_WO = Eigen::Translation3d(center) *
             Eigen::AngleAxisd(random.Uniform(-3.14159, 3.14159), Vec3::UnitZ()) *
             Eigen::Scaling(size);
    o.class_id = static_cast<std::uint8_t>(1 + i % 4);
    o.instance_id = static_cast<std::uint32_t>(1 + i % engine::kMaxInstances);
    scene.objects.push_back(o);
  }
  return scene;
}

// Nanoseconds per Sample of `sensor`, driven at its own rate so every Update samples.
template <class SensorT>
double TimeSamples(SensorT& sensor, engine::SensorContext context, int samples) {
  const engine::TimeNs period = static_cast<engine::TimeNs>(1e9 / sensor.schedule().rate_hz());
  for (int i = 0; i < samples / 10; ++i) {  // warm-up
    context.now_ns += period;
    sensor.Update(context);
  }
  const double start_s = ThreadCpuSeconds();
  for (int i = 0; i < samples; ++i) {
    context.now_ns += period;
    sensor.Update(context);
  }
  return (ThreadCpuSeconds() - start_s) * 1e9 / samples;
}

}  // namespace

std::unique_ptr<engine::Simulation> MakeReferenceQuadSimulation(bool with_sensors) {
  const engine::RandomStreams streams(1);
  auto world = std::make_unique<engine::World>(
      std::make_shared<const engine::StaticScene>(),
      engine::Environment(engine::EnvironmentConfig{},
                          {engine::DegToRad(47.641468), engine::DegToRad(-122.140165), 122.0},
                          streams.Stream("environment")));
  auto quad =
      std::make_unique<vehicles::Multirotor>("quad", scenes::LoadMultirotorPreset("quad_x"));
  quad->state().p_W = Vec3(0, 0, -50);
  // Hover for the air and gravity at 50 m, so the open-loop quad stays near its start.
  const double rho = world->environment().CalcAir(quad->state().p_W).density_kg_m3;
  const double g = world->environment().CalcGravity_m_s2(quad->state().p_W);
  const std::vector<double> hover(static_cast<std::size_t>(quad->actuator_count()),
                                  quad->CalcHoverCommand(rho, g));
  quad->ResetActuators(hover);
  const std::size_t index = world->AddVehicle(std::move(quad));
  if (with_sensors) {
    world->AddSensor(index, std::make_unique<sensors::Imu>("imu", sensors::ImuConfig{},
                                                           streams.Stream("quad/imu")));
    world->AddSensor(index,
                     std::make_unique<sensors::Barometer>("barometer", sensors::BarometerConfig{},
                                                          streams.Stream("quad/baro")));
    world->AddSensor(
        index, std::make_unique<sensors::Magnetometer>(
                   "magnetometer", sensors::MagnetometerConfig{}, streams.Stream("quad/mag")));
    world->AddSensor(index, std::make_unique<sensors::Gps>("gps", sensors::GpsConfig{},
                                                           streams.Stream("quad/gps")));
  }
  return std::make_unique<engine::Simulation>(std::move(world));
}

QuadTickRates MeasureReferenceQuadTicks(double seconds) {
  // Alternate short rounds of the two and keep each one's best, timed in this thread's CPU time so
  // that other processes on the machine do not count; transient slowdowns are discarded.
  auto bare = MakeReferenceQuadSimulation(false);
  auto with_sensors = MakeReferenceQuadSimulation(true);
  bare->RunFor(1.0);  // warm-up
  with_sensors->RunFor(1.0);
  QuadTickRates rates;
  const int rounds = 10;
  const auto ticks_per_round = static_cast<std::int64_t>(seconds * 1000.0 / rounds);
  for (int round = 0; round < rounds; ++round) {
    for (auto* sim : {bare.get(), with_sensors.get()}) {
      const double start_s = ThreadCpuSeconds();
      for (std::int64_t k = 0; k < ticks_per_round; ++k) sim->Step();
      const double rate = static_cast<double>(ticks_per_round) / (ThreadCpuSeconds() - start_s);
      double& best = sim == bare.get() ? rates.bare_ticks_per_s : rates.with_sensors_ticks_per_s;
      best = std::max(best, rate);
    }
  }
  return rates;
}

LidarRate MeasureLidarRate(const engine::RayCaster& caster, const Eigen::AlignedBox2d& area_ne,
                           const std::function<double(double, double)>& ground_m, int scans) {
  const engine::RandomStreams streams(1);
  const engine::Environment environment = MakeSensorBenchEnvironment(streams);
  engine::RigidBodyState state;
  state.v_W = Vec3(3, 1, 0);
  state.w_B = Vec3(0.1, -0.2, 0.05);
  engine::RigidBodyAccelerations accelerations;
  accelerations.gravity_W = Vec3(0, 0, environment.CalcGravity_m_s2(Vec3(0, 0, -30)));
  engine::SensorContext context;
  context.state = &state;
  context.accelerations = &accelerations;
  context.environment = &environment;
  context.rays = &caster;
  sensors::Lidar lidar("lidar", {}, streams.Stream("lidar"));
  engine::RandomStream poses(3);
  const auto period_ns = static_cast<engine::TimeNs>(1e9 / lidar.schedule().rate_hz());
  double cast_s = 0.0;
  std::size_t rays = 0;
  std::size_t hits = 0;
  for (int scan = -2; scan < scans; ++scan) {  // two warm-up scans
    const double north = poses.Uniform(area_ne.min().x(), area_ne.max().x());
    const double east = poses.Uniform(area_ne.min().y(), area_ne.max().y());
    state.p_W = Vec3(north, east, -ground_m(north, east) - poses.Uniform(20, 80));
    state.q_WB = engine::QuatFromEuler({0.0, 0.0, poses.Uniform(-3.14, 3.14)});
    context.now_ns += period_ns;
    const double scan_start_s = ThreadCpuSeconds();
    lidar.Update(context);
    if (scan < 0) continue;
    cast_s += ThreadCpuSeconds() - scan_start_s;
    rays += lidar.latest().points.size();
    hits += lidar.latest().hit_count;
  }
  return {static_cast<double>(rays) / cast_s,
          static_cast<double>(hits) / static_cast<double>(std::max<std::size_t>(rays, 1)),
          lidar.latest().points.size()};
}

nlohmann::json RunSensorBenchmarks(const SensorBenchOptions& options) {
  nlohmann::json out;
  const engine::RandomStreams streams(1);
  const engine::Environment environment = MakeSensorBenchEnvironment(streams);
  engine::RigidBodyState state;
  state.p_W = Vec3(0, 0, -30);
  state.v_W = Vec3(3, 1, 0);
  state.w_B = Vec3(0.1, -0.2, 0.05);
  engine::RigidBodyAccelerations accelerations;
  accelerations.gravity_W = Vec3(0, 0, environment.CalcGravity_m_s2(state.p_W));
  engine::SensorContext context;
  context.state = &state;
  context.accelerations = &accelerations;
  context.environment = &environment;

  // Lidar rays in the city.
  const auto start = Clock::now();
  const engine::EmbreeRayCaster caster(MakeCity(options.city_boxes, options.city_extent_m));
  out["caster_build_s"] = SecondsSince(start);
  out["city_boxes"] = options.city_boxes;
  out["city_extent_m"] = options.city_extent_m;
  const LidarRate lidar = MeasureLidarRate(
      caster, Eigen::AlignedBox2d(Eigen::Vector2d(-400, -400), Eigen::Vector2d(400, 400)),
      [](double, double) { return 0.0; }, options.lidar_scans);
  out["lidar_rays_per_s"] = lidar.rays_per_s;
  out["lidar_hit_fraction"] = lidar.hit_fraction;
  out["lidar_points_per_scan"] = lidar.points_per_scan;

  context.rays = &caster;
  sensors::Rangefinder rangefinder("rangefinder", {}, streams.Stream("rangefinder"));
  out["rangefinder_ns"] = TimeSamples(rangefinder, context, 20000);
  context.rays = nullptr;

  sensors::Imu imu("imu", {}, streams.Stream("imu"));
  sensors::Barometer barometer("barometer", {}, streams.Stream("barometer"));
  sensors::Magnetometer magnetometer("magnetometer", {}, streams.Stream("magnetometer"));
  sensors::Gps gps("gps", {}, streams.Stream("gps"));
  out["imu_ns"] = TimeSamples(imu, context, 200000);
  out["barometer_ns"] = TimeSamples(barometer, context, 20000);
  out["magnetometer_ns"] = TimeSamples(magnetometer, context, 20000);
  out["gps_ns"] = TimeSamples(gps, context, 20000);

  // The reference quad's four sensors on a 1 kHz tick, each at its own rate, through
  // Sensor::Update.
  {
    sensors::Imu q_imu("imu", {}, streams.Stream("quad/imu"));
    sensors::Barometer q_baro("barometer", {}, streams.Stream("quad/barometer"));
    sensors::Magnetometer q_mag("magnetometer", {}, streams.Stream("quad/magnetometer"));
    sensors::Gps q_gps("gps", {}, streams.Stream("quad/gps"));
    engine::Sensor* all[] = {&q_imu, &q_baro, &q_mag, &q_gps};
    const auto ticks = static_cast<std::int64_t>(options.sensor_seconds * 1000.0);
    for (std::int64_t k = 0; k < 1000; ++k) {  // warm-up second
      context.now_ns = k * 1'000'000;
      for (engine::Sensor* s : all) s->Update(context);
    }
    const double start_s = ThreadCpuSeconds();
    for (std::int64_t k = 1000; k < 1000 + ticks; ++k) {
      context.now_ns = k * 1'000'000;
      state.p_W.x() += 1e-3;  // keep the truth changing so nothing is cached by accident
      for (engine::Sensor* s : all) s->Update(context);
    }
    out["reference_quad_sensors_ns_per_tick"] =
        (ThreadCpuSeconds() - start_s) * 1e9 / static_cast<double>(ticks);
  }
  const QuadTickRates rates = MeasureReferenceQuadTicks(options.sensor_seconds);
  out["ticks_per_s_bare"] = rates.bare_ticks_per_s;
  out["ticks_per_s_with_sensors"] = rates.with_sensors_ticks_per_s;
  out["sensor_overhead_fraction"] = rates.bare_ticks_per_s / rates.with_sensors_ticks_per_s - 1.0;
  return out;
}

}  // namespace airis::tools
