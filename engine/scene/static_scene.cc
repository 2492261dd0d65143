#include "engine/scene/static_scene.h"

#include <array>

namespace airis::engine {

namespace {
constexpr EnumName<Primitive> kPrimitiveNames[] = {
    {Primitive::kNone, "none"},         {Primitive::kBox, "box"},   {Primitive::kSphere, "sphere"},
    {Primitive::kCylinder, "cylinder"}, {Primitive::kCone, "cone"}, {Primitive::kPlane, "plane"}};
constexpr EnumName<CollisionShape> kCollisionShapeNames[] = {
    {CollisionShape::kAuto, "auto"},
    {CollisionShape::kNone, "none"},
    {CollisionShape::kBox, "box"},
    {CollisionShape::kConvexHull, "convex_hull"},
    {CollisionShape::kTriangleMesh, "triangle_mesh"}};
}  // namespace

std::span<const EnumName<Primitive>> EnumNames(Primitive) { return kPrimitiveNames; }
std::span<const EnumName<CollisionShape>> EnumNames(CollisionShape) { return kCollisionShapeNames; }

std::span<const EnumName<SkyModel>> EnumNames(SkyModel) {
  static constexpr std::array<EnumName<SkyModel>, 3> kNames{{
      {SkyModel::kGradient, "gradient"},
      {SkyModel::kClear, "clear"},
      {SkyModel::kOvercast, "overcast"},
  }};
  return kNames;
}

std::span<const EnumName<SurfacePattern>> EnumNames(SurfacePattern) {
  static constexpr std::array<EnumName<SurfacePattern>, kSurfacePatterns> kNames{{
      {SurfacePattern::kPlain, "plain"},
      {SurfacePattern::kFacade, "facade"},
      {SurfacePattern::kRoof, "roof"},
      {SurfacePattern::kAsphalt, "asphalt"},
      {SurfacePattern::kSidewalk, "sidewalk"},
      {SurfacePattern::kGrass, "grass"},
      {SurfacePattern::kSoil, "soil"},
      {SurfacePattern::kRock, "rock"},
      {SurfacePattern::kBark, "bark"},
      {SurfacePattern::kFoliage, "foliage"},
      {SurfacePattern::kCarPaint, "car_paint"},
  }};
  return kNames;
}

Material MakePatternedMaterial(std::string name, const Eigen::Vector3f& rgb, SurfacePattern pattern,
                               const Eigen::Vector2f& size_m, float roughness) {
  Material m;
  m.name = std::move(name);
  m.base_color_rgb = rgb;
  m.roughness = roughness;
  m.pattern = pattern;
  m.pattern_size_m = size_m;
  return m;
}

const SemanticClass* StaticScene::FindClass(std::uint8_t id) const {
  for (const auto& c : classes) {
    if (c.id == id) return &c;
  }
  return nullptr;
}

Eigen::AlignedBox3d StaticScene::ObjectBounds(std::size_t index) const {
  const StaticObject& o = objects[index];
  const Eigen::AlignedBox3f& b = models[o.model].bounds;
  Eigen::AlignedBox3d out;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d c =
        b.corner(static_cast<Eigen::AlignedBox3f::CornerType>(corner)).cast<double>();
    out.extend(o.T_WO * c);
  }
  return out;
}

std::size_t StaticScene::CountDrawnTriangles() const {
  std::size_t n = 0;
  for (const auto& o : objects) {
    for (const auto& part : models[o.model].parts) n += meshes[part.mesh].triangle_count();
  }
  return n;
}

}  // namespace airis::engine
