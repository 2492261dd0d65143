// Part of the GDAL plugin (gdal_plugin.h): what geotiff_export.h's WriteTerrainGeoTiff does.
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "engine/core/error.h"
#include "engine/core/limits.h"
#include "engine/dataset/file_io.h"
#include "scenes/gdal_plugin.h"
#include "scenes/gdal_session.h"

namespace airis::scenes {
namespace {

// Iterations that find where the geodetic vertical through a pixel meets the surface; each leaves
// the previous error times the surface's slope times (distance / Earth radius): far below a
// micrometre after three.
constexpr int kVerticalIterations = 3;

// Ellipsoidal height of the surface under geodetic (lat, lon) (rad).
double SurfaceAltitude_m(const engine::Heightfield& field, const engine::LocalNedFrame& frame,
                         double lat_rad, double lon_rad) {
  engine::GeodeticPosition g{lat_rad, lon_rad, frame.origin().altitude_m};
  for (int k = 0; k < kVerticalIterations; ++k) {
    const engine::Vec3 p = frame.ToNed(g);
    // Up by how far the point is below the surface (z down).
    g.altitude_m += p.z() + field.CalcHeight_m(p.x(), p.y());
  }
  return g.altitude_m;
}

}  // namespace

void GdalWriteTerrainGeoTiff(const engine::Heightfield& field, const engine::LocalNedFrame& frame,
                             double pixel_m,
                             const std::vector<std::pair<std::string, std::string>>& metadata,
                             const std::string& path) {
  engine::RequirePositive("pixel_m", pixel_m);
  // Latitude and longitude bounds inside the grid: each corner's, the inner of each pair.
  const Eigen::Vector2d lo = field.origin_ne_m(), hi = field.end_ne_m();
  const auto geo = [&](double n, double e) { return frame.ToGeodetic(engine::Vec3(n, e, 0.0)); };
  const double lat0 = std::max(geo(lo.x(), lo.y()).latitude_rad, geo(lo.x(), hi.y()).latitude_rad);
  const double lat1 = std::min(geo(hi.x(), lo.y()).latitude_rad, geo(hi.x(), hi.y()).latitude_rad);
  const double lon0 =
      std::max(geo(lo.x(), lo.y()).longitude_rad, geo(hi.x(), lo.y()).longitude_rad);
  const double lon1 =
      std::min(geo(lo.x(), hi.y()).longitude_rad, geo(hi.x(), hi.y()).longitude_rad);
  // Degrees per pixel from the ellipsoid's radii of curvature at the origin (meridian, prime
  // vertical).
  const double s = std::sin(frame.origin().latitude_rad);
  const double w = std::sqrt(1.0 - engine::wgs84::kEccentricitySq * s * s);
  const double meridian_m =
      engine::wgs84::kSemiMajorAxis_m * (1.0 - engine::wgs84::kEccentricitySq) / (w * w * w);
  const double prime_m = engine::wgs84::kSemiMajorAxis_m / w;
  const double dlat = pixel_m / meridian_m;
  const double dlon = pixel_m / (prime_m * std::cos(frame.origin().latitude_rad));
  // Whole pixels whose centres lie inside the bounds.
  const double rows_d = std::floor((lat1 - lat0) / dlat + 1e-9);
  const double cols_d = std::floor((lon1 - lon0) / dlon + 1e-9);
  if (rows_d < 2.0 || cols_d < 2.0 || rows_d * cols_d > engine::kMaxTerrainSamples) {
    throw engine::InvalidField(
        "pixel_m", "pixels of " + engine::FormatNumber(pixel_m) + " m give " +
                       engine::FormatNumber(cols_d) + " x " + engine::FormatNumber(rows_d) +
                       " over the terrain; expected 2 x 2 to " +
                       std::to_string(engine::kMaxTerrainSamples) + " pixels");
  }
  const int rows = static_cast<int>(rows_d), cols = static_cast<int>(cols_d);
  const double rad = 180.0 / M_PI;
  // North-up: row 0 is the northern edge. Pixel edges, in degrees.
  const double north_deg = (lat0 + 0.5 * (lat1 - lat0 + rows * dlat)) * rad;
  const double west_deg = (lon0 + 0.5 * (lon1 - lon0 - cols * dlon)) * rad;
  double geo_transform[6] = {west_deg, dlon * rad, 0.0, north_deg, 0.0, -dlat * rad};

  std::vector<float> heights(static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols));
  for (int r = 0; r < rows; ++r) {
    const double lat = (north_deg - (r + 0.5) * dlat * rad) / rad;
    for (int c = 0; c < cols; ++c) {
      const double lon = (west_deg + (c + 0.5) * dlon * rad) / rad;
      heights[static_cast<std::size_t>(r) * cols + c] =
          static_cast<float>(SurfaceAltitude_m(field, frame, lat, lon));
    }
  }

  GdalErrorCapture capture;
  const auto fail = [&](const std::string& what) {
    throw engine::DatasetIoError("cannot write " + path + ": " + what +
                                 " (GDAL: " + capture.Message("unknown reason") + ")");
  };
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
  if (driver == nullptr) fail("GDAL has no GTiff driver");
  const char* options[] = {"COMPRESS=DEFLATE", "PREDICTOR=3", "ZLEVEL=9", nullptr};
  std::unique_ptr<GDALDataset> out(
      driver->Create(path.c_str(), cols, rows, 1, GDT_Float32, const_cast<char**>(options)));
  if (!out) fail("the file cannot be created");
  // WGS84 3-D (EPSG:4979): the CRS itself says the heights are ellipsoidal, so a reader needs
  // no `heights` key.
  OGRSpatialReference wgs84;
  wgs84.importFromEPSG(4979);
  out->SetGeoTransform(geo_transform);
  out->SetSpatialRef(&wgs84);
  for (const auto& [key, value] : metadata) out->SetMetadataItem(key.c_str(), value.c_str());
  GDALRasterBand* band = out->GetRasterBand(1);
  band->SetDescription("height above the WGS84 ellipsoid (m)");
  band->SetUnitType("m");
  if (band->RasterIO(GF_Write, 0, 0, cols, rows, heights.data(), cols, rows, GDT_Float32, 0, 0) !=
      CE_None) {
    fail("writing the heights failed");
  }
  // Closing writes the file (GDAL 3.6 reports a failure there only through its error handler).
  out.reset();
  if (capture.HasError()) fail("closing the file failed");
}

}  // namespace airis::scenes
