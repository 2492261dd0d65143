#include "tools/jobs/terrain_export.h"

#include <cstdio>

#include "engine/core/config.h"
#include "engine/core/error.h"
#include "scenes/geotiff_export.h"
#include "tools/jobs/version.h"

namespace airis::tools {

TerrainExport ExportTerrain(const SceneSource& source, double pixel_m, const std::string& date,
                            const std::string& out) {
  const scenes::Scene scene = LoadSceneSource(source);
  const engine::Heightfield* field = scene.static_scene->terrain.heightfield.get();
  if (field == nullptr) {
    throw engine::ConfigError({scene.path, 0, 0}, "terrain",
                              "the scene has no `terrain` block to export");
  }
  TerrainExport result;
  result.path = out;
  result.pixel_m = pixel_m > 0.0 ? pixel_m : field->spacing_m();
  result.lowest_m = field->min_height_m();
  result.highest_m = field->max_height_m();
  char origin[96];
  std::snprintf(origin, sizeof origin, "%.9f N, %.9f E, %.3f m (WGS84 ellipsoid)",
                engine::RadToDeg(scene.origin.latitude_rad),
                engine::RadToDeg(scene.origin.longitude_rad), scene.origin.altitude_m);
  scenes::WriteTerrainGeoTiff(*field, engine::LocalNedFrame(scene.origin), result.pixel_m,
                              {{"generator", std::string("airis terrain export ") + kVersion},
                               {"scene", scene.path},
                               {"seed", std::to_string(scene.seed)},
                               {"parameters", scene.terrain_settings},
                               {"origin", origin},
                               {"heights", "ellipsoid (WGS84), m"},
                               {"date", date}},
                              out);
  return result;
}

}  // namespace airis::tools
