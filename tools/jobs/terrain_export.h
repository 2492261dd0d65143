#pragma once

// A scene's terrain written out as a GeoTIFF elevation model with its provenance: what
// `airis terrain export` does.

#include <string>

#include "tools/jobs/simulation_job.h"

namespace airis::tools {

/// What ExportTerrain wrote.
struct TerrainExport {
  std::string path;
  double pixel_m = 0.0;
  double lowest_m = 0.0, highest_m = 0.0;  ///< of the terrain's samples, above the origin (m)
};

/// Loads `source`'s scene and writes its terrain's surface to `out` (scenes::WriteTerrainGeoTiff:
/// WGS84 geographic, ellipsoidal heights) with pixels of `pixel_m` metres (0: the terrain's
/// resolution). The file's metadata say where it came from: generator (airis and its version),
/// scene (its path), seed, parameters (the terrain block's keys), origin, heights and `date`
/// (ISO 8601, as the caller gives it). Throws ConfigError for a scene that is refused or has no
/// terrain, engine::InvalidField for a pixel size that gives too few or too many pixels,
/// engine::DatasetIoError when the file cannot be written.
TerrainExport ExportTerrain(const SceneSource& source, double pixel_m, const std::string& date,
                            const std::string& out);

}  // namespace airis::tools
