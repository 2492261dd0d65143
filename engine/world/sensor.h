#pragma once

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/clock.h"
#include "engine/environment/environment.h"
#include "engine/physics/rigid_body_state.h"
#include "engine/world/log_column.h"
#include "engine/world/ray_caster.h"
#include "engine/world/sensor_samples.h"

namespace airis::engine {

class ImageSensor;
class World;

/// The truth a sensor may read when it samples: its vehicle after this tick's integration and
/// contacts.
struct SensorContext {
  TimeNs now_ns = 0;
  const RigidBodyState* state = nullptr;                  ///< the vehicle's body
  const RigidBodyAccelerations* accelerations = nullptr;  ///< over the last step, contacts included
  const Environment* environment = nullptr;
  const RayCaster* rays = nullptr;  ///< null when the world has no ray caster
  /// The world with every vehicle at this tick (cameras draw the other vehicles' bodies); null
  /// where a sensor samples without one (unit tests).
  const World* world = nullptr;
  std::size_t vehicle = 0;  ///< index of the sensor's own vehicle in `world`
  /// Changes whenever the vehicle's state or accelerations may have changed since the previous
  /// tick (World::motion_serial); two contexts with the same non-zero value describe the same
  /// state and accelerations bit for bit (a vehicle asleep), so a sensor may keep what it worked
  /// out from them. 0: not known (a context made outside a World): nothing may be kept.
  std::uint64_t motion_serial = 0;
};

/// A sensor mounted on a vehicle (DESIGN.md: sensors/ implements this; the engine knows no concrete
/// sensor). It samples at its own exact rate on the simulated clock and tells its listeners of each
/// new sample. Sample k of a sensor of rate r is due at k / r for k = 1, 2, ... (RateSchedule,
/// first event 1), taken at the first tick at or after that time and stamped with the tick's time:
/// a sensor reads the state a tick produced (DESIGN principle 3), and the initial state at t = 0 is
/// no tick's output (an IMU's accelerations over the last step do not exist before the first step),
/// so the first sample comes one period after the start and every interval is one period. Generic
/// consumers (telemetry log, dataset writer) read samples as rows of numbers named by columns();
/// sensors that produce images are ImageSensors (image() is not null) and give their frames there.
class Sensor {
 public:
  /// @param name unique within its vehicle, e.g. "imu"; @param rate_hz samples per simulated
  /// second.
  Sensor(std::string name, double rate_hz);
  virtual ~Sensor() = default;
  Sensor(const Sensor&) = delete;
  Sensor& operator=(const Sensor&) = delete;

  /// Called every tick after physics: samples when the schedule says so and notifies the
  /// listeners. Returns true when a sample was taken.
  bool Update(const SensorContext& context) {
    if (!SampleIfDue(context)) return false;
    NotifyListeners();
    return true;
  }
  /// Update without the listeners (SampleIfDue, then NotifyListeners when it sampled, is Update).
  /// Sensors of different vehicles may sample at the same time on different threads (each reads
  /// only its context and changes only itself); an image sensor renders, so only on the thread
  /// that owns the GL context. The Simulation samples every vehicle's sensors on its threads, then
  /// notifies on its own thread, in order. Inline when nothing is due (most ticks of a sensor
  /// slower than the physics).
  bool SampleIfDue(const SensorContext& context) {
    return schedule_.IsDue(context.now_ns) && SampleDue(context);
  }
  /// Calls every listener with this sensor (after a sample).
  void NotifyListeners() const;
  /// True when a listener was added (NotifyListeners would call someone).
  bool has_listeners() const { return !listeners_.empty(); }

  /// Column names with units of the sample row, e.g. {"angular_velocity_sensor_x_rad_s", ...};
  /// constant over the run.
  virtual std::span<const std::string> columns() const = 0;
  /// The last sample as numbers in the order of columns(); requires out.size() == columns().size().
  virtual void CopyLatestRow(std::span<double> out) const = 0;
  /// What column `column` holds beyond the unit and frame its name gives (docs/dataset-format.md's
  /// column tables are made from it); empty for a column described with the one before it (the y
  /// and z of a vector after its x).
  virtual std::string_view column_doc(std::size_t column) const {
    (void)column;
    return {};
  }
  /// How logs store a column: float32 unless the sensor says otherwise (a GPS latitude needs
  /// float64, its fix type is a whole number).
  virtual LogType column_type(std::size_t column) const {
    (void)column;
    return LogType::kFloat32;
  }

  /// The last sample of a standard kind (engine/world/sensor_samples.h), or null when the sensor
  /// is not of that kind: what the PX4 bridge and the Python API read.
  virtual const InertialSample* inertial() const { return nullptr; }
  virtual const BarometricSample* barometric() const { return nullptr; }
  virtual const MagneticSample* magnetic() const { return nullptr; }
  virtual const GnssSample* gnss() const { return nullptr; }
  virtual const RangeSample* range() const { return nullptr; }
  /// The last scan of a scanning range sensor (a lidar), or null when the sensor is not one. Its
  /// pattern is set from construction on, its points from the first scan.
  virtual const PointCloudSample* point_cloud() const { return nullptr; }
  /// Rotation of the sensor frame into the body frame (its mount); identity when it has none.
  virtual Quat q_BS() const { return Quat::Identity(); }
  /// Age of the state a sample describes when it is delivered (s): an estimator's delay setting.
  virtual double latency_s() const { return 0.0; }

  /// This sensor as an image sensor, or null when it produces no images.
  virtual ImageSensor* image() { return nullptr; }
  virtual const ImageSensor* image() const { return nullptr; }

  /// Calls `listener` after every new sample (in the simulation thread; keep it cheap, do not keep
  /// the ref).
  void AddListener(std::function<void(const Sensor&)> listener) {
    listeners_.push_back(std::move(listener));
  }

  /// A disabled sensor keeps its schedule (its rate stays exact) but takes no samples: cameras are
  /// switched off while nothing records them. Enabled by default.
  void set_enabled(bool enabled) { enabled_ = enabled; }
  bool enabled() const { return enabled_; }

  /// When set, a due sample of an enabled sensor is taken only if `gate(now_ns)` returns true; the
  /// schedule advances either way. A dataset shard uses it to skip the camera frames other shards
  /// render.
  void set_sample_gate(std::function<bool(TimeNs)> gate) { gate_ = std::move(gate); }

  const std::string& name() const { return name_; }
  const RateSchedule& schedule() const { return schedule_; }
  /// Simulated time of the last sample (-1 before the first).
  TimeNs last_sample_ns() const { return last_sample_ns_; }

 protected:
  /// Takes one sample from `context` (called only when due).
  virtual void Sample(const SensorContext& context) = 0;

 private:
  // SampleIfDue once the schedule says a sample is due.
  bool SampleDue(const SensorContext& context);

  std::string name_;
  RateSchedule schedule_;
  TimeNs last_sample_ns_ = -1;
  bool enabled_ = true;
  std::function<bool(TimeNs)> gate_;
  std::vector<std::function<void(const Sensor&)>> listeners_;
};

}  // namespace airis::engine
