#include "scenes/scene_schema.h"

#include "scenes/scene_file.h"
#include "scenes/schema.h"
#include "scenes/sensor_kinds.h"
#include "scenes/vehicle_kinds.h"

namespace airis::scenes {

namespace {

template <class T>
SchemaSection Section(const std::string& title, const std::string& prefix) {
  const std::vector<FieldDoc> fields = ListFields<T>();
  return {title, FieldTableMarkdown(fields, prefix)};
}

}  // namespace

std::vector<SchemaSection> SceneSchemaSections() {
  std::vector<SchemaSection> out;
  // Top level: only the first-level keys; each block has its own table below.
  std::vector<FieldDoc> top;
  for (const FieldDoc& f : ListFields<SceneFileConfig>()) {
    if (f.key.find_first_of(".[") == std::string::npos) top.push_back(f);
  }
  out.push_back({"top level", FieldTableMarkdown(top)});
  out.push_back(Section<SceneSettingsConfig>("scene", "scene."));
  out.push_back(Section<GroundConfig>("ground", "ground."));
  out.push_back(Section<TerrainConfig>("terrain", "terrain."));
  out.push_back(Section<engine::PhysicsConfig>("physics", "physics."));
  out.push_back(Section<ClassConfig>("classes[]", "classes[]."));
  out.push_back(Section<ObjectConfig>("objects[]", "objects[]."));
  out.push_back(Section<CityConfig>("generators[].city", "generators[].city."));
  out.push_back(Section<ForestConfig>("generators[].forest", "generators[].forest."));
  out.push_back(Section<VehicleEntryConfig>("vehicles[]", "vehicles[]."));
  // Each registered kind's own keys: the airframe of a vehicle kind (its presets and overrides),
  // the config of a sensor kind.
  for (const VehicleKind& k : VehicleKinds()) {
    const std::string title = "vehicles[].overrides (" + std::string(k.name) + ")";
    out.push_back({title, FieldTableMarkdown(k.fields(), "vehicles[].overrides.")});
  }
  for (const SensorKind& k : SensorKinds()) {
    const std::string prefix = "vehicles[].sensors[]." + std::string(k.name) + ".";
    out.push_back(
        {"vehicles[].sensors[]." + std::string(k.name), FieldTableMarkdown(k.fields(), prefix)});
  }
  return out;
}

}  // namespace airis::scenes
