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

// One Embree scene holding the triangles of `mesh` in its own frame.
RTCScene BuildMeshScene(RTCDevice device, const TriangleMesh& mesh) {
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
  RTCScene scene = rtcNewScene(device);
  Check(device, scene != nullptr, "rtcNewScene");
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  if (mesh.triangle_count() > 0) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), mesh.positions.size()));
    auto* triangles = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(unsigned), mesh.triangle_count()));
    Check(device, vertices != nullptr && triangles != nullptr, "rtcSetNewGeometryBuffer");
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      vertices[3 * i + 0] = mesh.positions[i].x();
      vertices[3 * i + 1] = mesh.positions[i].y();
      vertices[3 * i + 2] = mesh.positions[i].z();
    }
    std::copy(mesh.indices.begin(), mesh.indices.end(), triangles);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(scene);
  Check(device, rtcGetDeviceError(device) == RTC_ERROR_NONE, "committing a mesh scene");
  return scene;
}

}  // namespace

EmbreeRayCaster::EmbreeRayCaster(const StaticScene& scene) {
  device_ = rtcNewDevice(nullptr);
  if (device_ == nullptr) {
    throw std::runtime_error("EmbreeRayCaster: rtcNewDevice failed: " + DeviceErrorText(nullptr));
  }
  try {
    top_ = rtcNewScene(device_);
    Check(device_, top_ != nullptr, "rtcNewScene");
    rtcSetSceneFlags(top_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(top_, RTC_BUILD_QUALITY_HIGH);
    mesh_scenes_.assign(scene.meshes.size(), nullptr);

    for (const StaticObject& object : scene.objects) {
      if (object.collision == CollisionShape::kNone) continue;
      if (object.model >= scene.models.size()) {
        throw std::invalid_argument("EmbreeRayCaster: object '" + object.name + "' names model " +
                                    std::to_string(object.model) + " of " +
                                    std::to_string(scene.models.size()));
      }
      for (const ModelPart& part : scene.models[object.model].parts) {
        if (part.mesh >= scene.meshes.size()) {
          throw std::invalid_argument("EmbreeRayCaster: model '" + scene.models[object.model].name +
                                      "' names mesh " + std::to_string(part.mesh) + " of " +
                                      std::to_string(scene.meshes.size()));
        }
        if (mesh_scenes_[part.mesh] == nullptr) {
          mesh_scenes_[part.mesh] = BuildMeshScene(device_, scene.meshes[part.mesh]);
        }
        // Part -> world, in float as Embree stores it (column-major 3x4).
        const Eigen::Affine3f T_WP = object.T_WO.cast<float>() * part.T_MP;
        float transform[12];
        for (int c = 0; c < 4; ++c) {
          for (int r = 0; r < 3; ++r) transform[3 * c + r] = T_WP.matrix()(r, c);
        }
        RTCGeometry instance = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(instance, mesh_scenes_[part.mesh]);
        rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, transform);
        rtcCommitGeometry(instance);
        const unsigned geometry_id = rtcAttachGeometry(top_, instance);
        rtcReleaseGeometry(instance);
        Check(device_, geometry_id == instances_.size(), "instance ids are not consecutive");

        const std::size_t material = object.material_override >= 0
                                         ? static_cast<std::size_t>(object.material_override)
                                         : part.material;
        if (material >= scene.materials.size()) {
          throw std::invalid_argument("EmbreeRayCaster: object '" + object.name +
                                      "' names material " + std::to_string(material) + " of " +
                                      std::to_string(scene.materials.size()));
        }
        InstanceInfo info;
        info.class_id = object.class_id;
        info.instance_id = object.instance_id;
        info.reflectivity = scene.materials[material].base_color_rgb.mean();
        // Embree reports an instance hit's normal in the instanced scene's space (RTCHit: "geometry
        // normal in object space"); normals map to the world by the inverse transpose of the linear
        // part.
        info.normal_to_W = T_WP.linear().inverse().transpose();
        instances_.push_back(info);
      }
    }
    rtcCommitScene(top_);
    Check(device_, rtcGetDeviceError(device_) == RTC_ERROR_NONE, "committing the top-level scene");
  } catch (...) {
    for (RTCScene s : mesh_scenes_) {
      if (s != nullptr) rtcReleaseScene(s);
    }
    if (top_ != nullptr) rtcReleaseScene(top_);
    rtcReleaseDevice(device_);
    throw;
  }
}

EmbreeRayCaster::~EmbreeRayCaster() {
  rtcReleaseScene(top_);
  for (RTCScene s : mesh_scenes_) {
    if (s != nullptr) rtcReleaseScene(s);
  }
  rtcReleaseDevice(device_);
}

std::size_t EmbreeRayCaster::mesh_scene_count() const {
  return static_cast<std::size_t>(std::count_if(mesh_scenes_.begin(), mesh_scenes_.end(),
                                                [](RTCScene s) { return s != nullptr; }));
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
      out.reflectivity = info.reflectivity;
      Eigen::Vector3f n = info.normal_to_W * Eigen::Vector3f(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
      const Eigen::Vector3f d(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
      if (n.dot(d) > 0.0f) n = -n;  // face the ray origin whatever the triangle's winding
      const float length = n.norm();
      out.normal_W = length > 0.0f ? Eigen::Vector3f(n / length) : Eigen::Vector3f::Zero();
    }
  }
}

}  // namespace airis::engine
