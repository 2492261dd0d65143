#include "scenes/terrain.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>

#include "engine/core/error.h"
#include "engine/core/limits.h"
#include "engine/scene/terrain_mesh.h"

namespace airis::scenes {
namespace {

using engine::Require;
using engine::RequireInRange;
using engine::RequireNonNegative;
using engine::RequirePositive;

// Samples along one side of an extent: whole cells (rounded down) plus one.
double SampleCount(double extent_m, double resolution_m) {
  return std::floor(extent_m / resolution_m + 1e-9) + 1.0;
}

// SplitMix64 (Steele, Lea & Flood 2014): a lattice point's gradient from the seed, the octave and
// the point alone, so every sample is computed independently and identically on every machine.
std::uint64_t Mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Perlin's gradients for 2-D: the eight directions to the corners and edges of a square (constants,
// no trigonometry: bit-identical everywhere).
constexpr double kDiagonal = 0.70710678118654752;
constexpr std::array<std::array<double, 2>, 8> kGradients{{{1.0, 0.0},
                                                           {-1.0, 0.0},
                                                           {0.0, 1.0},
                                                           {0.0, -1.0},
                                                           {kDiagonal, kDiagonal},
                                                           {-kDiagonal, kDiagonal},
                                                           {kDiagonal, -kDiagonal},
                                                           {-kDiagonal, -kDiagonal}}};

double Fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

// Gradient noise at (x, y) (lattice units) in about [-1, 1].
double GradientNoise(std::uint64_t seed, double x, double y) {
  const double fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy);
  const double dx = x - fx, dy = y - fy;
  const auto corner = [&](std::int64_t cx, std::int64_t cy, double ox, double oy) {
    const std::uint64_t h =
        Mix(seed ^ Mix(static_cast<std::uint64_t>(cx) ^ Mix(static_cast<std::uint64_t>(cy))));
    const auto& g = kGradients[h & 7u];
    return g[0] * ox + g[1] * oy;
  };
  const double n00 = corner(ix, iy, dx, dy);
  const double n10 = corner(ix + 1, iy, dx - 1.0, dy);
  const double n01 = corner(ix, iy + 1, dx, dy - 1.0);
  const double n11 = corner(ix + 1, iy + 1, dx - 1.0, dy - 1.0);
  const double u = Fade(dx), v = Fade(dy);
  const double a = n00 + u * (n10 - n00), b = n01 + u * (n11 - n01);
  // 2-D gradient noise stays within +-sqrt(1/2): scaled to +-1.
  return std::sqrt(2.0) * (a + v * (b - a));
}

// Writes each field of a config as `key=value` (DescribeTerrain).
class DescribeVisitor {
 public:
  explicit DescribeVisitor(bool dem) : dem_(dem) {}
  template <class T>
  void Field(const char* key, const T& value, const char*) {
    // Only the keys that shaped this terrain: a DEM's or the generated hills'.
    const std::string k = key;
    const bool dem_key = k == "dem" || k == "heights";
    const bool hills_key =
        std::any_of(std::begin(kGeneratedTerrainKeys), std::end(kGeneratedTerrainKeys),
                    [&](const char* g) { return k == g; });
    if ((dem_key && !dem_) || (hills_key && dem_)) return;
    Append(key, Text(value));
  }
  std::string text;

 private:
  void Append(const char* key, const std::string& value) {
    text += (text.empty() ? "" : " ") + std::string(key) + "=" + value;
  }
  static std::string Text(double v) { return engine::FormatNumber(v); }
  static std::string Text(int v) { return std::to_string(v); }
  static std::string Text(const std::string& v) { return v; }
  static std::string Text(DemHeights v) { return std::string(engine::ToString(v)); }
  static std::string Text(const Eigen::Vector2d& v) {
    return "[" + engine::FormatNumber(v.x()) + "," + engine::FormatNumber(v.y()) + "]";
  }
  bool dem_;
};

}  // namespace

std::string DescribeTerrain(const TerrainConfig& config) {
  DescribeVisitor v(!config.dem.empty());
  TerrainConfig fields = config;  // Visit takes its fields by reference
  fields.Visit(v);
  return v.text;
}

void TerrainConfig::Validate() const {
  for (int i = 0; i < 2; ++i) {
    const std::string field = "extent_ne_m[" + std::to_string(i) + "]";
    RequirePositive(field, extent_m[i]);
    Require(extent_m[i] <= 2.0 * engine::kMaxCoordinate_m, field,
            "must be at most " + engine::FormatNumber(2.0 * engine::kMaxCoordinate_m) +
                " m, the width of the world (got " + engine::FormatNumber(extent_m[i]) +
                "; docs/limits.md)");
  }
  engine::RequireWithinWorld("center_ne_m", center_m);
  RequirePositive("resolution_m", resolution_m);
  // A DEM's grid depends on the file (its extent, its pixel size): LoadDemTerrain checks it.
  if (dem.empty()) ValidateGeneratedHills();
  RequireInRange("rock_slope_deg", rock_slope_deg, 0.0, 90.0);
  RequireInRange("soil_above_fraction", soil_above_fraction, 0.0, 1.0);
  RequireNonNegative("friction", friction);
  RequireInRange("restitution", restitution, 0.0, 1.0);
  Require(!class_name.empty(), "class", "must not be empty");
}

void TerrainConfig::ValidateGeneratedHills() const {
  const double cells_min = std::min(extent_m.x(), extent_m.y()) / resolution_m;
  Require(cells_min >= 1.0, "resolution_m",
          "must be at most the smaller extent, " +
              engine::FormatNumber(std::min(extent_m.x(), extent_m.y())) +
              " m (one cell at least; got " + engine::FormatNumber(resolution_m) + ")");
  const double samples =
      SampleCount(extent_m.x(), resolution_m) * SampleCount(extent_m.y(), resolution_m);
  Require(samples <= static_cast<double>(engine::kMaxTerrainSamples), "resolution_m",
          "gives " + engine::FormatNumber(samples) + " height samples over " +
              engine::FormatNumber(extent_m.x()) + " x " + engine::FormatNumber(extent_m.y()) +
              " m, more than the limit of " + std::to_string(engine::kMaxTerrainSamples) +
              " (docs/limits.md; got " + engine::FormatNumber(resolution_m) + ")");
  RequireNonNegative("relief_m", relief_m);
  Require(relief_m <= engine::kMaxFlightHeight_m, "relief_m",
          "must be at most " + engine::FormatNumber(engine::kMaxFlightHeight_m) + " m (got " +
              engine::FormatNumber(relief_m) + ")");
  RequirePositive("feature_size_m", feature_size_m);
  RequireInRange("octaves", octaves, 1, 16);
  RequireInRange("roughness", roughness, 0.0, 1.0);
  RequireInRange("ridges", ridges, 0.0, 1.0);
  RequireInRange("valleys", valleys, 0.0, 1.0);
}

engine::Heightfield GenerateTerrain(const TerrainConfig& c, engine::RandomStream& stream) {
  const int rows = static_cast<int>(SampleCount(c.extent_m.x(), c.resolution_m));
  const int cols = static_cast<int>(SampleCount(c.extent_m.y(), c.resolution_m));
  const Eigen::Vector2d origin =
      c.center_m - 0.5 * c.resolution_m * Eigen::Vector2d(rows - 1, cols - 1);
  const std::uint64_t seed = stream.NextU64();
  std::vector<double> f(static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols));
  for (int r = 0; r < rows; ++r) {
    for (int col = 0; col < cols; ++col) {
      const double x = (origin.x() + r * c.resolution_m) / c.feature_size_m;
      const double y = (origin.y() + col * c.resolution_m) / c.feature_size_m;
      double sum = 0.0, amplitude = 1.0, frequency = 1.0;
      for (int k = 0; k < c.octaves; ++k) {
        const double n =
            GradientNoise(Mix(seed + static_cast<std::uint64_t>(k)), x * frequency, y * frequency);
        sum += amplitude * ((1.0 - c.ridges) * n + c.ridges * (1.0 - 2.0 * std::abs(n)));
        amplitude *= c.roughness;
        frequency *= 2.0;
      }
      f[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) +
        static_cast<std::size_t>(col)] = sum;
    }
  }
  const auto [lo_it, hi_it] = std::minmax_element(f.begin(), f.end());
  const double lo = *lo_it, span = *hi_it - *lo_it;
  const double exponent = 1.0 + 3.0 * c.valleys;
  for (double& h : f) {
    const double t = span > 0.0 ? (h - lo) / span : 0.0;
    h = c.relief_m * std::pow(t, exponent);
  }
  return engine::Heightfield(origin, c.resolution_m, rows, cols, std::move(f));
}

TerraceResult LevelTerrain(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
                           engine::Heightfield* field) {
  const double s = field->spacing_m();
  const Eigen::Vector2d o = field->origin_ne_m();
  // Samples from the cell that holds lo to the one past hi, clamped to the grid.
  const int r0 =
      std::clamp(static_cast<int>(std::floor((lo.x() - o.x()) / s)), 0, field->rows() - 1);
  const int r1 =
      std::clamp(static_cast<int>(std::ceil((hi.x() - o.x()) / s)), 0, field->rows() - 1);
  const int c0 =
      std::clamp(static_cast<int>(std::floor((lo.y() - o.y()) / s)), 0, field->cols() - 1);
  const int c1 =
      std::clamp(static_cast<int>(std::ceil((hi.y() - o.y()) / s)), 0, field->cols() - 1);
  TerraceResult result;
  result.lowest_m = std::numeric_limits<double>::infinity();
  result.highest_m = -std::numeric_limits<double>::infinity();
  double sum = 0.0;
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) {
      const double h = field->height_m(r, c);
      sum += h;
      result.lowest_m = std::min(result.lowest_m, h);
      result.highest_m = std::max(result.highest_m, h);
    }
  }
  result.height_m = sum / ((r1 - r0 + 1) * (c1 - c0 + 1));
  std::vector<double> heights;
  heights.reserve(static_cast<std::size_t>(field->rows()) *
                  static_cast<std::size_t>(field->cols()));
  for (int r = 0; r < field->rows(); ++r) {
    for (int c = 0; c < field->cols(); ++c) {
      const bool under = r >= r0 && r <= r1 && c >= c0 && c <= c1;
      heights.push_back(under ? result.height_m : field->height_m(r, c));
    }
  }
  *field = engine::Heightfield(o, s, field->rows(), field->cols(), std::move(heights));
  return result;
}

bool AddTerrain(const TerrainConfig& c, engine::Heightfield heightfield, std::uint8_t class_id,
                engine::StaticSceneBuilder& builder) {
  // Grass, rock and soil (linear RGB), one contact material for all three.
  const auto material = [&](const char* name, const Eigen::Vector3f& rgb,
                            engine::SurfacePattern pattern, const Eigen::Vector2f& size_m) {
    engine::Material m = engine::MakePatternedMaterial(name, rgb, pattern, size_m, 0.9f);
    m.friction = static_cast<float>(c.friction);
    m.restitution = static_cast<float>(c.restitution);
    return builder.Material(m);
  };
  // Patches of 15 m with a 0.5 m grain; rock strata 1.5 m apart.
  const std::uint32_t materials[3] = {material("grass", Eigen::Vector3f(0.22f, 0.36f, 0.12f),
                                               engine::SurfacePattern::kGrass, {15.0f, 0.5f}),
                                      material("rock", Eigen::Vector3f(0.42f, 0.40f, 0.37f),
                                               engine::SurfacePattern::kRock, {1.5f, 0.3f}),
                                      material("soil", Eigen::Vector3f(0.40f, 0.31f, 0.20f),
                                               engine::SurfacePattern::kSoil, {6.0f, 0.3f})};
  const double rock_up = std::cos(c.rock_slope_deg * M_PI / 180.0);
  // Generated hills span 0 to relief_m (before terraces); a DEM its own lowest to highest sample.
  const double soil_above_m =
      c.dem.empty()
          ? c.soil_above_fraction * c.relief_m
          : heightfield.min_height_m() +
                c.soil_above_fraction * (heightfield.max_height_m() - heightfield.min_height_m());
  const engine::TerrainTriangleClass classify = [&](const engine::Vec3& n, double height_m) {
    if (-n.z() < rock_up) return 1;
    return height_m > soil_above_m ? 2 : 0;
  };

  return engine::AddTerrainChunks(
      std::make_shared<const engine::Heightfield>(std::move(heightfield)), class_id, materials,
      classify, builder);
}

}  // namespace airis::scenes
