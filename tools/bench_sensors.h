#pragma once

#include <nlohmann/json.hpp>

namespace airis::tools {

/// What `airis bench sensors` measures.
struct SensorBenchOptions {
  int city_boxes = 10000;         ///< boxes in the lidar scene (one shared mesh, instanced)
  double city_extent_m = 1000.0;  ///< side of the square they are scattered over
  int lidar_scans = 40;           ///< VLP-16 scans timed (10,000 rays each)
  double sensor_seconds = 20.0;   ///< simulated seconds of the reference quad's sensors at 1 kHz
};

/// Runs the sensor benchmarks on the calling thread and returns their results (wall-clock, this
/// machine):
///   lidar_rays_per_s        rays per second cast by one core through the Embree caster, VLP-16
///   scans from
///                           random poses 20-80 m up in a city of `city_boxes` boxes over
///                           `city_extent_m`
///   lidar_hit_fraction      fraction of those rays that returned
///   caster_build_s          time to build the Embree scene of the city
///   imu_ns, barometer_ns, magnetometer_ns, gps_ns, rangefinder_ns   cost of one Sample (ns)
///   reference_quad_sensors_ns_per_tick   IMU 1 kHz + barometer 50 Hz + magnetometer 50 Hz + GPS 10
///   Hz,
///                           driven through Sensor::Update on every 1 kHz tick, amortised per tick
///   ticks_per_s_bare / ticks_per_s_with_sensors   null with a note: they need the World (for the
///   lead)
nlohmann::json RunSensorBenchmarks(const SensorBenchOptions& options = {});

}  // namespace airis::tools
