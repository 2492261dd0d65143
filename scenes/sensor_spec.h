#pragma once

// A sensor as a loaded scene describes it (no yaml-cpp here, so that any layer above scenes/ can
// include it). The kinds are registered in sensor_kinds.cc.

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "engine/core/random.h"
#include "engine/render/render_scene.h"
#include "engine/world/sensor.h"

namespace airis::scenes {

/// What building a sensor may use.
struct SensorBuildContext {
  engine::RandomStream stream;  ///< the sensor's own stream (vehicles/VEHICLE/SENSOR)
  /// The GPU copy of the static scene that every camera shares, made on first use (so scenes
  /// without cameras need no EGL display).
  std::function<std::shared_ptr<const engine::RenderScene>()> render_scene;
};

/// A sensor as a scene describes it: its kind and config, ready to build.
class SensorSpec {
 public:
  virtual ~SensorSpec() = default;
  /// The file key of its kind ("imu", ...).
  virtual std::string_view kind() const = 0;
  /// Throws InvalidField when the sensor cannot run with physics ticking at `physics_rate_hz`.
  virtual void ValidateForPhysicsRate(double physics_rate_hz) const = 0;
  /// Throws InvalidField when the sensor cannot run in a scene of `instances` objects and vehicle
  /// bodies (a camera whose instance images hold fewer ids).
  virtual void ValidateForInstances(std::size_t instances) const = 0;
  /// The engine sensor named `name`. Throws InvalidField on a config its class refuses.
  virtual std::unique_ptr<engine::Sensor> Build(const std::string& name,
                                                SensorBuildContext& context) const = 0;
  /// True when Build needs the render scene (a GL context): cameras.
  virtual bool renders() const = 0;
  /// True when the sensor casts rays at the static scene (rangefinder, lidar).
  virtual bool casts_rays() const = 0;
  /// The names of the image streams a sensor named `name` of this kind makes (datasets write a
  /// folder per stream); empty for sensors without images.
  virtual std::vector<std::string> ImageStreamNames(const std::string& name) const = 0;
};

/// The SensorSpec of config `Config` built as `SensorT`: constructed from (name, config, stream),
/// or, for sensors that render, from (name, config, render scene, stream).
template <class Config, class SensorT>
class SensorSpecOf final : public SensorSpec {
 public:
  SensorSpecOf(std::string_view kind, Config config) : kind_(kind), config_(std::move(config)) {}
  const Config& config() const { return config_; }
  std::string_view kind() const override { return kind_; }
  void ValidateForPhysicsRate(double physics_rate_hz) const override {
    if constexpr (requires { config_.ValidateForPhysicsRate(1.0); }) {
      config_.ValidateForPhysicsRate(physics_rate_hz);
    }
  }
  void ValidateForInstances(std::size_t instances) const override {
    if constexpr (requires { config_.ValidateForInstances(std::size_t{1}); }) {
      config_.ValidateForInstances(instances);
    }
  }
  std::unique_ptr<engine::Sensor> Build(const std::string& name,
                                        SensorBuildContext& context) const override {
    if constexpr (kRenders) {
      return std::make_unique<SensorT>(name, config_, context.render_scene(), context.stream);
    } else {
      return std::make_unique<SensorT>(name, config_, context.stream);
    }
  }
  bool renders() const override { return kRenders; }
  bool casts_rays() const override {
    if constexpr (requires { SensorT::kCastsRays; }) {
      return SensorT::kCastsRays;
    } else {
      return false;
    }
  }
  std::vector<std::string> ImageStreamNames(const std::string& name) const override {
    if constexpr (requires { SensorT::StreamNames(name); }) {
      return SensorT::StreamNames(name);
    } else {
      return {};
    }
  }

 private:
  static constexpr bool kRenders =
      !std::is_constructible_v<SensorT, std::string, const Config&, engine::RandomStream>;
  std::string_view kind_;
  Config config_;
};

/// A sensor to mount on a vehicle.
struct SensorDescription {
  std::string name;  ///< unique on the vehicle
  std::shared_ptr<const SensorSpec> spec;
};

/// The typed config of `spec` when it is of config type Config, else null.
template <class Config, class SensorT>
const Config* SensorConfigOf(const SensorSpec& spec) {
  const auto* typed = dynamic_cast<const SensorSpecOf<Config, SensorT>*>(&spec);
  return typed ? &typed->config() : nullptr;
}

}  // namespace airis::scenes
