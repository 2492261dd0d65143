#include "engine/scene/primitive_meshes.h"

#include <cmath>
#include <numbers>

#include "engine/core/error.h"

namespace airis::engine {

using Eigen::Vector2f;
using Eigen::Vector3f;

namespace {

/// Appends a vertex and returns its index.
std::uint32_t AddVertex(TriangleMesh& m, const Vector3f& p, const Vector3f& n, const Vector2f& uv) {
  m.positions.push_back(p);
  m.normals.push_back(n);
  m.uvs.push_back(uv);
  return static_cast<std::uint32_t>(m.positions.size() - 1);
}

/// Appends triangle (a, b, c), flipped if needed so that it winds counter-clockwise seen from the
/// side `outward` points to. Orienting by construction check keeps every generator free of winding
/// slips.
void AddTriangle(TriangleMesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                 const Vector3f& outward) {
  const Vector3f n = (m.positions[b] - m.positions[a]).cross(m.positions[c] - m.positions[a]);
  if (n.dot(outward) < 0.0f) std::swap(b, c);
  m.indices.insert(m.indices.end(), {a, b, c});
}

/// A flat polygon face (convex, corners in order) with one normal.
void AddFace(TriangleMesh& m, std::initializer_list<Vector3f> corners, const Vector3f& normal) {
  const std::uint32_t first = static_cast<std::uint32_t>(m.positions.size());
  int i = 0;
  for (const Vector3f& c : corners) {
    // Planar projection for texture coordinates: the two axes the normal is least aligned with.
    const Vector3f a = normal.cwiseAbs();
    Vector2f uv;
    if (a.z() >= a.x() && a.z() >= a.y()) {
      uv = Vector2f(c.x() + 0.5f, c.y() + 0.5f);
    } else if (a.x() >= a.y()) {
      uv = Vector2f(c.y() + 0.5f, -c.z() + 0.5f);
    } else {
      uv = Vector2f(c.x() + 0.5f, -c.z() + 0.5f);
    }
    AddVertex(m, c, normal, uv);
    ++i;
  }
  for (int k = 1; k + 1 < i; ++k) {
    AddTriangle(m, first, first + k, first + k + 1, normal);
  }
}

TriangleMesh MakeBox() {
  TriangleMesh m;
  const float h = 0.5f;
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {-1.0f, 1.0f}) {
      Vector3f n = Vector3f::Zero();
      n[axis] = sign;
      const int u = (axis + 1) % 3;
      const int v = (axis + 2) % 3;
      Vector3f c[4];
      const float du[4] = {-h, h, h, -h};
      const float dv[4] = {-h, -h, h, h};
      for (int k = 0; k < 4; ++k) {
        c[k] = n * h;
        c[k][u] = du[k];
        c[k][v] = dv[k];
      }
      AddFace(m, {c[0], c[1], c[2], c[3]}, n);
    }
  }
  return m;
}

TriangleMesh MakeSphere(int segments) {
  TriangleMesh m;
  const int rings = segments / 2;
  for (int r = 0; r <= rings; ++r) {
    const float theta =
        std::numbers::pi_v<float> * static_cast<float>(r) / rings;  // from -z (up) down
    for (int s = 0; s <= segments; ++s) {
      const float phi = 2.0f * std::numbers::pi_v<float> * static_cast<float>(s) / segments;
      const Vector3f n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                       -std::cos(theta));
      AddVertex(m, 0.5f * n, n,
                Vector2f(static_cast<float>(s) / segments, static_cast<float>(r) / rings));
    }
  }
  const int row = segments + 1;
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const std::uint32_t a = r * row + s, b = a + 1, c = a + row, d = c + 1;
      const Vector3f out = (m.positions[a] + m.positions[d]);
      if (r > 0) AddTriangle(m, a, b, d, out);
      if (r + 1 < rings) AddTriangle(m, a, d, c, out);
    }
  }
  return m;
}

/// Side of a cylinder (top_radius = bottom_radius) or cone (top_radius = 0 at z = -0.5), plus caps.
TriangleMesh MakeRound(float top_radius, float bottom_radius, int segments) {
  TriangleMesh m;
  const float slope = bottom_radius - top_radius;  // radial normal tilt over unit height
  for (int s = 0; s <= segments; ++s) {
    const float phi = 2.0f * std::numbers::pi_v<float> * static_cast<float>(s) / segments;
    const Vector3f radial(std::cos(phi), std::sin(phi), 0.0f);
    // Side normal: perpendicular to the slant line, pointing out and (for a cone) up (-z).
    const Vector3f n = (radial - Vector3f(0, 0, slope)).normalized();
    const float u = static_cast<float>(s) / segments;
    AddVertex(m, top_radius * radial + Vector3f(0, 0, -0.5f), n, Vector2f(u, 0.0f));
    AddVertex(m, bottom_radius * radial + Vector3f(0, 0, 0.5f), n, Vector2f(u, 1.0f));
  }
  for (int s = 0; s < segments; ++s) {
    const std::uint32_t t0 = 2 * s, b0 = t0 + 1, t1 = t0 + 2, b1 = t0 + 3;
    const Vector3f out = m.positions[b0] + m.positions[b1] + m.positions[t0] + m.positions[t1];
    const Vector3f outward(out.x(), out.y(), 0.0f);
    if (top_radius > 0.0f) AddTriangle(m, t0, t1, b1, outward);
    AddTriangle(m, t0, b1, b0, outward);
  }
  for (float z : {-0.5f, 0.5f}) {
    const float radius = z < 0.0f ? top_radius : bottom_radius;
    if (radius <= 0.0f) continue;
    const Vector3f n(0, 0, z < 0.0f ? -1.0f : 1.0f);
    const std::uint32_t centre = AddVertex(m, Vector3f(0, 0, z), n, Vector2f(0.5f, 0.5f));
    for (int s = 0; s <= segments; ++s) {
      const float phi = 2.0f * std::numbers::pi_v<float> * static_cast<float>(s) / segments;
      const Vector3f radial(std::cos(phi), std::sin(phi), 0.0f);
      AddVertex(m, radius * radial + Vector3f(0, 0, z), n,
                Vector2f(0.5f + 0.5f * radial.x(), 0.5f + 0.5f * radial.y()));
    }
    for (int s = 0; s < segments; ++s) {
      AddTriangle(m, centre, centre + 1 + s, centre + 2 + s, n);
    }
  }
  return m;
}

TriangleMesh MakePlane() {
  TriangleMesh m;
  AddFace(m,
          {Vector3f(-0.5f, -0.5f, 0), Vector3f(0.5f, -0.5f, 0), Vector3f(0.5f, 0.5f, 0),
           Vector3f(-0.5f, 0.5f, 0)},
          Vector3f(0, 0, -1));
  return m;
}

}  // namespace

void UpdateBounds(TriangleMesh& mesh) {
  mesh.bounds.setEmpty();
  for (const Vector3f& p : mesh.positions) mesh.bounds.extend(p);
}

TriangleMesh MakePrimitiveMesh(Primitive primitive, int segments) {
  AIRIS_DEMAND(segments >= 3);
  TriangleMesh m;
  switch (primitive) {
    case Primitive::kBox:
      m = MakeBox();
      break;
    case Primitive::kSphere:
      m = MakeSphere(segments);
      break;
    case Primitive::kCylinder:
      m = MakeRound(0.5f, 0.5f, segments);
      break;
    case Primitive::kCone:
      m = MakeRound(0.0f, 0.5f, segments);
      break;
    case Primitive::kPlane:
      m = MakePlane();
      break;
    case Primitive::kNone:
      AIRIS_DEMAND(primitive != Primitive::kNone);
  }
  m.primitive = primitive;
  m.name = "primitive:" + std::string(ToString(primitive));
  UpdateBounds(m);
  return m;
}

TriangleMesh MakeGableRoofMesh() {
  TriangleMesh m;
  const float h = 0.5f;
  const Vector3f a(-h, -h, 0), b(h, -h, 0), c(h, h, 0), d(-h, h, 0);
  const Vector3f r0(-h, 0, -1), r1(h, 0, -1);
  AddFace(m, {a, b, c, d}, Vector3f(0, 0, 1));                      // base (facing down)
  AddFace(m, {a, b, r1, r0}, Vector3f(0, -1, -0.5f).normalized());  // west slope
  AddFace(m, {d, c, r1, r0}, Vector3f(0, 1, -0.5f).normalized());   // east slope
  AddFace(m, {a, d, r0}, Vector3f(-1, 0, 0));                       // gable ends
  AddFace(m, {b, c, r1}, Vector3f(1, 0, 0));
  m.name = "generated:gable_roof";
  UpdateBounds(m);
  return m;
}

TriangleMesh MakePyramidRoofMesh() {
  TriangleMesh m;
  const float h = 0.5f;
  const Vector3f a(-h, -h, 0), b(h, -h, 0), c(h, h, 0), d(-h, h, 0), apex(0, 0, -1);
  AddFace(m, {a, b, c, d}, Vector3f(0, 0, 1));
  AddFace(m, {a, b, apex}, Vector3f(0, -1, -0.5f).normalized());
  AddFace(m, {b, c, apex}, Vector3f(1, 0, -0.5f).normalized());
  AddFace(m, {c, d, apex}, Vector3f(0, 1, -0.5f).normalized());
  AddFace(m, {d, a, apex}, Vector3f(-1, 0, -0.5f).normalized());
  m.name = "generated:pyramid_roof";
  UpdateBounds(m);
  return m;
}

}  // namespace airis::engine
