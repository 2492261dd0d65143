#include "engine/scene/model_levels.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

#include "engine/core/error.h"
#include "engine/scene/primitive_meshes.h"

namespace airis::engine {
namespace {

constexpr int kLevelSegments[] = {18, 14, 12, 10, 8, 6, 5, 4, 3};
// A part narrower than this fraction of its model's largest extent is thin.
constexpr double kThinFraction = 0.1;

bool IsRound(Primitive p) {
  return p == Primitive::kSphere || p == Primitive::kCylinder || p == Primitive::kCone;
}

// How much T enlarges the tessellation error of `primitive`: its largest scale, across the axis
// for a cylinder or cone (whose sides are exact along it).
double ErrorScale(Primitive primitive, const Eigen::Affine3f& T) {
  const Eigen::Matrix3f L = T.linear();
  const double across = std::max(L.col(0).norm(), L.col(1).norm());
  return primitive == Primitive::kSphere ? std::max<double>(across, L.col(2).norm()) : across;
}

// The width of `mesh` placed by T: the middle of its three extents (a pole's or a trunk's
// thickness; a plate, wide in two directions, is not narrow).
double Width_m(const TriangleMesh& mesh, const Eigen::Affine3f& T) {
  if (mesh.bounds.isEmpty()) return 0.0;
  const Eigen::Vector3f size = mesh.bounds.sizes();
  const Eigen::Matrix3f L = T.linear();
  std::array<double, 3> extent;
  for (int a = 0; a < 3; ++a) extent[a] = size[a] * L.col(a).norm();
  std::sort(extent.begin(), extent.end());
  return extent[1];
}

}  // namespace

double CalcTessellationError_m(const TriangleMesh& mesh, Primitive primitive, int segments) {
  AIRIS_DEMAND(IsRound(primitive) && segments >= 3);
  if (primitive != Primitive::kSphere) {
    // The sides are flat between points on the circle of radius 0.5.
    return 0.5 * (1.0 - std::cos(std::numbers::pi / segments));
  }
  // Every vertex is on the sphere: a face is nowhere farther inside than its plane.
  double nearest_plane = 0.5;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const Vec3 a = mesh.positions[mesh.indices[t]].cast<double>();
    const Vec3 b = mesh.positions[mesh.indices[t + 1]].cast<double>();
    const Vec3 c = mesh.positions[mesh.indices[t + 2]].cast<double>();
    const Vec3 n = (b - a).cross(c - a);
    if (n.norm() == 0.0) continue;
    nearest_plane = std::min(nearest_plane, std::abs(n.normalized().dot(a)));
  }
  return 0.5 - nearest_plane;
}

CoarsePrimitiveMesh MakeCoarsePrimitiveMesh(Primitive primitive, int segments) {
  CoarsePrimitiveMesh coarse{MakePrimitiveMesh(primitive, segments), 0.0};
  const double inscribed = CalcTessellationError_m(coarse.mesh, primitive, segments);
  // Widened by s = 1 / (1 - e), the faces' nearest points are at (0.5 - e) s and the vertices at
  // 0.5 s from the axis (the centre): both 0.5 e / (1 - e) off the radius 0.5.
  const float s = static_cast<float>(1.0 / (1.0 - inscribed));
  const Eigen::Vector3f widen(s, s, primitive == Primitive::kSphere ? s : 1.0f);
  for (Eigen::Vector3f& p : coarse.mesh.positions) p = p.cwiseProduct(widen);
  // Normals go with the inverse transpose (a cone's sides get steeper).
  for (Eigen::Vector3f& n : coarse.mesh.normals) n = n.cwiseQuotient(widen).normalized();
  UpdateBounds(coarse.mesh);
  coarse.error_m = 0.5 * inscribed / (1.0 - inscribed);
  return coarse;
}

void AddCoarserLevels(StaticScene& scene) {
  // The coarse tessellations, made once per (primitive, segments), and their errors.
  std::map<std::pair<Primitive, int>, std::pair<std::uint32_t, double>> coarse;
  const auto coarse_mesh = [&](Primitive p, int segments) {
    if (p == Primitive::kSphere) segments = std::max(segments, 4);
    auto [it, inserted] = coarse.try_emplace({p, segments});
    if (inserted) {
      CoarsePrimitiveMesh made = MakeCoarsePrimitiveMesh(p, segments);
      it->second = {static_cast<std::uint32_t>(scene.meshes.size()), made.error_m};
      scene.meshes.push_back(std::move(made.mesh));
    }
    return it->second;
  };
  // A round mesh is the builder's tessellation of its primitive: the same triangle count.
  std::map<Primitive, std::size_t> round_triangles;
  for (Primitive p : {Primitive::kSphere, Primitive::kCylinder, Primitive::kCone}) {
    round_triangles[p] = MakePrimitiveMesh(p).triangle_count();
  }
  const std::size_t own_meshes = scene.meshes.size();
  const auto is_round = [&](std::uint32_t mesh) {
    const TriangleMesh& m = scene.meshes[mesh];
    return IsRound(m.primitive) && m.triangle_count() == round_triangles[m.primitive];
  };
  for (Model& model : scene.models) {
    if (!model.levels.empty() || model.parts.empty() || model.bounds.isEmpty()) continue;
    // The model's width: the middle of its three extents.
    std::array<double, 3> extent = {model.bounds.sizes().x(), model.bounds.sizes().y(),
                                    model.bounds.sizes().z()};
    std::sort(extent.begin(), extent.end());
    const double largest = model.bounds.sizes().maxCoeff();
    std::vector<bool> thin(model.parts.size(), false);
    bool any_round = false, any_thin = false, any_thick = false;
    for (std::size_t i = 0; i < model.parts.size(); ++i) {
      const ModelPart& part = model.parts[i];
      AIRIS_DEMAND(part.mesh < own_meshes);
      any_round = any_round || is_round(part.mesh);
      thin[i] = Width_m(scene.meshes[part.mesh], part.T_MP) < kThinFraction * largest;
      any_thin = any_thin || thin[i];
      any_thick = any_thick || !thin[i];
    }
    std::vector<ModelPart> parts = model.parts;
    double error_m = 0.0;
    if (any_round) {
      for (int segments : kLevelSegments) {
        for (std::size_t i = 0; i < parts.size(); ++i) {
          if (!is_round(model.parts[i].mesh)) continue;
          const Primitive primitive = scene.meshes[model.parts[i].mesh].primitive;
          const auto [mesh, unit_error] = coarse_mesh(primitive, segments);
          parts[i].mesh = mesh;
          error_m = std::max(error_m, unit_error * ErrorScale(primitive, parts[i].T_MP));
        }
        // A sphere's 3 segments are its 4: the same look again.
        const bool same =
            !model.levels.empty() &&
            std::equal(parts.begin(), parts.end(), model.levels.back().parts.begin(),
                       [](const ModelPart& a, const ModelPart& b) { return a.mesh == b.mesh; });
        if (!same) model.levels.push_back({parts, static_cast<float>(error_m)});
      }
    }
    if (any_thin && any_thick) {
      std::vector<ModelPart> kept;
      for (std::size_t i = 0; i < parts.size(); ++i) {
        if (!thin[i]) {
          kept.push_back(parts[i]);
        } else {
          error_m =
              std::max(error_m, Width_m(scene.meshes[model.parts[i].mesh], model.parts[i].T_MP));
        }
      }
      model.levels.push_back({std::move(kept), static_cast<float>(error_m)});
    }
    // Last, nothing: a model narrower than the tolerance is a thread at most.
    model.levels.push_back({{}, static_cast<float>(std::max(error_m, extent[1]))});
  }
}

}  // namespace airis::engine
