// Terrain from an elevation model file (`terrain: {dem: ...}`): placed by its georeferencing on
// the scene's NED grid, heights against the closed form the test DEM was written from, the geoid
// against NGA's published EGM96 values, cropping and resampling, the exported GeoTIFF, and every
// refusal with its file, line and key.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "engine/core/geodetic.h"
#include "scenes/geotiff_export.h"
#include "scenes/scene.h"
#include "tests/fixtures/temp_dir.h"
#include "tests/scenes/dem_test_files.h"
#include "tests/scenes/scene_error_of.h"

namespace airis::scenes {
namespace {

using testing::DemSpec;
using ::testing::HasSubstr;
using testing::TransformPoint;
using testing::WriteDem;

// The scene's origin (Zurich, in UTM zone 32N) and the DEM around it.
constexpr double kLat_deg = 47.3769, kLon_deg = 8.5417, kAlt_m = 408.0;

// UTM 32N coordinates of the origin.
void OriginUtm(double* x, double* y) {
  *x = kLon_deg;
  *y = kLat_deg;
  TransformPoint("EPSG:4326", "EPSG:32632", x, y);
}

// A DEM of 1 km x 1 km at 5 m pixels centred on the origin, heights (ellipsoidal) a bilinear
// function of the UTM coordinates: bilinear interpolation between its pixel centres reproduces it
// exactly, so the surface it stands for is known everywhere.
DemSpec BilinearDem() {
  double x0, y0;
  OriginUtm(&x0, &y0);
  DemSpec spec;
  spec.x0 = x0 - 502.5;
  spec.y0 = y0 + 502.5;
  spec.height_at = [x0, y0](double x, double y) {
    const double dx = x - x0, dy = y - y0;
    return 400.0 + 0.1 * dx - 0.05 * dy + 2e-5 * dx * dy;
  };
  return spec;
}

std::string SceneOver(const std::string& dem_path, const std::string& more = "",
                      double altitude_m = kAlt_m) {
  return "scene:\n  origin: {latitude_deg: " + std::to_string(kLat_deg) +
         ", longitude_deg: " + std::to_string(kLon_deg) +
         ", altitude_m: " + std::to_string(altitude_m) + "}\nterrain:\n  dem: " + dem_path + "\n" +
         more;
}

const engine::Heightfield& FieldOf(const Scene& s) { return *s.static_scene->terrain.heightfield; }

engine::LocalNedFrame Frame() {
  return engine::LocalNedFrame({engine::DegToRad(kLat_deg), engine::DegToRad(kLon_deg), kAlt_m});
}

TEST(DemTerrainTest, HeightsMatchTheDemAtItsPixelCentres) {
  const DemSpec spec = BilinearDem();
  const std::string path = (airis::testing::TestTempDir() / "plane.tif").string();
  ASSERT_TRUE(WriteDem(path, spec));
  const Scene scene = LoadSceneFromString(
      SceneOver(path, "  heights: ellipsoid\n  extent_ne_m: [800, 800]\n  resolution_m: 2\n"),
      "mem.yaml");
  const engine::Heightfield& f = FieldOf(scene);
  const engine::LocalNedFrame frame = Frame();
  int checked = 0;
  for (int r = 0; r < spec.height; r += 7) {
    for (int c = 0; c < spec.width; c += 7) {
      // The pixel centre on the Earth: its UTM coordinates to WGS84, at the DEM's height.
      double x = spec.x0 + (c + 0.5) * spec.pixel, y = spec.y0 - (r + 0.5) * spec.pixel;
      const double h = spec.height_at(x, y);
      TransformPoint("EPSG:32632", "EPSG:4326", &x, &y);
      const engine::Vec3 p = frame.ToNed({engine::DegToRad(y), engine::DegToRad(x), h});
      if (std::abs(p.x()) > 399.0 || std::abs(p.y()) > 399.0) continue;  // off the crop
      // 1 mm: the terrain's triangles depart from the DEM's bilinear surface by at most
      // 2e-5 * 2 m * 2 m / 4 = 0.02 mm in a 2 m cell; the Earth's curvature bends a cell by less.
      EXPECT_NEAR(f.CalcHeight_m(p.x(), p.y()), -p.z(), 1e-3) << "pixel " << c << ", " << r;
      ++checked;
    }
  }
  EXPECT_GT(checked, 300);
  // The DEM's height at the origin is 400 m, 8 m below the origin's altitude.
  EXPECT_NEAR(f.CalcHeight_m(0.0, 0.0), -8.0, 1e-3);
}

TEST(DemTerrainTest, FarFromTheOriginTheVerticalStillMeetsTheSurface) {
  // A slope of 1 in 2 rising east, 8 km east of the origin and 1 km below it: NED's vertical
  // leans from the geodetic one there by 8 km / R = 1.3 mrad, so a single look straight down
  // would miss the surface by 1000 m * 1.3 mrad = 1.3 m horizontally, 0.6 m in height. The two
  // passes leave far below the millimetre the test asks.
  double x0, y0;
  OriginUtm(&x0, &y0);
  DemSpec spec;
  spec.pixel = 50.0;
  spec.width = spec.height = 400;
  spec.x0 = x0 - 10000.0;
  spec.y0 = y0 + 10000.0;
  spec.height_at = [x0](double x, double) { return 400.0 + 0.5 * (x - x0 - 8000.0); };
  const std::string path = (airis::testing::TestTempDir() / "slope.tif").string();
  ASSERT_TRUE(WriteDem(path, spec));
  const Scene scene = LoadSceneFromString(
      SceneOver(path,
                "  heights: ellipsoid\n  extent_ne_m: [300, 300]\n  center_ne_m: [0, 8000]\n"
                "  resolution_m: 2\n",
                1408.0),
      "mem.yaml");
  const engine::Heightfield& f = FieldOf(scene);
  const engine::LocalNedFrame frame(
      {engine::DegToRad(kLat_deg), engine::DegToRad(kLon_deg), 1408.0});
  int checked = 0;
  // The pixels around the crop (8 km east of the origin, 10 km from the DEM's western edge).
  for (int r = 190; r < 210; ++r) {
    for (int c = 350; c < 370; ++c) {
      double x = spec.x0 + (c + 0.5) * spec.pixel, y = spec.y0 - (r + 0.5) * spec.pixel;
      const double h = spec.height_at(x, y);
      TransformPoint("EPSG:32632", "EPSG:4326", &x, &y);
      const engine::Vec3 p = frame.ToNed({engine::DegToRad(y), engine::DegToRad(x), h});
      if (std::abs(p.x()) > 140.0 || std::abs(p.y() - 8000.0) > 140.0) continue;
      EXPECT_NEAR(f.CalcHeight_m(p.x(), p.y()), -p.z(), 1e-3) << "pixel " << c << ", " << r;
      ++checked;
    }
  }
  EXPECT_GE(checked, 16);
}

TEST(DemTerrainTest, PixelGeoreferencingRoundTripsThroughNed) {
  // A pixel centre's geodetic position to NED and back to the DEM's pixel grid, to 1 cm.
  const DemSpec spec = BilinearDem();
  const engine::LocalNedFrame frame = Frame();
  for (const auto& [c, r] : {std::pair{0, 0}, {200, 0}, {0, 200}, {137, 59}, {200, 200}}) {
    double x = spec.x0 + (c + 0.5) * spec.pixel, y = spec.y0 - (r + 0.5) * spec.pixel;
    const double x_utm = x, y_utm = y;
    TransformPoint("EPSG:32632", "EPSG:4326", &x, &y);
    const engine::Vec3 p = frame.ToNed({engine::DegToRad(y), engine::DegToRad(x), 430.0});
    const engine::GeodeticPosition g = frame.ToGeodetic(p);
    double bx = engine::RadToDeg(g.longitude_rad), by = engine::RadToDeg(g.latitude_rad);
    TransformPoint("EPSG:4326", "EPSG:32632", &bx, &by);
    EXPECT_NEAR(bx, x_utm, 0.01);
    EXPECT_NEAR(by, y_utm, 0.01);
    EXPECT_NEAR(g.altitude_m, 430.0, 0.01);
  }
}

TEST(DemTerrainTest, CropAndResolutionMakeTheGrid) {
  const DemSpec spec = BilinearDem();
  const std::string path = (airis::testing::TestTempDir() / "plane.tif").string();
  ASSERT_TRUE(WriteDem(path, spec));
  const Scene cropped = LoadSceneFromString(
      SceneOver(path,
                "  heights: ellipsoid\n  extent_ne_m: [300, 200]\n  center_ne_m: [100, -50]\n"
                "  resolution_m: 12.5\n"),
      "mem.yaml");
  const engine::Heightfield& f = FieldOf(cropped);
  // Whole cells over the extent, centred on center_ne_m.
  EXPECT_EQ(f.rows(), 25);
  EXPECT_EQ(f.cols(), 17);
  EXPECT_DOUBLE_EQ(f.spacing_m(), 12.5);
  EXPECT_DOUBLE_EQ(f.origin_ne_m().x(), 100.0 - 150.0);
  EXPECT_DOUBLE_EQ(f.origin_ne_m().y(), -50.0 - 100.0);
  // Without a crop or resolution: all the DEM covers, at its own pixel size (5 m, within the
  // UTM scale factor and the grid's convergence).
  const Scene whole = LoadSceneFromString(SceneOver(path, "  heights: ellipsoid\n"), "mem.yaml");
  const engine::Heightfield& w = FieldOf(whole);
  EXPECT_NEAR(w.spacing_m(), 5.0, 0.01);
  // 1000 m of UTM grid between the outer pixel centres (1000.4 m on the ground at UTM's scale
  // factor here), less what the grid's convergence from true north (0.34 degrees here, 0.46
  // degrees west of zone 32's meridian) cuts off the inscribed rectangle, 1000 * tan(0.34 deg) =
  // 6 m, and less up to one 5 m cell of rounding to whole cells.
  const Eigen::Vector2d size = w.end_ne_m() - w.origin_ne_m();
  EXPECT_GT(size.minCoeff(), 1000.4 - 6.0 - 5.0 - 0.5);
  EXPECT_LT(size.maxCoeff(), 1000.4);
}

TEST(DemTerrainTest, MslHeightsAddTheEgm96Geoid) {
  // A DEM of 0 m above mean sea level around NGA's EGM96 test points (WW15MGH test values),
  // origin at the point's ellipsoid: the terrain there is at the geoid's height N. 0.1 m: the 15'
  // grid's bilinear interpolation against the degree-360 series NGA's values come from.
  struct Point {
    double lat_deg, lon_deg, n_m;
  };
  for (const Point& pt :
       {Point{38.6281550, -90.2208450, -31.628}, Point{46.8743190, 102.4487290, -43.575},
        Point{-23.6174460, 133.8747120, 15.871}}) {
    DemSpec spec;
    spec.crs = "EPSG:4326";
    spec.pixel = 0.001;
    spec.width = spec.height = 21;
    spec.x0 = pt.lon_deg - 0.0105;
    spec.y0 = pt.lat_deg + 0.0105;
    const std::string path = (airis::testing::TestTempDir() / "msl.tif").string();
    ASSERT_TRUE(WriteDem(path, spec));
    const std::string origin = "scene:\n  origin: {latitude_deg: " + std::to_string(pt.lat_deg) +
                               ", longitude_deg: " + std::to_string(pt.lon_deg) +
                               ", altitude_m: 0}\n";
    const std::string terrain =
        "terrain: {dem: " + path + ", extent_ne_m: [200, 200], resolution_m: 10";
    const Scene msl = LoadSceneFromString(origin + terrain + "}\n", "mem.yaml");
    const Scene ell = LoadSceneFromString(origin + terrain + ", heights: ellipsoid}\n", "mem.yaml");
    EXPECT_NEAR(FieldOf(msl).CalcHeight_m(0, 0), pt.n_m, 0.1) << pt.lat_deg;
    EXPECT_NEAR(FieldOf(ell).CalcHeight_m(0, 0), 0.0, 1e-6) << pt.lat_deg;
  }
}

// A DEM whose CRS states its heights' reference is read by it: a compound CRS with EGM96 heights
// as `heights: msl` (NGA's EGM96 value at the first test point above, to 0.1 m), a 3-D geographic
// CRS as ellipsoidal heights; a `heights` key that disagrees is refused, and so is a vertical CRS
// PROJ cannot convert here (EGM2008: its grid is not in Debian's proj-data).
TEST(DemTerrainTest, TheFilesOwnVerticalReferenceIsRead) {
  const double lat = 38.6281550, lon = -90.2208450, n_m = -31.628;
  const auto write = [&](const std::string& crs) {
    DemSpec spec;
    spec.crs = crs;
    spec.pixel = 0.001;
    spec.width = spec.height = 21;
    spec.x0 = lon - 0.0105;
    spec.y0 = lat + 0.0105;
    const std::string path = (airis::testing::TestTempDir() / "vertical.tif").string();
    EXPECT_TRUE(WriteDem(path, spec));
    return "scene:\n  origin: {latitude_deg: " + std::to_string(lat) +
           ", longitude_deg: " + std::to_string(lon) + ", altitude_m: 0}\nterrain: {dem: " + path +
           ", extent_ne_m: [200, 200], resolution_m: 10";
  };
  std::string scene = write("EPSG:4326+5773");
  EXPECT_NEAR(FieldOf(LoadSceneFromString(scene + "}\n", "mem.yaml")).CalcHeight_m(0, 0), n_m, 0.1);
  EXPECT_NEAR(
      FieldOf(LoadSceneFromString(scene + ", heights: msl}\n", "mem.yaml")).CalcHeight_m(0, 0), n_m,
      0.1);
  EXPECT_THAT(SceneErrorOf(scene + ", heights: ellipsoid}\n"),
              HasSubstr("terrain.heights: " + airis::testing::TestTempDir().string() +
                        "/vertical.tif states its heights as EGM96 height (EPSG:5773), not "
                        "ellipsoid: leave out heights (the file's own reference is used)"));
  scene = write("EPSG:4979");
  EXPECT_NEAR(FieldOf(LoadSceneFromString(scene + "}\n", "mem.yaml")).CalcHeight_m(0, 0), 0.0,
              1e-6);
  EXPECT_THAT(SceneErrorOf(scene + ", heights: msl}\n"),
              HasSubstr("states its heights as ellipsoidal heights (WGS 84, a 3-D geographic "
                        "CRS), not msl"));
  scene = write("EPSG:4326+3855");
  EXPECT_THAT(SceneErrorOf(scene + "}\n"),
              HasSubstr("terrain.dem: " + airis::testing::TestTempDir().string() +
                        "/vertical.tif states its heights as EGM2008 height (EPSG:3855), which "
                        "PROJ cannot convert to WGS84 ellipsoidal heights here"));
}

TEST(DemTerrainTest, ExportedGeoTiffHoldsTheSurfaceAndItsProvenance) {
  const Scene hills = LoadSceneFromString(
      "scene: {seed: 5, origin: {latitude_deg: 46.5, longitude_deg: 7.9, altitude_m: 1500}}\n"
      "terrain: {extent_ne_m: [600, 400], resolution_m: 10, relief_m: 60}\n",
      "mem.yaml");
  const engine::Heightfield& f = FieldOf(hills);
  const engine::LocalNedFrame frame(hills.origin);
  const std::string path = (airis::testing::TestTempDir() / "hills.tif").string();
  WriteTerrainGeoTiff(f, frame, 10.0, {{"generator", "test"}, {"seed", "5"}}, path);

  GDALDataset* in = static_cast<GDALDataset*>(GDALOpen(path.c_str(), GA_ReadOnly));
  ASSERT_NE(in, nullptr);
  EXPECT_STREQ(in->GetMetadataItem("generator"), "test");
  EXPECT_STREQ(in->GetMetadataItem("seed"), "5");
  // WGS84 with ellipsoidal heights: a 3-D geographic CRS
  EXPECT_EQ(in->GetSpatialRef()->GetEPSGGeogCS(), 4979);
  EXPECT_TRUE(in->GetSpatialRef()->IsGeographic());
  EXPECT_EQ(in->GetSpatialRef()->GetAxesCount(), 3);
  double geo[6];
  ASSERT_EQ(in->GetGeoTransform(geo), CE_None);
  const int w = in->GetRasterXSize(), h = in->GetRasterYSize();
  // Pixels of 10 m inside the 600 x 400 m terrain.
  EXPECT_GE(w, 35);
  EXPECT_GE(h, 55);
  std::vector<float> z(static_cast<std::size_t>(w) * h);
  ASSERT_EQ(in->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, w, h, z.data(), w, h, GDT_Float32, 0, 0),
            CE_None);
  GDALClose(in);
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const double lon = geo[0] + (c + 0.5) * geo[1], lat = geo[3] + (r + 0.5) * geo[5];
      const double alt = z[static_cast<std::size_t>(r) * w + c];
      const engine::Vec3 p = frame.ToNed({engine::DegToRad(lat), engine::DegToRad(lon), alt});
      // 1 mm: float32 keeps 0.1 mm at 1,500 m; the point lies on the terrain's surface.
      ASSERT_NEAR(-p.z(), f.CalcHeight_m(p.x(), p.y()), 1e-3) << c << ", " << r;
    }
  }
  // Read back as a scene's DEM over the same origin, without a heights key (the file says
  // ellipsoid): the same surface, resampled twice (within 2% of the relief: bilinear smoothing of
  // hills sampled at 10 m).
  const Scene back = LoadSceneFromString(
      "scene: {origin: {latitude_deg: 46.5, longitude_deg: 7.9, altitude_m: 1500}}\n"
      "terrain: {dem: " +
          path + ", extent_ne_m: [500, 300], resolution_m: 10}\n",
      "mem.yaml");
  double worst = 0.0;
  const engine::Heightfield& b = FieldOf(back);
  for (int r = 0; r < b.rows(); ++r) {
    for (int c = 0; c < b.cols(); ++c) {
      const double n = b.origin_ne_m().x() + r * 10.0, e = b.origin_ne_m().y() + c * 10.0;
      worst = std::max(worst, std::abs(b.height_m(r, c) - f.CalcHeight_m(n, e)));
    }
  }
  EXPECT_LT(worst, 0.02 * 60.0);
}

class DemErrorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    plane_ = (airis::testing::TestTempDir() / "plane.tif").string();
    ASSERT_TRUE(WriteDem(plane_, BilinearDem()));
  }
  std::string plane_;
};

TEST_F(DemErrorTest, GeneratedKeysAndDemAreExclusive) {
  EXPECT_THAT(SceneErrorOf(SceneOver(plane_, "  relief_m: 100\n")),
              HasSubstr("scenes/v.yaml:5:3: terrain.relief_m: is a setting of generated hills, "
                        "but this terrain's heights come from `dem`"));
  EXPECT_THAT(SceneErrorOf("terrain: {heights: msl}\n"),
              HasSubstr("scenes/v.yaml:1:11: terrain.heights: applies to a `dem` only"));
  EXPECT_THAT(SceneErrorOf(SceneOver(plane_, "  center_ne_m: [10, 0]\n")),
              HasSubstr("scenes/v.yaml:5:3: terrain.center_ne_m: with `dem`, a centre crops only "
                        "with `extent_ne_m`"));
  EXPECT_THAT(SceneErrorOf(SceneOver(plane_, "  heights: sea\n")),
              HasSubstr("scenes/v.yaml:5:3: terrain.heights: unknown value 'sea' (expected msl or "
                        "ellipsoid)"));
}

TEST_F(DemErrorTest, MissingUnreadableAndUngeoreferencedFilesAreRefused) {
  EXPECT_THAT(
      SceneErrorOf(SceneOver("/nonexistent/dem.tif")),
      HasSubstr("scenes/v.yaml:4:3: terrain.dem: DEM file not found: /nonexistent/dem.tif"));
  const std::string text = airis::testing::WriteTempFile("text.tif", "not a raster\n").string();
  EXPECT_THAT(SceneErrorOf(SceneOver(text)),
              HasSubstr("scenes/v.yaml:4:3: terrain.dem: cannot read " + text + " as a raster"));
  DemSpec bare = BilinearDem();
  bare.crs = "";
  const std::string nogeo = (airis::testing::TestTempDir() / "nogeo.tif").string();
  ASSERT_TRUE(WriteDem(nogeo, bare));
  EXPECT_THAT(SceneErrorOf(SceneOver(nogeo)),
              HasSubstr("scenes/v.yaml:4:3: terrain.dem: " + nogeo + " has no georeferencing"));
}

TEST_F(DemErrorTest, ADemThatDoesNotCoverTheTerrainIsRefused) {
  // At the DEM's own resolution (5 m of UTM grid: 5.002 m on the ground here) 1200 m is 239
  // cells: the first sample lies 597.8 m south, past the DEM's 497.3 m.
  EXPECT_THAT(
      SceneErrorOf(SceneOver(plane_, "  extent_ne_m: [1200, 200]\n")),
      HasSubstr("scenes/v.yaml:5:3: terrain.extent_ne_m: " + plane_ +
                " does not cover the terrain: its sample at north -597.8, east -97.54 m lies off "
                "the DEM, whose pixel centres cover north -497.3, east -497.3 m to north "
                "497.3, east 497.3 m around the scene's origin"));
  EXPECT_THAT(SceneErrorOf(SceneOver(plane_,
                                     "  extent_ne_m: [100, 100]\n  center_ne_m: [600, "
                                     "0]\n")),
              HasSubstr("lies off the DEM, whose pixel centres cover north "));
}

TEST_F(DemErrorTest, NoDataUnderTheTerrainIsRefusedAndBesideItIsNot) {
  DemSpec spec = BilinearDem();
  spec.no_data = -9999.0;
  spec.no_data_pixels = {{100, 100}};  // under the origin
  const std::string holed = (airis::testing::TestTempDir() / "holed.tif").string();
  ASSERT_TRUE(WriteDem(holed, spec));
  EXPECT_THAT(
      SceneErrorOf(SceneOver(holed, "  heights: ellipsoid\n  extent_ne_m: [100, 100]\n")),
      HasSubstr("scenes/v.yaml:4:3: terrain.dem: " + holed +
                " has no height (no-data value -9999) at pixel (99, 100) or beside it, under "
                "the terrain's sample at north -2.501, east -2.501 m"));
  // Cropped away from the hole: accepted.
  EXPECT_EQ(SceneErrorOf(SceneOver(holed,
                                   "  heights: ellipsoid\n  extent_ne_m: [100, 100]\n"
                                   "  center_ne_m: [300, 300]\n")),
            "no error");
}

TEST_F(DemErrorTest, AbsurdResolutionsAndHeightsAreRefused) {
  EXPECT_THAT(SceneErrorOf(SceneOver(plane_, "  resolution_m: 0.1\n")),
              HasSubstr("scenes/v.yaml:5:3: terrain.resolution_m: gives "));
  EXPECT_THAT(SceneErrorOf(SceneOver(plane_, "  resolution_m: 0.1\n")),
              HasSubstr("height samples over "));
  EXPECT_THAT(SceneErrorOf(SceneOver(plane_, "  extent_ne_m: [100, 100]\n  resolution_m: 500\n")),
              HasSubstr("scenes/v.yaml:6:3: terrain.resolution_m: a resolution of 500 m gives "
                        "less than one cell"));
  // The origin 20 km above the DEM's ground: a wrong origin altitude.
  const std::string far =
      SceneOver(plane_, "  heights: ellipsoid\n  extent_ne_m: [100, 100]\n", kAlt_m + 20000.0);
  EXPECT_THAT(SceneErrorOf(far), HasSubstr("terrain.dem: " + plane_ + " puts the ground at north"));
}

}  // namespace
}  // namespace airis::scenes
