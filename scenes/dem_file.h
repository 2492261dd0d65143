#pragma once

// Terrain from a digital elevation model file read through GDAL: the file's heights placed by its
// own georeferencing on the scene's local NED grid.

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>

#include "engine/core/config.h"
#include "engine/core/geodetic.h"
#include "engine/scene/heightfield.h"

namespace airis::scenes {

/// What a DEM's heights are measured from.
enum class DemHeights {
  kMsl,        ///< mean sea level: the EGM96 geoid (PROJ's egm96_15.gtx grid, Debian's proj-data)
  kEllipsoid,  ///< the WGS84 ellipsoid, as the scene's origin altitude
};
std::span<const engine::EnumName<DemHeights>> EnumNames(DemHeights);

/// How to sample a DEM onto the terrain's grid. An unset extent is the largest north-east
/// rectangle the DEM's pixel centres cover; an unset resolution the DEM's own pixel size (m).
struct DemSampling {
  std::string path;  ///< of the file (already resolved)
  /// What the DEM's heights are measured from, when its file does not say (unset: msl). A DEM
  /// whose coordinate reference system states it (a compound CRS with a vertical one: heights
  /// over that geoid or datum, read through PROJ; a 3-D geographic CRS: ellipsoidal heights) is
  /// read by its own; a `heights` that disagrees is refused.
  std::optional<DemHeights> heights;
  std::optional<Eigen::Vector2d> extent_m;  ///< [north, east] size (m)
  Eigen::Vector2d center_m = Eigen::Vector2d::Zero();
  std::optional<double> resolution_m;
};

/// Reads the DEM `sampling.path` and samples it onto a regular NED grid of `frame` (the scene's
/// origin): each grid point (north, east) gets the height (m, up; z_W = -height) of the point where
/// the vertical through it meets the DEM's surface, the DEM interpolated bilinearly between its
/// pixel centres. The DEM is reprojected from its own coordinate reference system to WGS84 through
/// GDAL/OGR (PROJ) and from there to NED by `frame` (exact, through ECEF: the Earth's curvature is
/// in the heights). The grid is centred on center_m and covers extent_m in whole cells.
///
/// Throws engine::InvalidField naming the key to blame (`dem`, `heights`, `extent_ne_m`,
/// `center_ne_m`, `resolution_m`) for a file GDAL cannot read, one without georeferencing, one
/// that does not cover the extent, a no-data value under the grid, or a grid larger than the limits
/// (kMaxTerrainSamples, kMaxDemWindowPixels: counts checked before anything is allocated).
engine::Heightfield LoadDemTerrain(const DemSampling& sampling, const engine::LocalNedFrame& frame);

}  // namespace airis::scenes
