#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>

namespace airis::engine {
class RayCaster;
class Simulation;
}  // namespace airis::engine

namespace airis::tools {

/// What `airis bench sensors` measures.
struct SensorBenchOptions {
  int city_boxes = 10000;         ///< boxes in the lidar scene (one shared mesh, instanced)
  double city_extent_m = 1000.0;  ///< side of the square they are scattered over
  int lidar_scans = 40;           ///< VLP-16 scans timed (10,000 rays each)
  double sensor_seconds = 100.0;  ///< simulated seconds of the reference quad's sensors at 1 kHz
};

/// Simulation ticks per wall-clock second of the reference quad-x hovering in an empty world,
/// without sensors and with IMU (1 kHz), barometer and magnetometer (50 Hz) and GPS (10 Hz).
struct QuadTickRates {
  double bare_ticks_per_s = 0.0;
  double with_sensors_ticks_per_s = 0.0;
};
/// The reference quad-x hovering open loop 50 m up in an empty world at 47.6 deg N (1 kHz
/// physics), with IMU (1 kHz), barometer and magnetometer (50 Hz) and GPS (10 Hz), all at their
/// defaults, when `with_sensors`, else none.
std::unique_ptr<engine::Simulation> MakeReferenceQuadSimulation(bool with_sensors);
/// Measures QuadTickRates over about `seconds` of simulated time each (alternating rounds, best
/// kept).
QuadTickRates MeasureReferenceQuadTicks(double seconds = 20.0);

/// Runs the sensor benchmarks on the calling thread and returns their results, timed in that
/// thread's CPU time (so other processes on the machine do not inflate them; the caster build uses
/// Embree's worker threads and is wall clock):
/// - lidar_rays_per_s: rays per second one core casts through the Embree caster, VLP-16 scans from
/// random
///   poses 20-80 m up in a city of `city_boxes` boxes over `city_extent_m`; lidar_hit_fraction: the
///   share that returned; caster_build_s: time to build the city's Embree scene.
/// - imu_ns, barometer_ns, magnetometer_ns, gps_ns, rangefinder_ns: cost of one sample.
/// - reference_quad_sensors_ns_per_tick: IMU 1 kHz + barometer 50 Hz + magnetometer 50 Hz + GPS 10
/// Hz
///   driven through Sensor::Update on every 1 kHz tick, amortised per tick.
/// - ticks_per_s_bare, ticks_per_s_with_sensors, sensor_overhead_fraction:
/// MeasureReferenceQuadTicks over
///   `sensor_seconds`.
nlohmann::json RunSensorBenchmarks(const SensorBenchOptions& options = {});

/// What a lidar cast: rays per CPU second of the calling thread, the share that hit, points a scan.
struct LidarRate {
  double rays_per_s = 0.0;
  double hit_fraction = 0.0;
  std::size_t points_per_scan = 0;
};

/// Times `scans` scans (after two warm-up ones) of the default lidar (sensors::Lidar: a VLP-16)
/// against `caster`, each from a pose drawn in `area_ne` (north, east; m) at 20 to 80 m above
/// `ground_m(north, east)` (m, up), level, with a random heading.
LidarRate MeasureLidarRate(const engine::RayCaster& caster, const Eigen::AlignedBox2d& area_ne,
                           const std::function<double(double, double)>& ground_m, int scans);

}  // namespace airis::tools
