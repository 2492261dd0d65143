// Part of the GDAL plugin (gdal_plugin.h): what dem_file.h's LoadDemTerrain does.
#include <cpl_conv.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/limits.h"
#include "scenes/gdal_plugin.h"
#include "scenes/gdal_session.h"

namespace airis::scenes {
namespace {

namespace fs = std::filesystem;
using engine::FormatNumber;
using engine::FormatRounded;
using engine::InvalidField;

// A pixel-centre coordinate this close outside the DEM still counts as on it (rounding of the
// reprojection; 1e-6 pixel is a micrometre on a 1 m DEM).
constexpr double kEdgeTolerance_px = 1e-6;

// Points along each edge of a DEM at most, where its footprint on the ground plan is found.
constexpr int kEdgePoints = 4096;

using Transform =
    std::unique_ptr<OGRCoordinateTransformation, void (*)(OGRCoordinateTransformation*)>;

Transform MakeTransform(const OGRSpatialReference& from, const OGRSpatialReference& to) {
  OGRCoordinateTransformationOptions options;
  // No silent "ballpark" fallback (a datum shift or geoid left out): fail instead.
  options.SetBallparkAllowed(false);
  return Transform(OGRCreateCoordinateTransformation(&from, &to, options),
                   OGRCoordinateTransformation::DestroyCT);
}

// The WGS84 ellipsoidal heights (m, into `z`) of height 0 of `from` (a CRS with heights: compound
// or 3-D) at its points (x, y), in GIS order, through PROJ without a "ballpark" fallback. False
// when there is no such transformation here (a geoid grid missing) or a point fails.
bool CalcEllipsoidalHeightsOfZero(const OGRSpatialReference& from, std::vector<double> x,
                                  std::vector<double> y, std::vector<double>* z) {
  OGRSpatialReference ellipsoidal;
  ellipsoidal.importFromEPSG(4979);
  ellipsoidal.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  const Transform t = MakeTransform(from, ellipsoidal);
  if (!t) return false;
  z->assign(x.size(), 0.0);
  std::vector<int> ok(x.size(), 0);
  t->Transform(x.size(), x.data(), y.data(), z->data(), ok.data());
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!ok[i] || !std::isfinite((*z)[i])) return false;
  }
  return true;
}

OGRSpatialReference Wgs84Geographic() {
  OGRSpatialReference wgs84;
  wgs84.importFromEPSG(4326);
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);  // x = longitude, y = latitude
  return wgs84;
}

// The open DEM: its first band, georeferencing and the transforms to and from WGS84.
class Dem {
 public:
  explicit Dem(const std::string& path) : path_(path) {
    if (fs::is_directory(path)) throw InvalidField("dem", path + " is a folder, not a DEM file");
    if (!fs::is_regular_file(path)) throw InvalidField("dem", "DEM file not found: " + path);
    GdalErrorCapture capture;
    {
      // GeoTIFF reports a vertical CRS (VerticalCSTypeGeoKey) only when asked.
      CPLConfigOptionSetter report_vertical("GTIFF_REPORT_COMPD_CS", "YES", false);
      dataset_.reset(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
    }
    if (!dataset_) {
      throw InvalidField("dem", "cannot read " + path + " as a raster (GDAL: " +
                                    capture.Message("no driver recognises it") + ")");
    }
    width_ = dataset_->GetRasterXSize();
    height_ = dataset_->GetRasterYSize();
    if (dataset_->GetRasterCount() < 1 || width_ < 2 || height_ < 2) {
      throw InvalidField("dem", path + " has " + std::to_string(dataset_->GetRasterCount()) +
                                    " band(s) of " + std::to_string(width_) + " x " +
                                    std::to_string(height_) +
                                    " pixels; a DEM needs one band of at least 2 x 2");
    }
    band_ = dataset_->GetRasterBand(1);
    const OGRSpatialReference* crs = dataset_->GetSpatialRef();
    if (dataset_->GetGeoTransform(geo_.data()) != CE_None || crs == nullptr || crs->IsEmpty()) {
      throw InvalidField("dem", path +
                                    " has no georeferencing (a geotransform and a coordinate "
                                    "reference system): airis cannot place it on the Earth");
    }
    if (!GDALInvGeoTransform(geo_.data(), inverse_.data())) {
      throw InvalidField("dem", path + " has a degenerate geotransform (its pixels have no area)");
    }
    crs_ = *crs;
    crs_.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    if (crs_.IsCompound()) {
      const char* name = crs_.GetAttrValue("COMPD_CS|VERT_CS");
      const char* code = crs_.GetAuthorityCode("COMPD_CS|VERT_CS");
      stated_ = DemHeights::kMsl;
      vertical_ = std::string(name ? name : "an unnamed vertical CRS") +
                  (code ? std::string(" (EPSG:") + code + ")" : "");
    } else if (crs_.IsGeographic() && crs_.GetAxesCount() == 3) {
      stated_ = DemHeights::kEllipsoid;
      vertical_ = "ellipsoidal heights (" + std::string(crs_.GetName() ? crs_.GetName() : "") +
                  ", a 3-D geographic CRS)";
    }
    // Positions on the ground plan go through the horizontal part alone.
    OGRSpatialReference horizontal = crs_;
    if (horizontal.IsCompound()) horizontal.StripVertical();
    const OGRSpatialReference wgs84 = Wgs84Geographic();
    to_wgs84_ = MakeTransform(horizontal, wgs84);
    from_wgs84_ = MakeTransform(wgs84, horizontal);
    if (!to_wgs84_ || !from_wgs84_) {
      throw InvalidField("dem",
                         path + ": no transformation between its coordinate reference system (" +
                             std::string(crs_.GetName() ? crs_.GetName() : "unnamed") +
                             ") and WGS84 (GDAL: " + capture.Message("unknown reason") + ")");
    }
    int has_no_data = 0;
    no_data_ = band_->GetNoDataValue(&has_no_data);
    has_no_data_ = has_no_data != 0;
  }

  const std::string& path() const { return path_; }
  int width() const { return width_; }
  int height() const { return height_; }

  /// Geodetic (rad) of the pixel centre (col, row) (pixel indices; centres at integers).
  bool PixelToGeodetic(double col, double row, double* lat_rad, double* lon_rad) const {
    double x, y;
    PixelToCrs(col, row, &x, &y);
    GdalErrorCapture quiet;
    if (!to_wgs84_->Transform(1, &x, &y)) return false;
    *lon_rad = x * M_PI / 180.0;
    *lat_rad = y * M_PI / 180.0;
    return std::isfinite(x) && std::isfinite(y);
  }

  /// Pixel-centre coordinates (col, row) of geodetic points, in place: x = longitude, y =
  /// latitude (rad) in, column, row out. False where a point does not transform.
  void GeodeticToPixels(std::vector<double>& x, std::vector<double>& y,
                        std::vector<int>& ok) const {
    for (std::size_t i = 0; i < x.size(); ++i) {
      x[i] *= 180.0 / M_PI;
      y[i] *= 180.0 / M_PI;
    }
    ok.assign(x.size(), 0);
    GdalErrorCapture quiet;
    from_wgs84_->Transform(x.size(), x.data(), y.data(), nullptr, ok.data());
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double col = inverse_[0] + inverse_[1] * x[i] + inverse_[2] * y[i] - 0.5;
      const double row = inverse_[3] + inverse_[4] * x[i] + inverse_[5] * y[i] - 0.5;
      x[i] = col;
      y[i] = row;
      ok[i] = ok[i] && std::isfinite(col) && std::isfinite(row);
    }
  }

  /// Reads columns [c0, c1] x rows [r0, r1] of the band into `out` (row-major).
  void Read(int c0, int r0, int c1, int r1, std::vector<double>* out) const {
    const int w = c1 - c0 + 1, h = r1 - r0 + 1;
    out->resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    GdalErrorCapture capture;
    if (band_->RasterIO(GF_Read, c0, r0, w, h, out->data(), w, h, GDT_Float64, 0, 0) != CE_None) {
      throw InvalidField("dem", "cannot read the heights of " + path_ +
                                    " (GDAL: " + capture.Message("read failed") + ")");
    }
  }

  /// What the file says its heights are measured from (unset: it does not say).
  const std::optional<DemHeights>& stated() const { return stated_; }
  /// The same in words, for messages ("EGM96 height (EPSG:5773)").
  const std::string& vertical() const { return vertical_; }

  /// The WGS84 ellipsoidal height (m) of the file's height 0 at pixel-centre coordinates (col,
  /// row) (centres at integers), for a file that states its heights' reference: through PROJ,
  /// from the file's CRS to WGS84 3-D (EPSG:4979), without a "ballpark" fallback (a missing geoid
  /// grid is an error, not heights left as they are).
  std::vector<double> CalcZeroHeights_m(const std::vector<double>& col,
                                        const std::vector<double>& row) const {
    std::vector<double> x(col.size()), y(col.size()), z;
    for (std::size_t i = 0; i < col.size(); ++i) PixelToCrs(col[i], row[i], &x[i], &y[i]);
    GdalErrorCapture quiet;  // (GDAL's message spells out both CRSs in full WKT: too long to help)
    if (!CalcEllipsoidalHeightsOfZero(crs_, std::move(x), std::move(y), &z)) {
      throw InvalidField("dem", path_ + " states its heights as " + vertical_ +
                                    ", which PROJ cannot convert to WGS84 ellipsoidal heights "
                                    "here (its geoid grid is not installed; Debian's proj-data "
                                    "holds the EGM96 one): convert the heights to EGM96 or to "
                                    "the ellipsoid first");
    }
    return z;
  }

  bool IsNoData(double h) const { return !std::isfinite(h) || (has_no_data_ && h == no_data_); }
  double no_data() const { return no_data_; }

 private:
  // The DEM's CRS coordinates of pixel-centre coordinates (col, row) (centres at integers).
  void PixelToCrs(double col, double row, double* x, double* y) const {
    *x = geo_[0] + (col + 0.5) * geo_[1] + (row + 0.5) * geo_[2];
    *y = geo_[3] + (col + 0.5) * geo_[4] + (row + 0.5) * geo_[5];
  }

  std::string path_;
  std::unique_ptr<GDALDataset> dataset_;
  GDALRasterBand* band_ = nullptr;
  int width_ = 0, height_ = 0;
  std::array<double, 6> geo_{}, inverse_{};
  OGRSpatialReference crs_;
  Transform to_wgs84_{nullptr, OGRCoordinateTransformation::DestroyCT};
  Transform from_wgs84_{nullptr, OGRCoordinateTransformation::DestroyCT};
  bool has_no_data_ = false;
  double no_data_ = 0.0;
  std::optional<DemHeights> stated_;
  std::string vertical_;
};

// The DEM's pixel centres on the ground plan (NED north, east at the origin's altitude): the
// largest axis-aligned rectangle inside them (each edge's innermost point), and the pixel size.
struct Footprint {
  Eigen::Vector2d lo, hi;
  double pixel_m = 0.0;
};

Footprint CalcFootprint(const Dem& dem, const engine::LocalNedFrame& frame) {
  const auto ne = [&](double col, double row) {
    engine::GeodeticPosition g;
    g.altitude_m = frame.origin().altitude_m;
    if (!dem.PixelToGeodetic(col, row, &g.latitude_rad, &g.longitude_rad)) {
      throw InvalidField("dem", dem.path() + ": its pixel (" + FormatNumber(col) + ", " +
                                    FormatNumber(row) + ") does not transform to WGS84");
    }
    const engine::Vec3 p = frame.ToNed(g);
    return Eigen::Vector2d(p.x(), p.y());
  };
  // The four edges of pixel centres, each as points along it: every pixel, or for a large DEM
  // kEdgePoints spread evenly (an edge bends by centimetres between them, and a huge raster
  // costs no more to place than a small one).
  const int w = dem.width() - 1, h = dem.height() - 1;
  const auto along = [](int last) {
    std::vector<double> at;
    const int count = std::min(last, kEdgePoints);
    for (int k = 0; k <= count; ++k) at.push_back(static_cast<double>(last) * k / count);
    return at;
  };
  std::array<std::vector<Eigen::Vector2d>, 4> edges;
  for (const double c : along(w)) {
    edges[0].push_back(ne(c, 0));
    edges[1].push_back(ne(c, h));
  }
  for (const double r : along(h)) {
    edges[2].push_back(ne(0, r));
    edges[3].push_back(ne(w, r));
  }
  // Name each edge by where its middle lies: the southernmost, northernmost, westernmost, ...
  const auto mean = [](const std::vector<Eigen::Vector2d>& e) {
    Eigen::Vector2d m = Eigen::Vector2d::Zero();
    for (const auto& p : e) m += p;
    return Eigen::Vector2d(m / static_cast<double>(e.size()));
  };
  std::array<int, 4> order{0, 1, 2, 3};
  const auto by = [&](int axis, bool lowest) {
    return *std::min_element(order.begin(), order.end(), [&](int a, int b) {
      return lowest ? mean(edges[a])[axis] < mean(edges[b])[axis]
                    : mean(edges[a])[axis] > mean(edges[b])[axis];
    });
  };
  Footprint f;
  f.lo = Eigen::Vector2d(-std::numeric_limits<double>::infinity(),
                         -std::numeric_limits<double>::infinity());
  f.hi = -f.lo;
  for (const auto& p : edges[by(0, true)]) f.lo.x() = std::max(f.lo.x(), p.x());
  for (const auto& p : edges[by(0, false)]) f.hi.x() = std::min(f.hi.x(), p.x());
  for (const auto& p : edges[by(1, true)]) f.lo.y() = std::max(f.lo.y(), p.y());
  for (const auto& p : edges[by(1, false)]) f.hi.y() = std::min(f.hi.y(), p.y());
  // The pixel size at the DEM's middle, the smaller way.
  const double cc = std::floor(0.5 * w), rc = std::floor(0.5 * h);
  const Eigen::Vector2d mid = ne(cc, rc);
  f.pixel_m = std::min((ne(cc + 1, rc) - mid).norm(), (ne(cc, rc + 1) - mid).norm());
  return f;
}

double SampleCount(double extent_m, double resolution_m) {
  return std::floor(extent_m / resolution_m + 1e-9) + 1.0;
}

std::string Ne(const Eigen::Vector2d& p) {
  return "north " + FormatRounded(p.x()) + ", east " + FormatRounded(p.y()) + " m";
}

// Undulations N of the EGM96 geoid above the WGS84 ellipsoid (m) at geodetic points (rad).
std::vector<double> CalcGeoidHeights_m(const std::vector<double>& lat_rad,
                                       const std::vector<double>& lon_rad) {
  // WGS84 with EGM96 heights (EPSG:5773) to WGS84 3-D: PROJ applies the geoid grid.
  OGRSpatialReference msl;
  msl.SetFromUserInput("EPSG:4326+5773");
  msl.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::vector<double> x(lon_rad.size()), y(lat_rad.size()), z;
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = lon_rad[i] * 180.0 / M_PI;
    y[i] = lat_rad[i] * 180.0 / M_PI;
  }
  GdalErrorCapture capture;
  if (!CalcEllipsoidalHeightsOfZero(msl, std::move(x), std::move(y), &z)) {
    throw InvalidField("heights",
                       "msl heights need the EGM96 geoid (PROJ's grid egm96_15.gtx, Debian "
                       "package proj-data), which is not usable here (GDAL: " +
                           capture.Message("the geoid transformation failed") +
                           "); install it or give heights: ellipsoid if the DEM's are");
  }
  return z;
}

}  // namespace

engine::Heightfield GdalLoadDemTerrain(const DemSampling& s, const engine::LocalNedFrame& frame) {
  const Dem dem(s.path);
  const Footprint foot = CalcFootprint(dem, frame);

  // The grid: the sampling's extent or the whole footprint, at its resolution or the DEM's.
  const double resolution = s.resolution_m.value_or(foot.pixel_m);
  const Eigen::Vector2d extent = s.extent_m.value_or(foot.hi - foot.lo);
  const Eigen::Vector2d center =
      s.extent_m ? s.center_m : Eigen::Vector2d(0.5 * (foot.lo + foot.hi));
  const char* const extent_key = s.extent_m ? "extent_ne_m" : "dem";
  if (!s.extent_m && (extent.x() <= 0.0 || extent.y() <= 0.0)) {
    throw InvalidField("dem", s.path +
                                  "'s pixel centres enclose no north-east rectangle on the "
                                  "scene's ground plan");
  }
  const char* const resolution_key = s.resolution_m ? "resolution_m" : "dem";
  if (!(resolution > 0.0) || extent.minCoeff() / resolution < 1.0) {
    throw InvalidField(resolution_key, "a resolution of " + FormatRounded(resolution) +
                                           " m gives less than one cell over " +
                                           FormatRounded(extent.x()) + " x " +
                                           FormatRounded(extent.y()) + " m");
  }
  const double samples = SampleCount(extent.x(), resolution) * SampleCount(extent.y(), resolution);
  if (samples > static_cast<double>(engine::kMaxTerrainSamples)) {
    throw InvalidField(resolution_key,
                       "gives " + FormatNumber(samples) + " height samples over " +
                           FormatRounded(extent.x()) + " x " + FormatRounded(extent.y()) +
                           " m, more than the limit of " +
                           std::to_string(engine::kMaxTerrainSamples) + " (docs/limits.md; got " +
                           FormatNumber(resolution) + " m)");
  }
  const int rows = static_cast<int>(SampleCount(extent.x(), resolution));
  const int cols = static_cast<int>(SampleCount(extent.y(), resolution));
  const Eigen::Vector2d origin = center - 0.5 * resolution * Eigen::Vector2d(rows - 1, cols - 1);
  const std::size_t n = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
  const auto ne_of = [&](std::size_t i) {
    return Eigen::Vector2d(origin.x() + static_cast<double>(i / cols) * resolution,
                           origin.y() + static_cast<double>(i % cols) * resolution);
  };

  // First pass: the DEM under each grid point at the tangent plane (z = 0), exactly reprojected.
  std::vector<double> alt(n), lat(n), lon(n), col, row;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d p = ne_of(i);
    const engine::GeodeticPosition g = frame.ToGeodetic(engine::Vec3(p.x(), p.y(), 0.0));
    lat[i] = g.latitude_rad;
    lon[i] = g.longitude_rad;
    alt[i] = g.altitude_m;
  }
  // The ellipsoidal height of the DEM's height 0 under each sample: by the file's own vertical
  // reference where it states one, else the EGM96 geoid for msl, else 0 (ellipsoidal heights).
  if (dem.stated() && s.heights && *s.heights != *dem.stated()) {
    throw InvalidField("heights", s.path + " states its heights as " + dem.vertical() + ", not " +
                                      (*s.heights == DemHeights::kMsl ? "msl" : "ellipsoid") +
                                      ": leave out heights (the file's own reference is used)");
  }
  std::vector<double> zero_height_m;
  if (!dem.stated() && s.heights.value_or(DemHeights::kMsl) == DemHeights::kMsl) {
    zero_height_m = CalcGeoidHeights_m(lat, lon);
  }
  col = std::move(lon);
  row = std::move(lat);
  std::vector<int> ok;
  dem.GeodeticToPixels(col, row, ok);

  // Every sample on the DEM, then the window of pixels under the grid (read once).
  double cmin = std::numeric_limits<double>::infinity(), cmax = -cmin, rmin = cmin, rmax = -cmin;
  for (std::size_t i = 0; i < n; ++i) {
    const bool on = ok[i] && col[i] >= -kEdgeTolerance_px &&
                    col[i] <= dem.width() - 1 + kEdgeTolerance_px && row[i] >= -kEdgeTolerance_px &&
                    row[i] <= dem.height() - 1 + kEdgeTolerance_px;
    if (!on) {
      throw InvalidField(extent_key, s.path + " does not cover the terrain: its sample at " +
                                         Ne(ne_of(i)) +
                                         " lies off the DEM, whose pixel centres cover " +
                                         Ne(foot.lo) + " to " + Ne(foot.hi) +
                                         " around the scene's origin (move or shrink extent_ne_m, "
                                         "center_ne_m, or check scene.origin)");
    }
    cmin = std::min(cmin, col[i]);
    cmax = std::max(cmax, col[i]);
    rmin = std::min(rmin, row[i]);
    rmax = std::max(rmax, row[i]);
  }
  if (dem.stated()) zero_height_m = dem.CalcZeroHeights_m(col, row);
  // One pixel of margin: the second pass moves a sample by centimetres.
  const int c0 = std::max(0, static_cast<int>(std::floor(cmin)) - 1);
  const int r0 = std::max(0, static_cast<int>(std::floor(rmin)) - 1);
  const int c1 = std::min(dem.width() - 1, static_cast<int>(std::ceil(cmax)) + 1);
  const int r1 = std::min(dem.height() - 1, static_cast<int>(std::ceil(rmax)) + 1);
  const double pixels = static_cast<double>(c1 - c0 + 1) * static_cast<double>(r1 - r0 + 1);
  if (pixels > static_cast<double>(engine::kMaxDemWindowPixels)) {
    throw InvalidField(extent_key, "the terrain covers " + FormatNumber(pixels) + " pixels of " +
                                       s.path + ", more than the limit of " +
                                       std::to_string(engine::kMaxDemWindowPixels) +
                                       " read at once (docs/limits.md): crop it smaller");
  }
  std::vector<double> window;
  dem.Read(c0, r0, c1, r1, &window);
  const int wc = c1 - c0 + 1, wr = r1 - r0 + 1;

  // The DEM's height (ellipsoidal, m) at pixel coordinates (x, y), bilinear between the four pixel
  // centres around it (clamped onto the window).
  const auto sample = [&](double x, double y, std::size_t i) {
    const double cx = std::clamp(x - c0, 0.0, static_cast<double>(wc - 1));
    const double ry = std::clamp(y - r0, 0.0, static_cast<double>(wr - 1));
    const int ci = std::min(static_cast<int>(cx), wc - 2);
    const int ri = std::min(static_cast<int>(ry), wr - 2);
    const double u = cx - ci, v = ry - ri;
    const double* p = &window[static_cast<std::size_t>(ri) * static_cast<std::size_t>(wc) +
                              static_cast<std::size_t>(ci)];
    const double h00 = p[0], h01 = p[1], h10 = p[wc], h11 = p[wc + 1];
    for (const double h : {h00, h01, h10, h11}) {
      if (dem.IsNoData(h)) {
        throw InvalidField(
            "dem", s.path + " has no height (no-data value " + FormatNumber(dem.no_data()) +
                       ") at pixel (" + std::to_string(c0 + ci) + ", " + std::to_string(r0 + ri) +
                       ") or beside it, under the terrain's sample at " + Ne(ne_of(i)) +
                       ": crop the terrain away from it (extent_ne_m, center_ne_m)");
      }
    }
    const double h = (1 - v) * ((1 - u) * h00 + u * h01) + v * ((1 - u) * h10 + u * h11);
    return zero_height_m.empty() ? h : h + zero_height_m[i];
  };

  // Up along the vertical by the DEM's height above the tangent plane's point.
  std::vector<double> z(n);
  for (std::size_t i = 0; i < n; ++i) z[i] = alt[i] - sample(col[i], row[i], i);

  // Second pass, at the first estimate (n, e, z1): NED's vertical leans from the geodetic one
  // there by n / M north and e / N east (the ellipsoid's radii of curvature at the origin: meridian
  // M, prime vertical N), so the point lies on the geodetic vertical of the tangent plane's point
  // (n (1 + z1 / M), e (1 + z1 / N)), whose pixel coordinates follow from the first pass's by the
  // grid's own Jacobian (central differences of its pixel coordinates: exact to far below a
  // millimetre for a shift of centimetres to metres), and its altitude is the plane point's less
  // z1 cos(lean).
  const double sin_lat = std::sin(frame.origin().latitude_rad);
  const double w = std::sqrt(1.0 - engine::wgs84::kEccentricitySq * sin_lat * sin_lat);
  const double prime_m = engine::wgs84::kSemiMajorAxis_m / w;
  const double meridian_m = prime_m * (1.0 - engine::wgs84::kEccentricitySq) / (w * w);
  const double radius_m = std::sqrt(meridian_m * prime_m);
  const auto diff = [&](const std::vector<double>& v, std::size_t i, int r, int c,
                        bool along_rows) {
    const int last = along_rows ? rows - 1 : cols - 1;
    const int k = along_rows ? r : c;
    const std::size_t step = along_rows ? static_cast<std::size_t>(cols) : 1;
    const std::size_t lo = k > 0 ? i - step : i, hi = k < last ? i + step : i;
    return (v[hi] - v[lo]) / (static_cast<double>((k < last) + (k > 0)) * resolution);
  };
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const std::size_t i = static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) +
                            static_cast<std::size_t>(c);
      const Eigen::Vector2d p = ne_of(i);
      const Eigen::Vector2d shift(p.x() * z[i] / meridian_m, p.y() * z[i] / prime_m);
      const double x =
          col[i] + diff(col, i, r, c, true) * shift.x() + diff(col, i, r, c, false) * shift.y();
      const double y =
          row[i] + diff(row, i, r, c, true) * shift.x() + diff(row, i, r, c, false) * shift.y();
      const double altitude = alt[i] - z[i] * (1.0 - 0.5 * p.squaredNorm() / (radius_m * radius_m));
      z[i] -= sample(x, y, i) - altitude;
    }
  }

  std::vector<double> heights(n);
  for (std::size_t i = 0; i < n; ++i) {
    heights[i] = -z[i];
    // A height tens of kilometres from the origin's is a wrong origin altitude, height reference
    // or unit, or an unmarked no-data value.
    if (std::abs(heights[i]) > engine::kMaxFlightHeight_m) {
      throw InvalidField("dem", s.path + " puts the ground at " + Ne(ne_of(i)) + " " +
                                    FormatRounded(heights[i]) +
                                    " m from the origin's altitude, more than " +
                                    FormatNumber(engine::kMaxFlightHeight_m) +
                                    " m (check scene.origin.altitude_m, `heights` and the DEM's "
                                    "no-data value)");
    }
  }
  return engine::Heightfield(origin, resolution, rows, cols, std::move(heights));
}

}  // namespace airis::scenes
