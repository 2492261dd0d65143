#pragma once

// A vehicle as a loaded scene describes it (no yaml-cpp here). The kinds are registered in
// vehicle_kinds.cc.

#include <memory>
#include <string>
#include <string_view>

#include "engine/physics/rigid_body.h"
#include "engine/world/vehicle.h"

namespace airis::scenes {

/// A vehicle's kind and config (its preset with the scene's overrides), ready to build.
class VehicleSpec {
 public:
  virtual ~VehicleSpec() = default;
  /// The file key of its kind ("multirotor").
  virtual std::string_view kind() const = 0;
  /// The rigid body (mass, inertia, box, drag, material): for start checks and summaries.
  virtual engine::RigidBodyConfig CalcRigidBodyConfig() const = 0;
  /// The engine vehicle named `name`. Throws InvalidField on a config its class refuses.
  virtual std::unique_ptr<engine::Vehicle> Build(const std::string& name) const = 0;
  /// The fastest a mission may ask it to fly (m/s): its controller's limit.
  virtual double CalcMaxSpeed_m_s() const = 0;
};

/// The VehicleSpec of config `Config` built as `VehicleT(name, config)`.
template <class Config, class VehicleT>
class VehicleSpecOf final : public VehicleSpec {
 public:
  VehicleSpecOf(std::string_view kind, Config config) : kind_(kind), config_(std::move(config)) {}
  const Config& config() const { return config_; }
  std::string_view kind() const override { return kind_; }
  engine::RigidBodyConfig CalcRigidBodyConfig() const override {
    return config_.CalcRigidBodyConfig();
  }
  std::unique_ptr<engine::Vehicle> Build(const std::string& name) const override {
    return std::make_unique<VehicleT>(name, config_);
  }
  double CalcMaxSpeed_m_s() const override { return config_.CalcMaxSpeed_m_s(); }

 private:
  std::string_view kind_;
  Config config_;
};

/// The typed config of `spec` when it is of config type Config, else null.
template <class Config, class VehicleT>
const Config* VehicleConfigOf(const VehicleSpec& spec) {
  const auto* typed = dynamic_cast<const VehicleSpecOf<Config, VehicleT>*>(&spec);
  return typed ? &typed->config() : nullptr;
}

}  // namespace airis::scenes
