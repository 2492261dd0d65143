#include "scenes/vehicle_kinds.h"

#include "vehicles/multirotor/multirotor.h"

namespace airis::scenes {

std::span<const VehicleKind> VehicleKinds() {
  // A new kind is a folder in vehicles/ and one line here.
  static const VehicleKind kKinds[] = {
      VehicleKindOf<vehicles::MultirotorConfig, vehicles::Multirotor>(
          "multirotor", "rotors at the vertices of a box body, with the built-in controller",
          vehicles::MultirotorPresetFiles()),
  };
  return kKinds;
}

const VehicleKind* FindVehicleKind(std::string_view name) {
  for (const VehicleKind& k : VehicleKinds()) {
    if (k.name == name) return &k;
  }
  return nullptr;
}

const vehicles::PresetFile* FindPreset(const VehicleKind& kind, std::string_view name) {
  for (const vehicles::PresetFile& p : kind.presets) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

vehicles::MultirotorConfig LoadMultirotorPreset(std::string_view name) {
  const VehicleKind& kind = VehicleKinds()[0];
  const vehicles::PresetFile* preset = FindPreset(kind, name);
  if (!preset) {
    throw engine::ConfigError({}, "preset", "no multirotor preset '" + std::string(name) + "'");
  }
  vehicles::MultirotorConfig config;
  ReadPresetFile(*preset, config);
  return config;
}

}  // namespace airis::scenes
