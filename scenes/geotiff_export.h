#pragma once

// A terrain written out as a georeferenced elevation model (GeoTIFF through GDAL): what
// `airis terrain export` makes, and a DEM that a scene's `terrain: {dem: ...}` reads back.

#include <string>
#include <utility>
#include <vector>

#include "engine/core/geodetic.h"
#include "engine/scene/heightfield.h"

namespace airis::scenes {

/// Writes the surface of `field` (heights on `frame`'s NED grid) as a single-band float32 GeoTIFF
/// at `path`: WGS84 geographic coordinates (EPSG:4326), north up, pixels of `pixel_m` metres (at
/// the origin's latitude) over the largest latitude-longitude rectangle inside the grid, DEFLATE
/// compressed. Each pixel holds the ellipsoidal height (WGS84, m) of the point where the geodetic
/// vertical through its centre meets the surface, so that `terrain: {dem: ..., heights:
/// ellipsoid}` over the same origin gives the surface back. `metadata` become the file's GDAL
/// metadata items (provenance: generator, scene, seed, parameters, date).
/// Throws engine::InvalidField ("pixel_m") for a pixel size that gives fewer than 2 x 2 pixels
/// or more than kMaxTerrainSamples, and engine::DatasetIoError when the file cannot be written.
void WriteTerrainGeoTiff(const engine::Heightfield& field, const engine::LocalNedFrame& frame,
                         double pixel_m,
                         const std::vector<std::pair<std::string, std::string>>& metadata,
                         const std::string& path);

}  // namespace airis::scenes
