#include "scenes/scene_stats.h"

#include <map>

namespace airis::scenes {

namespace {

template <class T>
std::size_t VectorBytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

/// Heap bytes of a string beyond its inline (small-string) buffer.
std::size_t StringBytes(const std::string& s) {
  return s.capacity() > std::string().capacity() ? s.capacity() + 1 : 0;
}

}  // namespace

std::size_t EstimateMemoryBytes(const engine::StaticScene& s) {
  std::size_t bytes = VectorBytes(s.meshes) + VectorBytes(s.materials) + VectorBytes(s.models) +
                      VectorBytes(s.objects) + VectorBytes(s.vehicle_bodies) +
                      VectorBytes(s.classes);
  for (const auto& m : s.meshes) {
    bytes += VectorBytes(m.positions) + VectorBytes(m.normals) + VectorBytes(m.uvs) +
             VectorBytes(m.indices) + StringBytes(m.name);
  }
  for (const auto& m : s.materials) bytes += StringBytes(m.name) + StringBytes(m.texture_path);
  for (const auto& [name, image] : s.embedded_images)
    bytes += StringBytes(name) + StringBytes(image);
  for (const auto& m : s.models) bytes += VectorBytes(m.parts) + StringBytes(m.name);
  for (const auto& o : s.objects) bytes += StringBytes(o.name);
  for (const auto& b : s.vehicle_bodies) bytes += StringBytes(b.name);
  for (const auto& c : s.classes) bytes += StringBytes(c.name);
  return bytes;
}

SceneStats CalcSceneStats(const Scene& scene) {
  const engine::StaticScene& s = *scene.static_scene;
  SceneStats out;
  std::map<std::uint8_t, std::size_t> per_class;
  out.bounds_W.setEmpty();
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    ++per_class[s.objects[i].class_id];
    out.bounds_W.extend(s.ObjectBounds(i));
  }
  for (const auto& [id, count] : per_class) {
    const engine::SemanticClass* c = s.FindClass(id);
    out.classes.push_back({id, c ? c->name : "?", count});
  }
  out.objects = s.objects.size();
  out.models = s.models.size();
  out.meshes = s.meshes.size();
  out.materials = s.materials.size();
  for (const auto& m : s.meshes) out.stored_triangles += m.triangle_count();
  out.drawn_triangles = s.CountDrawnTriangles();
  out.vehicles = scene.vehicles.size();
  out.memory_bytes = EstimateMemoryBytes(s);
  return out;
}

}  // namespace airis::scenes
