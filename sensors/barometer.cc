#include "sensors/barometer.h"

#include "engine/core/config.h"
#include "engine/core/standard_normal.h"
#include "engine/environment/atmosphere.h"
#include "sensors/sensor_checks.h"

namespace airis::sensors {

namespace {
const std::string kColumns[] = {"pressure_pa", "temperature_k", "altitude_m"};
const std::string_view kColumnDocs[] = {
    "measured static pressure",
    "measured air temperature: the standard atmosphere's at the sensor, with the sensor's offset "
    "and noise",
    "pressure altitude: the standard atmosphere inverted at the measured pressure",
};
static_assert(std::size(kColumnDocs) == std::size(kColumns));
}  // namespace

void BarometerConfig::Validate() const {
  engine::RequireRate("rate_hz", rate_hz, engine::kMaxPhysicsRate_hz);
  ValidateNested("mount", mount);
  engine::RequireNonNegative("pressure_noise_pa", pressure_noise_pa);
  engine::RequireInRange("drift_sigma", drift_sigma, 0.0, 0.5);
  engine::RequirePositive("drift_correlation_s", drift_correlation_s);
  engine::RequireNonNegative("temperature_noise_k", temperature_noise_k);
  engine::RequireNonNegative("temperature_offset_k", temperature_offset_k);
}

void BarometerConfig::ValidateForPhysicsRate(double physics_rate_hz) const {
  Validate();
  RequireRateWithinPhysics("rate_hz", rate_hz, physics_rate_hz);
}

Barometer::Barometer(std::string name, const BarometerConfig& config, engine::RandomStream stream)
    : Sensor(std::move(name), (config.Validate(), config.rate_hz)),
      config_(config),
      stream_(stream),
      drift_step_(GaussMarkovStep::Make(config.drift_sigma, config.drift_correlation_s,
                                        1.0 / config.rate_hz)),
      temperature_stream_(stream.Fork("temperature")) {
  // The drift starts in its stationary distribution, so its statistics do not depend on the run's
  // length.
  drift_ = config.drift_sigma * engine::StandardNormal(stream_);
  temperature_offset_k_ = config.temperature_offset_k * engine::StandardNormal(temperature_stream_);
}

std::span<const std::string> Barometer::columns() const { return kColumns; }

std::string_view Barometer::column_doc(std::size_t column) const { return kColumnDocs[column]; }

void Barometer::CopyLatestRow(std::span<double> out) const {
  AIRIS_DEMAND(out.size() == std::size(kColumns));
  out[0] = latest_.pressure_pa;
  out[1] = latest_.temperature_k;
  out[2] = latest_.altitude_m;
}

void Barometer::Sample(const engine::SensorContext& context) {
  AIRIS_DEMAND(context.state != nullptr && context.environment != nullptr);
  if (context.motion_serial == 0 || context.motion_serial != air_motion_serial_) {
    const engine::RigidBodyState& s = *context.state;
    const engine::Vec3 p_WS = s.p_W + s.q_WB * config_.mount.position_m;
    air_ = context.environment->CalcAir(p_WS);
    air_motion_serial_ = context.motion_serial;
  }
  const engine::AtmosphereSample& air = air_;

  drift_ = drift_step_.Next(drift_, engine::StandardNormal(stream_));
  const double white_pa = config_.pressure_noise_pa * engine::StandardNormal(stream_);

  latest_.time_ns = context.now_ns;
  latest_.pressure_pa = air.pressure_pa * (1.0 + drift_) + white_pa;
  latest_.temperature_k = air.temperature_k + temperature_offset_k_ +
                          config_.temperature_noise_k * engine::StandardNormal(temperature_stream_);
  latest_.altitude_m = engine::ussa1976::CalcAltitudeFromPressure(latest_.pressure_pa);
}

}  // namespace airis::sensors
