#pragma once

// The GDAL plugin: elevation models read (dem_file.h) and written (geotiff_export.h) through GDAL,
// built as its own shared object (libairis_gdal.so) and loaded the first time a scene reads a DEM
// or a terrain is exported. GDAL brings some 110 shared libraries; linked into every airis
// process, loading them cost each process tens of milliseconds of CPU whether it read a DEM or
// not (docs/performance.md, "Process start").

#include <string>
#include <utility>
#include <vector>

#include "engine/core/geodetic.h"
#include "engine/scene/heightfield.h"
#include "scenes/dem_file.h"

namespace airis::scenes {

/// What the plugin gives: one table behind one exported symbol. The plugin is built with the same
/// compiler and libraries as its callers (the same build), so C++ types and exceptions cross.
struct GdalPluginApi {
  int abi_version = 0;
  engine::Heightfield (*load_dem_terrain)(const DemSampling&,
                                          const engine::LocalNedFrame&) = nullptr;
  void (*write_terrain_geotiff)(const engine::Heightfield&, const engine::LocalNedFrame&, double,
                                const std::vector<std::pair<std::string, std::string>>&,
                                const std::string&) = nullptr;
};

/// Raised when a table's layout changes.
inline constexpr int kGdalPluginAbiVersion = 1;
/// The plugin's one exported symbol: `const GdalPluginApi* airis_gdal_plugin_api()`.
inline constexpr char kGdalPluginEntry[] = "airis_gdal_plugin_api";

/// The plugin's table, loaded on the first call: from the file named by the environment variable
/// AIRIS_GDAL_PLUGIN when set, else the build's own libairis_gdal.so. Null, with `*error` naming
/// the file and the loader's reason, when it cannot be loaded.
const GdalPluginApi* FindGdalPlugin(std::string* error);

// Inside the plugin: the implementations behind dem_file.h and geotiff_export.h.
engine::Heightfield GdalLoadDemTerrain(const DemSampling& sampling,
                                       const engine::LocalNedFrame& frame);
void GdalWriteTerrainGeoTiff(const engine::Heightfield& field, const engine::LocalNedFrame& frame,
                             double pixel_m,
                             const std::vector<std::pair<std::string, std::string>>& metadata,
                             const std::string& path);

}  // namespace airis::scenes
