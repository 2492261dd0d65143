#pragma once

// Elevation model files written for tests through GDAL, with heights from a function of the
// DEM's own coordinates, so that what a scene samples can be checked against a closed form.

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace airis::testing {

/// A north-up DEM: `width` x `height` pixels of `pixel` CRS units, upper-left pixel corner at
/// (x0, y0) of the CRS `crs` ("EPSG:32632"; empty: no georeferencing at all).
struct DemSpec {
  std::string crs = "EPSG:32632";
  double x0 = 0.0, y0 = 0.0, pixel = 5.0;
  int width = 201, height = 201;
  /// Height (m) at a pixel centre's CRS coordinates.
  std::function<double(double x, double y)> height_at = [](double, double) { return 0.0; };
  /// Pixels given this value are marked as such (no-data); `no_data_pixels` lists them.
  std::optional<double> no_data;
  std::vector<std::pair<int, int>> no_data_pixels;  ///< (col, row)
  std::string driver = "GTiff";
};

/// Writes `spec` to `path` (float64, one band); false when GDAL could not.
[[nodiscard]] inline bool WriteDem(const std::string& path, const DemSpec& spec) {
  GDALAllRegister();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(spec.driver.c_str());
  GDALDataset* out = driver->Create(path.c_str(), spec.width, spec.height, 1, GDT_Float64, nullptr);
  if (out == nullptr) return false;
  if (!spec.crs.empty()) {
    double geo[6] = {spec.x0, spec.pixel, 0.0, spec.y0, 0.0, -spec.pixel};
    out->SetGeoTransform(geo);
    OGRSpatialReference crs;
    crs.SetFromUserInput(spec.crs.c_str());
    out->SetSpatialRef(&crs);
  }
  std::vector<double> h(static_cast<std::size_t>(spec.width) * spec.height);
  for (int r = 0; r < spec.height; ++r) {
    for (int c = 0; c < spec.width; ++c) {
      h[static_cast<std::size_t>(r) * spec.width + c] =
          spec.height_at(spec.x0 + (c + 0.5) * spec.pixel, spec.y0 - (r + 0.5) * spec.pixel);
    }
  }
  GDALRasterBand* band = out->GetRasterBand(1);
  if (spec.no_data) {
    band->SetNoDataValue(*spec.no_data);
    for (const auto& [c, r] : spec.no_data_pixels)
      h[static_cast<std::size_t>(r) * spec.width + c] = *spec.no_data;
  }
  const bool written = band->RasterIO(GF_Write, 0, 0, spec.width, spec.height, h.data(), spec.width,
                                      spec.height, GDT_Float64, 0, 0) == CE_None;
  GDALClose(out);
  return written;
}

/// Transforms (x, y) in place between two CRSs given as user input ("EPSG:4326"), in GIS order
/// (longitude, latitude in degrees for geographic ones).
inline void TransformPoint(const std::string& from, const std::string& to, double* x, double* y,
                           double* z = nullptr) {
  OGRSpatialReference a, b;
  a.SetFromUserInput(from.c_str());
  b.SetFromUserInput(to.c_str());
  a.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  b.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  OGRCoordinateTransformation* t = OGRCreateCoordinateTransformation(&a, &b);
  t->Transform(1, x, y, z);
  OGRCoordinateTransformation::DestroyCT(t);
}

}  // namespace airis::testing
