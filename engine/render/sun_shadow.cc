#include "engine/render/sun_shadow.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "engine/render/shader_sources.h"

namespace airis::engine {

namespace {

// Casters may stray this many times the camera's detail tolerance (DetailLimit).
constexpr double kCasterToleranceFactor = 4.0;

// The sphere around the view volume between the near plane and `far_m`, in the camera frame: its
// centre is the middle of the eight corners' bounding box, its radius the farthest corner's
// distance from it (both depend on the intrinsics and far_m only).
Eigen::Vector4d CalcViewSphere_C(const CameraIntrinsics& k, double far_m) {
  const double x_left = (-0.5 - k.cx_px) / k.fx_px;
  const double x_right = (k.width_px - 0.5 - k.cx_px) / k.fx_px;
  const double y_top = (-0.5 - k.cy_px) / k.fy_px;
  const double y_bottom = (k.height_px - 0.5 - k.cy_px) / k.fy_px;
  std::array<Eigen::Vector3d, 8> corners;
  int i = 0;
  for (const double z : {k.near_m, far_m}) {
    for (const double x : {x_left, x_right}) {
      for (const double y : {y_top, y_bottom}) corners[i++] = Eigen::Vector3d(x * z, y * z, z);
    }
  }
  Eigen::Vector3d lo = corners[0];
  Eigen::Vector3d hi = corners[0];
  for (const auto& c : corners) {
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  double radius = 0.0;
  for (const auto& c : corners) radius = std::max(radius, (c - centre).norm());
  return {centre.x(), centre.y(), centre.z(), radius};
}

// Rows: the map's x and y axes and the rays' direction, in the world frame. x is horizontal, so
// the grid the map snaps to is the same for every frame of one sun.
Eigen::Matrix3d CalcRotation_LW(const Eigen::Vector3d& ray_W) {
  const Eigen::Vector3d down(0.0, 0.0, 1.0);
  Eigen::Vector3d x = down.cross(ray_W);
  if (x.norm() < 1e-9) x = Eigen::Vector3d(0.0, 1.0, 0.0);  // the sun at the zenith
  x.normalize();
  const Eigen::Vector3d y = ray_W.cross(x);
  Eigen::Matrix3d R_LW;
  R_LW.row(0) = x;
  R_LW.row(1) = y;
  R_LW.row(2) = ray_W;
  return R_LW;
}

}  // namespace

std::optional<ShadowFrame> FitShadowFrame(const Eigen::Isometry3d& T_WC, const CameraIntrinsics& k,
                                          const Eigen::Vector3d& sun_direction_W, double distance_m,
                                          int map_size_px) {
  const Eigen::Vector3d ray_W = sun_direction_W.normalized();
  if (ray_W.z() <= 0.0) return std::nullopt;  // rays not travelling down: sun at or below horizon
  const double far_m = std::max(std::min(distance_m, k.far_m), k.near_m);
  const Eigen::Vector4d sphere_C = CalcViewSphere_C(k, far_m);
  const double radius = sphere_C.w();
  const double texel = 2.0 * radius / map_size_px;

  const Eigen::Matrix3d R_LW = CalcRotation_LW(ray_W);
  const Eigen::Matrix3d R_LC = R_LW * T_WC.linear();
  // The camera's position in the map's frame, and the sphere's centre snapped to whole texels
  // across the rays (along them any depth will do). Double precision: world coordinates are large.
  const Eigen::Vector3d t_L = R_LW * T_WC.translation();
  Eigen::Vector3d centre_L = R_LC * sphere_C.head<3>() + t_L;
  centre_L.x() = std::round(centre_L.x() / texel) * texel;
  centre_L.y() = std::round(centre_L.y() / texel) * texel;
  const double z_near = centre_L.z() - radius - kShadowCasterReach_m;
  const double z_far = centre_L.z() + radius;

  // p_L - centre_L = R_LC p_C + (t_L - centre_L): a small offset, kept exact in floats.
  const Eigen::Vector3d offset = t_L - centre_L;
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.topLeftCorner<3, 3>() = R_LC;
  view.topRightCorner<3, 1>() = offset;
  Eigen::Matrix4d ortho = Eigen::Matrix4d::Identity();
  ortho(0, 0) = 1.0 / radius;
  ortho(1, 1) = 1.0 / radius;
  ortho(2, 2) = 2.0 / (z_far - z_near);
  ortho(2, 3) = -(z_far + z_near - 2.0 * centre_L.z()) / (z_far - z_near);

  ShadowFrame frame;
  frame.shadow_from_C = ortho * view;
  frame.texel_m = texel;
  frame.radius_m = radius;
  // Inside: |x_L - cx| <= r, |y_L - cy| <= r, z_near <= z_L <= z_far, with x_L - cx = row0 . p_C +
  // offset.x and so on.
  for (int axis = 0; axis < 2; ++axis) {
    const Eigen::Vector3d n = R_LC.row(axis).transpose();
    frame.planes_C.emplace_back(n.x(), n.y(), n.z(), offset[axis] + radius);
    frame.planes_C.emplace_back(-n.x(), -n.y(), -n.z(), radius - offset[axis]);
  }
  const Eigen::Vector3d n = R_LC.row(2).transpose();
  const double z_offset = offset.z() + centre_L.z();  // z_L = row2 . p_C + z_offset
  frame.planes_C.emplace_back(n.x(), n.y(), n.z(), z_offset - z_near);
  frame.planes_C.emplace_back(-n.x(), -n.y(), -n.z(), z_far - z_offset);

  // Casters: also inside the view volume's planes that the rays leave (moving along the rays does
  // not bring a point back across them), each moved out by what a receiver's lookups reach.
  frame.caster_planes_C = frame.planes_C;
  const Eigen::Vector3d ray_C = T_WC.linear().transpose() * ray_W;
  const double x_left = (-0.5 - k.cx_px) / k.fx_px;
  const double x_right = (k.width_px - 0.5 - k.cx_px) / k.fx_px;
  const double y_top = (-0.5 - k.cy_px) / k.fy_px;
  const double y_bottom = (k.height_px - 0.5 - k.cy_px) / k.fy_px;
  const Eigen::Vector4d view_planes[] = {{1.0, 0.0, -x_left, 0.0},   {-1.0, 0.0, x_right, 0.0},
                                         {0.0, 1.0, -y_top, 0.0},    {0.0, -1.0, y_bottom, 0.0},
                                         {0.0, 0.0, 1.0, -k.near_m}, {0.0, 0.0, -1.0, far_m}};
  for (const Eigen::Vector4d& plane : view_planes) {
    const double norm = plane.head<3>().norm();
    const Eigen::Vector4d unit = plane / norm;
    if (unit.head<3>().dot(ray_C) > 0.0) continue;  // rays cross it inward: a shadow may enter
    frame.caster_planes_C.push_back(unit +
                                    Eigen::Vector4d(0, 0, 0, kShadowLookupReachTexels * texel));
  }
  return frame;
}

SunShadow::SunShadow(int map_size_px) : map_size_px_(map_size_px) {
  program_ = GlProgram("shadow", shaders::k_scene_vert, shaders::k_shadow_frag,
                       "#define SHADOW_CASTER 1\n");
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT24, map_size_px, map_size_px);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glBindTexture(GL_TEXTURE_2D, 0);
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, texture_, 0);
  const GLenum none = GL_NONE;
  glDrawBuffers(1, &none);
  glReadBuffer(GL_NONE);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("the shadow map's framebuffer is incomplete (status " +
                             std::to_string(status) + ")");
  }
  glGenBuffers(1, &instance_buffer_);
  CheckGl("shadow map setup");
}

SunShadow::~SunShadow() {
  glDeleteBuffers(1, &instance_buffer_);
  glDeleteFramebuffers(1, &fbo_);
  glDeleteTextures(1, &texture_);
}

void SunShadow::Render(const GpuScene& scene, const Eigen::Isometry3d& T_WC,
                       const ShadowFrame& frame, const BodyPoses& bodies,
                       const DetailLimit& detail) {
  // Every body casts, the camera's own vehicle too (a drone sees its shadow on the ground).
  BodyPoses casters = bodies;
  casters.hidden = -1;
  // Casters are drawn at coarser looks than the camera needs: a look's error is seen through the
  // map's texels, which are wider than the camera's pixels over most of the shadowed view.
  DetailLimit caster_detail = detail;
  caster_detail.tolerance_px *= kCasterToleranceFactor;
  scene.CollectVisible(T_WC, frame.caster_planes_C, casters, visible_, caster_detail, true);
  glBindBuffer(GL_ARRAY_BUFFER, instance_buffer_);
  const std::size_t bytes = visible_.instances.size() * sizeof(GpuInstance);
  if (bytes > instance_capacity_) {
    instance_capacity_ = std::max<std::size_t>(bytes, 2 * instance_capacity_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(instance_capacity_), nullptr,
                 GL_STREAM_DRAW);
  }
  if (bytes > 0) {
    glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), visible_.instances.data());
  }

  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, map_size_px_, map_size_px_);
  glDepthMask(GL_TRUE);
  const GLfloat far_depth = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &far_depth);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  // The faces toward the sun cast (half the fragments of both; terrain, an open surface, faces
  // up). Winding as in the camera pass: the map's frame is x right, y down, z along the rays. The
  // slope-scaled offset keeps a lit face from shading itself (acne); the receiver's normal offset
  // does the rest.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(GL_CW);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, 2.0f);
  glUseProgram(program_.id());
  const Eigen::Matrix4f M = frame.shadow_from_C.cast<float>();
  glUniformMatrix4fv(program_.Uniform("u_shadow_from_C"), 1, GL_FALSE, M.data());
  for (const VisibleSet::Draw& d : visible_.draws) {
    scene.DrawBatch(d.batch, instance_buffer_, d.first, d.count, {});
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  CheckGl("shadow map");
}

}  // namespace airis::engine
