#include "engine/world/embree_ray_caster.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "engine/core/error.h"

namespace airis::engine {

namespace {

// Rays traced per rtcIntersect1M call: large enough for Embree's stream tracer to form coherent
// packets, small enough to live on the stack (256 * 80 bytes).
constexpr std::size_t kBatch = 256;

std::string DeviceErrorText(RTCDevice device) {
  switch (rtcGetDeviceError(device)) {
    case RTC_ERROR_NONE:
      return "no error";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION:
      return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "unsupported CPU";
    case RTC_ERROR_CANCELLED:
      return "cancelled";
    default:
      return "unknown error";
  }
}

void Check(RTCDevice device, bool ok, const char* what) {
  if (!ok)
    throw std::runtime_error(std::string("EmbreeRayCaster: ") + what + ": " +
                             DeviceErrorText(device));
}

void CheckIndices(const TriangleMesh& mesh) {
  if (mesh.indices.size() % 3 != 0) {
    throw std::invalid_argument("EmbreeRayCaster: mesh '" + mesh.name +
                                "' has an index count that is not a multiple of 3");
  }
  for (std::uint32_t index : mesh.indices) {
    if (index >= mesh.positions.size()) {
      throw std::invalid_argument("EmbreeRayCaster: mesh '" + mesh.name + "' has index " +
                                  std::to_string(index) + " beyond its " +
                                  std::to_string(mesh.positions.size()) + " positions");
    }
  }
}

RTCScene NewScene(RTCDevice device) {
  RTCScene scene = rtcNewScene(device);
  Check(device, scene != nullptr, "rtcNewScene");
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  return scene;
}

// Attaches the triangles of `mesh`, placed by `T` (mesh -> the scene's frame), to `scene` as
// geometry `id`; a mesh without triangles attaches nothing.
void AttachMesh(RTCDevice device, RTCScene scene, const TriangleMesh& mesh,
                const Eigen::Affine3f& T, unsigned id) {
  CheckIndices(mesh);
  if (mesh.triangle_count() == 0) return;
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               mesh.positions.size()));
  auto* triangles = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(unsigned), mesh.triangle_count()));
  Check(device, vertices != nullptr && triangles != nullptr, "rtcSetNewGeometryBuffer");
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const Eigen::Vector3f p = T * mesh.positions[i];
    vertices[3 * i + 0] = p.x();
    vertices[3 * i + 1] = p.y();
    vertices[3 * i + 2] = p.z();
  }
  std::copy(mesh.indices.begin(), mesh.indices.end(), triangles);
  rtcCommitGeometry(geometry);
  rtcAttachGeometryByID(scene, geometry, id);
  rtcReleaseGeometry(geometry);
}

}  // namespace

EmbreeRayCaster::EmbreeRayCaster(const StaticScene& scene) {
  device_ = rtcNewDevice(nullptr);
  if (device_ == nullptr) {
    throw std::runtime_error("EmbreeRayCaster: rtcNewDevice failed: " + DeviceErrorText(nullptr));
  }
  try {
    top_ = NewScene(device_);
    mesh_scenes_.assign(scene.meshes.size(), nullptr);
    model_scenes_.assign(scene.models.size(), nullptr);
    model_first_part_.assign(scene.models.size(), kNoParts);
    reflectivities_.reserve(scene.materials.size());
    for (const Material& m : scene.materials) reflectivities_.push_back(m.base_color_rgb.mean());
    instances_.reserve(static_cast<std::size_t>(
        std::count_if(scene.objects.begin(), scene.objects.end(),
                      [](const StaticObject& o) { return o.collision != CollisionShape::kNone; })));

    for (const StaticObject& object : scene.objects) {
      if (object.collision == CollisionShape::kNone) continue;
      if (object.model >= scene.models.size()) {
        throw std::invalid_argument("EmbreeRayCaster: object '" + object.name + "' names model " +
                                    std::to_string(object.model) + " of " +
                                    std::to_string(scene.models.size()));
      }
      const Model& model = scene.models[object.model];
      if (model.parts.empty()) continue;
      if (object.material_override >= 0 &&
          static_cast<std::size_t>(object.material_override) >= scene.materials.size()) {
        throw std::invalid_argument("EmbreeRayCaster: object '" + object.name +
                                    "' names material " + std::to_string(object.material_override) +
                                    " of " + std::to_string(scene.materials.size()));
      }
      // The model's parts, once: their materials, and for a model of several parts one scene
      // holding them all in the model frame (an object is then one instance, not one a part).
      std::uint32_t& first_part = model_first_part_[object.model];
      if (first_part == kNoParts) first_part = AddModelParts(scene, model);
      const bool one_part = model.parts.size() == 1;
      const Eigen::Affine3f T_WO = object.T_WO.cast<float>();
      const Eigen::Affine3f T_WI = one_part ? Eigen::Affine3f(T_WO * model.parts[0].T_MP) : T_WO;
      // Part -> world, or model -> world, in float as Embree stores it (column-major 3x4).
      float transform[12];
      for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 3; ++r) transform[3 * c + r] = T_WI.matrix()(r, c);
      }
      RTCGeometry instance = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
      rtcSetGeometryInstancedScene(
          instance, one_part ? mesh_scenes_[model.parts[0].mesh] : model_scenes_[object.model]);
      rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, transform);
      rtcCommitGeometry(instance);
      const unsigned geometry_id = rtcAttachGeometry(top_, instance);
      rtcReleaseGeometry(instance);
      Check(device_, geometry_id == instances_.size(), "instance ids are not consecutive");

      InstanceInfo info;
      info.class_id = object.class_id;
      info.instance_id = object.instance_id;
      info.material_override = object.material_override;
      info.first_part = first_part;
      // Embree reports an instance hit's normal in the instanced scene's space (RTCHit: "geometry
      // normal in object space"); normals map to the world by the inverse transpose of the linear
      // part.
      info.normal_to_W = T_WI.linear().inverse().transpose();
      instances_.push_back(info);
    }
    rtcCommitScene(top_);
    Check(device_, rtcGetDeviceError(device_) == RTC_ERROR_NONE, "committing the top-level scene");
  } catch (...) {
    Release();
    throw;
  }
}

std::uint32_t EmbreeRayCaster::AddModelParts(const StaticScene& scene, const Model& model) {
  const auto first = static_cast<std::uint32_t>(part_materials_.size());
  for (const ModelPart& part : model.parts) {
    if (part.mesh >= scene.meshes.size()) {
      throw std::invalid_argument("EmbreeRayCaster: model '" + model.name + "' names mesh " +
                                  std::to_string(part.mesh) + " of " +
                                  std::to_string(scene.meshes.size()));
    }
    if (part.material >= scene.materials.size()) {
      throw std::invalid_argument("EmbreeRayCaster: model '" + model.name + "' names material " +
                                  std::to_string(part.material) + " of " +
                                  std::to_string(scene.materials.size()));
    }
    part_materials_.push_back(part.material);
  }
  if (model.parts.size() == 1) {
    // Its mesh's own scene, shared by every model of one part that uses the mesh (a box, a
    // file's mesh), placed per object by T_WO T_MP.
    RTCScene& mesh_scene = mesh_scenes_[model.parts[0].mesh];
    if (mesh_scene == nullptr) {
      mesh_scene = NewScene(device_);
      AttachMesh(device_, mesh_scene, scene.meshes[model.parts[0].mesh],
                 Eigen::Affine3f::Identity(), 0);
      rtcCommitScene(mesh_scene);
      Check(device_, rtcGetDeviceError(device_) == RTC_ERROR_NONE, "committing a mesh scene");
    }
    return first;
  }
  // The parts placed by T_MP in one scene, part k as its geometry k.
  RTCScene model_scene = NewScene(device_);
  model_scenes_[static_cast<std::size_t>(&model - scene.models.data())] = model_scene;
  for (std::size_t k = 0; k < model.parts.size(); ++k) {
    AttachMesh(device_, model_scene, scene.meshes[model.parts[k].mesh], model.parts[k].T_MP,
               static_cast<unsigned>(k));
  }
  rtcCommitScene(model_scene);
  Check(device_, rtcGetDeviceError(device_) == RTC_ERROR_NONE, "committing a model scene");
  return first;
}

void EmbreeRayCaster::Release() {
  if (top_ != nullptr) rtcReleaseScene(top_);
  for (RTCScene s : mesh_scenes_) {
    if (s != nullptr) rtcReleaseScene(s);
  }
  for (RTCScene s : model_scenes_) {
    if (s != nullptr) rtcReleaseScene(s);
  }
  rtcReleaseDevice(device_);
}

EmbreeRayCaster::~EmbreeRayCaster() { Release(); }

std::size_t EmbreeRayCaster::mesh_scene_count() const {
  const auto built = [](RTCScene s) { return s != nullptr; };
  return static_cast<std::size_t>(std::count_if(mesh_scenes_.begin(), mesh_scenes_.end(), built) +
                                  std::count_if(model_scenes_.begin(), model_scenes_.end(), built));
}

void EmbreeRayCaster::Cast(std::span<const Ray> rays, std::span<RayHit> hits) const {
  AIRIS_DEMAND(hits.size() == rays.size());
  RTCRayHit batch[kBatch];
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);

  for (std::size_t first = 0; first < rays.size(); first += kBatch) {
    const std::size_t count = std::min(kBatch, rays.size() - first);
    for (std::size_t i = 0; i < count; ++i) {
      const Ray& in = rays[first + i];
      RTCRayHit& rh = batch[i];
      rh.ray.org_x = static_cast<float>(in.origin_W.x());
      rh.ray.org_y = static_cast<float>(in.origin_W.y());
      rh.ray.org_z = static_cast<float>(in.origin_W.z());
      rh.ray.dir_x = static_cast<float>(in.direction_W.x());
      rh.ray.dir_y = static_cast<float>(in.direction_W.y());
      rh.ray.dir_z = static_cast<float>(in.direction_W.z());
      rh.ray.tnear = in.min_range_m;
      rh.ray.tfar = in.max_range_m;
      rh.ray.time = 0.0f;
      rh.ray.mask = 0xFFFFFFFFu;
      rh.ray.id = static_cast<unsigned>(i);
      rh.ray.flags = 0;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect1M(top_, &context, batch, static_cast<unsigned>(count), sizeof(RTCRayHit));
    for (std::size_t i = 0; i < count; ++i) {
      const RTCRayHit& rh = batch[i];
      RayHit& out = hits[first + i];
      if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
        out = RayHit{};
        continue;
      }
      const InstanceInfo& info = instances_[rh.hit.instID[0]];
      out.distance_m = rh.ray.tfar;
      out.class_id = info.class_id;
      out.instance_id = info.instance_id;
      // The part hit: geometry k of a model's scene is its part k (a mesh scene's only one, 0).
      out.reflectivity = reflectivities_[info.material_override >= 0
                                             ? static_cast<std::uint32_t>(info.material_override)
                                             : part_materials_[info.first_part + rh.hit.geomID]];
      Eigen::Vector3f n = info.normal_to_W * Eigen::Vector3f(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
      const Eigen::Vector3f d(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
      if (n.dot(d) > 0.0f) n = -n;  // face the ray origin whatever the triangle's winding
      const float length = n.norm();
      out.normal_W = length > 0.0f ? Eigen::Vector3f(n / length) : Eigen::Vector3f::Zero();
    }
  }
}

}  // namespace airis::engine
