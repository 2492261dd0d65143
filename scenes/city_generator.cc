// The `city` generator (scene_config.h CityConfig): a street grid with blocks, lots and street
// furniture.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/scene/primitive_meshes.h"
#include "scenes/generators.h"

namespace airis::scenes {

using Eigen::Affine3f;
using Eigen::Vector3d;
using Eigen::Vector3f;
using engine::CollisionShape;
using engine::Primitive;

namespace {

constexpr double kRoadThickness_m = 0.04;  // above the ground plane so the two never z-fight
constexpr double kKerbHeight_m = 0.15;
constexpr double kGableRoofRatio = 0.35;  // roof height / wall height
constexpr double kPyramidRoofRatio = 0.3;
constexpr double kLampHeight_m = 6.0;
constexpr double kCarLength_m = 4.4;

Affine3f PartPose(const Vector3f& offset, const Vector3f& scale) {
  Affine3f T = Affine3f::Identity();
  T.translate(offset);
  T.scale(scale);
  return T;
}

engine::Material Colored(const Eigen::Vector3d& rgb, const char* name) {
  engine::Material m;
  m.name = name;
  m.base_color_rgb = rgb.cast<float>();
  return m;
}

/// A material of colour `rgb` with a procedural pattern (docs/rendering.md, "Materials").
engine::Material Patterned(const Eigen::Vector3d& rgb, const char* name,
                           engine::SurfacePattern pattern, const Eigen::Vector2f& size_m,
                           float roughness) {
  return engine::MakePatternedMaterial(name, rgb.cast<float>(), pattern, size_m, roughness);
}

double Lerp(const Eigen::Vector2d& range, double u) { return range[0] + (range[1] - range[0]) * u; }

class CityBuilder {
 public:
  CityBuilder(const CityConfig& c, const CityResources& r, const std::string& name,
              engine::RandomStream& rng, engine::StaticSceneBuilder& b)
      : c_(c), r_(r), name_(name), rng_(rng), b_(b) {}

  GeneratorReport Build() {
    MakeModels();
    const Eigen::Vector2d pitch = c_.block_size_m + Eigen::Vector2d::Constant(c_.street_width_m);
    // Validate bounded the counts by kMaxCityBlocks.
    const Eigen::Vector2d blocks = CalcCityBlockCounts(c_);
    const int nx = static_cast<int>(blocks.x());
    const int ny = static_cast<int>(blocks.y());
    const Eigen::Vector2d used(nx * pitch.x() + c_.street_width_m,
                               ny * pitch.y() + c_.street_width_m);
    origin_ = c_.area.center_m - 0.5 * used;  // south-west corner of the first street
    b_.ReserveObjects(static_cast<std::size_t>(nx * ny) * 40 + (nx + 1) * (ny + 2));

    // Streets: one slab per north-south street line, and the east-west streets cut at the
    // crossings into one slab per block, so that no two road surfaces overlap (coplanar overlaps
    // make the instance image flicker between the two from frame to frame).
    for (int i = 0; i <= nx && ok_; ++i) {
      const double n = origin_.x() + i * pitch.x() + 0.5 * c_.street_width_m;
      Place(box_,
            Slab(n, origin_.y() + 0.5 * used.y(), c_.street_width_m, used.y(), kRoadThickness_m),
            r_.road_class, "street_n" + std::to_string(i), asphalt_);
    }
    for (int j = 0; j <= ny && ok_; ++j) {
      const double e = origin_.y() + j * pitch.y() + 0.5 * c_.street_width_m;
      for (int i = 0; i < nx && ok_; ++i) {
        const double n =
            origin_.x() + i * pitch.x() + c_.street_width_m + 0.5 * c_.block_size_m.x();
        Place(box_, Slab(n, e, c_.block_size_m.x(), c_.street_width_m, kRoadThickness_m),
              r_.road_class, "street_e" + std::to_string(j) + "_" + std::to_string(i), asphalt_);
      }
    }
    for (int i = 0; i < nx && ok_; ++i) {
      for (int j = 0; j < ny && ok_; ++j) {
        const Eigen::Vector2d lo = origin_ + Eigen::Vector2d(i * pitch.x(), j * pitch.y()) +
                                   Eigen::Vector2d::Constant(c_.street_width_m);
        Block(lo, lo + c_.block_size_m, "block" + std::to_string(i) + "_" + std::to_string(j));
      }
    }
    report_.out_of_instance_ids = !ok_;
    return report_;
  }

 private:
  void MakeModels() {
    box_ = b_.PrimitiveModel(Primitive::kBox);
    // Two 3.5 m lanes and 3 m dashes every 9 m; 1.2 m paving slabs; 0.3 m tile rows.
    asphalt_ = static_cast<std::int32_t>(b_.Material(Patterned(
        {0.12, 0.12, 0.13}, "asphalt", engine::SurfacePattern::kAsphalt, {3.5f, 9.0f}, 0.85f)));
    concrete_ = static_cast<std::int32_t>(b_.Material(Patterned(
        {0.62, 0.61, 0.58}, "concrete", engine::SurfacePattern::kSidewalk, {1.2f, 1.2f}, 0.8f)));
    const std::uint32_t roof_material = b_.Material(
        Patterned(c_.roof_color, "roof", engine::SurfacePattern::kRoof, {0.3f, 0.05f}, 0.75f));
    const std::uint32_t body_mesh = b_.PrimitiveMesh(Primitive::kBox);
    const std::uint32_t gable = b_.AddMesh(engine::MakeGableRoofMesh());
    const std::uint32_t pyramid = b_.AddMesh(engine::MakePyramidRoofMesh());
    for (const RoofShape roof : {RoofShape::kFlat, RoofShape::kGabled, RoofShape::kPyramid}) {
      for (std::size_t k = 0; k < c_.building_colors.size(); ++k) {
        engine::Model m;
        m.name =
            name_ + "/building_" + std::string(engine::ToString(roof)) + "_" + std::to_string(k);
        // Storeys of 3.0 to 3.5 m and window pitches of 2.6 to 3.8 m, by colour.
        const Eigen::Vector2f storey_and_pitch(3.0f + 0.25f * static_cast<float>(k % 3),
                                               2.6f + 0.4f * static_cast<float>(k % 4));
        const std::uint32_t wall =
            b_.Material(Patterned(c_.building_colors[k], "wall", engine::SurfacePattern::kFacade,
                                  storey_and_pitch, 0.85f));
        // Walls span z in [-1, 0] so the object's z scale is the wall height; the roof sits on top.
        m.parts.push_back({body_mesh, wall, PartPose({0, 0, -0.5f}, {1, 1, 1})});
        if (roof == RoofShape::kGabled) {
          m.parts.push_back(
              {gable, roof_material, PartPose({0, 0, -1}, {1, 1, float(kGableRoofRatio)})});
        } else if (roof == RoofShape::kPyramid) {
          m.parts.push_back(
              {pyramid, roof_material, PartPose({0, 0, -1}, {1, 1, float(kPyramidRoofRatio)})});
        }
        building_models_[static_cast<int>(roof)].push_back(b_.AddModel(std::move(m)));
      }
    }
    engine::Model lamp;
    lamp.name = name_ + "/lamp_post";
    engine::Material steel_material = Colored({0.55, 0.56, 0.58}, "steel");
    steel_material.metallic = 1.0f;
    steel_material.roughness = 0.45f;
    const std::uint32_t steel = b_.Material(steel_material);
    const std::uint32_t glass = b_.Material(Colored({1.0, 0.95, 0.8}, "lamp"));
    lamp.parts.push_back(
        {b_.PrimitiveMesh(Primitive::kCylinder), steel,
         PartPose({0, 0, float(-0.5 * kLampHeight_m)}, {0.15f, 0.15f, float(kLampHeight_m)})});
    lamp.parts.push_back({b_.PrimitiveMesh(Primitive::kSphere), glass,
                          PartPose({0, 0, float(-kLampHeight_m - 0.1)}, {0.5f, 0.5f, 0.4f})});
    lamp_model_ = b_.AddModel(std::move(lamp));
    if (r_.car_model) {
      car_model_ = *r_.car_model;
    } else {
      engine::Model car;
      car.name = name_ + "/car";
      const std::uint32_t box_mesh = b_.PrimitiveMesh(Primitive::kBox);
      car.parts.push_back(
          {box_mesh, 0, PartPose({0, 0, -0.65f}, {float(kCarLength_m), 1.8f, 0.9f})});
      car.parts.push_back({box_mesh, 0, PartPose({-0.2f, 0, -1.4f}, {2.3f, 1.6f, 0.6f})});
      car_model_ = b_.AddModel(std::move(car));
      const Eigen::Vector3d palette[] = {
          {0.8, 0.1, 0.1}, {0.1, 0.2, 0.6}, {0.85, 0.85, 0.85}, {0.1, 0.1, 0.1}, {0.5, 0.5, 0.52}};
      // Car paint: metallic flakes in the pigment under a clear coat (the car_paint pattern).
      for (const auto& rgb : palette) {
        engine::Material paint = Colored(rgb, "car");
        paint.pattern = engine::SurfacePattern::kCarPaint;
        paint.roughness = 0.4f;
        paint.metallic = 0.3f;
        car_colors_.push_back(static_cast<std::int32_t>(b_.Material(paint)));
      }
    }
  }

  /// A flat slab centred at (n, e) with its top `thickness` above the ground.
  Eigen::Affine3d Slab(double n, double e, double size_n, double size_e, double thickness) const {
    return engine::MakePose(Vector3d(n, e, -0.5 * thickness), 0, 0, 0,
                            Vector3d(size_n, size_e, thickness));
  }

  void Place(std::uint32_t model, const Eigen::Affine3d& T, std::uint8_t cls,
             const std::string& what, std::int32_t material = -1) {
    if (!ok_) return;
    ok_ = b_.AddObject(model, T, cls, CollisionShape::kAuto, name_ + "/" + what, material);
    if (ok_) ++report_.objects;
  }

  void Block(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, const std::string& id) {
    const double w = c_.sidewalk_width_m;
    const Eigen::Vector2d size = hi - lo;
    // Sidewalks: four kerb-high strips around the block.
    if (w > 0.0) {
      Place(box_, Slab(lo.x() + 0.5 * w, lo.y() + 0.5 * size.y(), w, size.y(), kKerbHeight_m),
            r_.sidewalk_class, id + "/sidewalk_s", concrete_);
      Place(box_, Slab(hi.x() - 0.5 * w, lo.y() + 0.5 * size.y(), w, size.y(), kKerbHeight_m),
            r_.sidewalk_class, id + "/sidewalk_n", concrete_);
      Place(box_,
            Slab(lo.x() + 0.5 * size.x(), lo.y() + 0.5 * w, size.x() - 2 * w, w, kKerbHeight_m),
            r_.sidewalk_class, id + "/sidewalk_w", concrete_);
      Place(box_,
            Slab(lo.x() + 0.5 * size.x(), hi.y() - 0.5 * w, size.x() - 2 * w, w, kKerbHeight_m),
            r_.sidewalk_class, id + "/sidewalk_e", concrete_);
    }
    Buildings(lo + Eigen::Vector2d::Constant(w), hi - Eigen::Vector2d::Constant(w), id);
    if (c_.lamp_spacing_m > 0.0) Lamps(lo, hi, id);
    if (c_.cars_per_100m > 0.0) Cars(lo, hi, id);
  }

  void Buildings(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, const std::string& id) {
    const Eigen::Vector2d inner = hi - lo;
    if (inner.minCoeff() <= 1.0) return;
    const int lx = std::max(1, static_cast<int>(inner.x() / c_.lot_size_m.x()));
    const int ly = std::max(1, static_cast<int>(inner.y() / c_.lot_size_m.y()));
    const Eigen::Vector2d lot(inner.x() / lx, inner.y() / ly);
    for (int i = 0; i < lx; ++i) {
      for (int j = 0; j < ly; ++j) {
        // Draw every number for every lot, used or not, so one lot's choices never shift the
        // next's.
        const double present = rng_.Uniform01();
        const double fill_n = Lerp(c_.footprint_fill, rng_.Uniform01());
        const double fill_e = Lerp(c_.footprint_fill, rng_.Uniform01());
        const double slide_n = rng_.Uniform01(), slide_e = rng_.Uniform01();
        const double low = Lerp(c_.low_height_m, rng_.Uniform01());
        const double tall = Lerp(c_.tall_height_m, rng_.Uniform01());
        const std::int64_t roof_pick =
            rng_.UniformInt(0, static_cast<std::int64_t>(c_.roof_shapes.size()) - 1);
        const std::int64_t color_pick =
            rng_.UniformInt(0, static_cast<std::int64_t>(c_.building_colors.size()) - 1);
        if (present >= c_.building_probability) continue;
        const Eigen::Vector2d footprint(lot.x() * fill_n, lot.y() * fill_e);
        const Eigen::Vector2d lot_lo = lo + Eigen::Vector2d(i * lot.x(), j * lot.y());
        const Eigen::Vector2d centre = lot_lo + 0.5 * footprint +
                                       Eigen::Vector2d(slide_n * (lot.x() - footprint.x()),
                                                       slide_e * (lot.y() - footprint.y()));
        // Downtown weighting: towers near the centre, houses far out (Gaussian fade).
        const double d = (centre - c_.downtown_center_m).norm() / c_.downtown_radius_m;
        const double weight = std::exp(-d * d);
        const double height = (1.0 - weight) * low + weight * tall;
        const RoofShape roof =
            height > c_.flat_roof_above_m ? RoofShape::kFlat : c_.roof_shapes[roof_pick];
        const std::uint32_t model = building_models_[static_cast<int>(roof)][color_pick];
        Place(model,
              engine::MakePose(Vector3d(centre.x(), centre.y(), 0.0), 0, 0, 0,
                               Vector3d(footprint.x(), footprint.y(), height)),
              r_.building_class, id + "/building" + std::to_string(i) + "_" + std::to_string(j));
        if (ok_) ++report_.buildings;
      }
    }
  }

  void Lamps(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, const std::string& id) {
    const double inset = 0.5;  // from the kerb
    const Eigen::Vector2d a = lo + Eigen::Vector2d::Constant(inset);
    const Eigen::Vector2d b = hi - Eigen::Vector2d::Constant(inset);
    int k = 0;
    auto along = [&](const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
      const double length = (to - from).norm();
      const int count = static_cast<int>(length / c_.lamp_spacing_m);
      for (int s = 0; s < count; ++s) {
        const Eigen::Vector2d p = from + (to - from) * ((s + 0.5) / count);
        Place(lamp_model_,
              engine::MakePose(Vector3d(p.x(), p.y(), -kKerbHeight_m), 0, 0, 0, Vector3d::Ones()),
              r_.lamp_class, id + "/lamp" + std::to_string(k++));
      }
    };
    along({a.x(), a.y()}, {b.x(), a.y()});
    along({b.x(), a.y()}, {b.x(), b.y()});
    along({b.x(), b.y()}, {a.x(), b.y()});
    along({a.x(), b.y()}, {a.x(), a.y()});
  }

  void Cars(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, const std::string& id) {
    const double lane = 1.2;  // car centre from the kerb
    int k = 0;
    // Each side of the block: kerb line from `from` to `to`, cars parked along it in the street.
    auto side = [&](const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                    const Eigen::Vector2d& out) {
      const double length = (to - from).norm();
      const int slots = static_cast<int>(length / (kCarLength_m + 1.5));
      const double p_car = std::min(1.0, c_.cars_per_100m * length / 100.0 / std::max(slots, 1));
      const Eigen::Vector2d dir = (to - from) / length;
      const double yaw = std::atan2(dir.y(), dir.x());
      for (int s = 0; s < slots; ++s) {
        const double u = rng_.Uniform01();
        const double flip = rng_.Uniform01();
        const std::int64_t color =
            car_colors_.empty() ? 0 : rng_.UniformInt(0, car_colors_.size() - 1);
        if (u >= p_car) continue;
        const Eigen::Vector2d p = from + dir * ((s + 0.5) * length / slots) + out * lane;
        Place(car_model_,
              engine::MakePose(Vector3d(p.x(), p.y(), 0.0),
                               yaw + (flip < 0.5 ? 0.0 : std::numbers::pi), 0, 0, Vector3d::Ones()),
              r_.car_class, id + "/car" + std::to_string(k++),
              car_colors_.empty() ? -1 : car_colors_[color]);
      }
    };
    side({lo.x(), lo.y()}, {hi.x(), lo.y()}, {0, -1});
    side({hi.x(), lo.y()}, {hi.x(), hi.y()}, {1, 0});
    side({hi.x(), hi.y()}, {lo.x(), hi.y()}, {0, 1});
    side({lo.x(), hi.y()}, {lo.x(), lo.y()}, {-1, 0});
  }

  const CityConfig& c_;
  const CityResources& r_;
  const std::string& name_;
  engine::RandomStream& rng_;
  engine::StaticSceneBuilder& b_;
  GeneratorReport report_;
  bool ok_ = true;
  Eigen::Vector2d origin_;
  std::uint32_t box_ = 0, lamp_model_ = 0, car_model_ = 0;
  std::int32_t asphalt_ = -1, concrete_ = -1;
  std::vector<std::uint32_t> building_models_[3];
  std::vector<std::int32_t> car_colors_;
};

}  // namespace

Eigen::Vector2d CalcCityBlockCounts(const CityConfig& c) {
  const Eigen::Vector2d pitch = c.block_size_m + Eigen::Vector2d::Constant(c.street_width_m);
  const Eigen::Vector2d size = c.area.size_m;
  return {std::max(1.0, std::floor((size.x() - c.street_width_m) / pitch.x())),
          std::max(1.0, std::floor((size.y() - c.street_width_m) / pitch.y()))};
}

GeneratorReport GenerateCity(const CityConfig& config, const CityResources& resources,
                             const std::string& name, engine::RandomStream& stream,
                             engine::StaticSceneBuilder& builder) {
  return CityBuilder(config, resources, name, stream, builder).Build();
}

}  // namespace airis::scenes
