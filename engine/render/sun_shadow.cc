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

Eigen::Matrix4d ShadowPlacement::CalcClipFromC(const Eigen::Isometry3d& T_WC) const {
  // T_MC in double: its translation is the camera's small offset from the anchor.
  return clip_from_M * (T_WM.inverse() * T_WC).matrix();
}

std::optional<ShadowPlacement> PlaceShadowMap(const Eigen::Vector3d& camera_W,
                                              const Eigen::Vector3d& sun_direction_W,
                                              double distance_m, int map_size_px) {
  const Eigen::Vector3d ray_W = sun_direction_W.normalized();
  if (ray_W.z() <= 0.0) return std::nullopt;  // rays not travelling down: sun at or below horizon
  // The camera stands within half a cell of the anchor on each axis, so the map reaches
  // distance_m from it when its half-width R = distance_m + cell / 2, with cell = c texels of
  // 2 R / M each: R = distance_m M / (M - c).
  const int cell_texels = std::max(1, map_size_px / kShadowCellFraction);
  const double radius = distance_m * map_size_px / (map_size_px - cell_texels);
  const double texel = 2.0 * radius / map_size_px;
  const double cell = cell_texels * texel;

  const Eigen::Matrix3d R_LW = CalcRotation_LW(ray_W);
  const Eigen::Vector3d camera_L = R_LW * camera_W;
  ShadowPlacement placement;
  Eigen::Vector3d anchor_L;
  for (int axis = 0; axis < 3; ++axis) {
    placement.cell[axis] = std::llround(camera_L[axis] / cell);
    anchor_L[axis] = static_cast<double>(placement.cell[axis]) * cell;
  }
  placement.T_WM.linear() = R_LW.transpose();
  placement.T_WM.translation() = R_LW.transpose() * anchor_L;
  placement.texel_m = texel;
  placement.radius_m = radius;
  placement.cell_m = cell;
  // Depth from the casters' reach toward the sun to the far side of the shadowed volume.
  const double z_near = -radius - kShadowCasterReach_m;
  const double z_far = radius;
  Eigen::Matrix4d& ortho = placement.clip_from_M;
  ortho(0, 0) = 1.0 / radius;
  ortho(1, 1) = 1.0 / radius;
  ortho(2, 2) = 2.0 / (z_far - z_near);
  ortho(2, 3) = -(z_far + z_near) / (z_far - z_near);
  placement.planes_M = {{1.0, 0.0, 0.0, radius},  {-1.0, 0.0, 0.0, radius},
                        {0.0, 1.0, 0.0, radius},  {0.0, -1.0, 0.0, radius},
                        {0.0, 0.0, 1.0, -z_near}, {0.0, 0.0, -1.0, z_far}};
  return placement;
}

SunShadow::SunShadow(int map_size_px) : map_size_px_(map_size_px) {
  program_ = GlProgram("shadow", shaders::k_scene_vert, shaders::k_shadow_frag,
                       "#define SHADOW_CASTER 1\n");
  static_map_ = MakeDepthMap();
  glGenBuffers(2, instance_buffers_.data());
  CheckGl("shadow map setup");
}

SunShadow::~SunShadow() {
  glDeleteBuffers(2, instance_buffers_.data());
  for (const DepthMap& map : {static_map_, bodies_map_}) {
    if (map.fbo != 0) glDeleteFramebuffers(1, &map.fbo);
    if (map.texture != 0) glDeleteTextures(1, &map.texture);
  }
}

SunShadow::DepthMap SunShadow::MakeDepthMap() const {
  DepthMap map;
  glGenTextures(1, &map.texture);
  glBindTexture(GL_TEXTURE_2D, map.texture);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT24, map_size_px_, map_size_px_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glBindTexture(GL_TEXTURE_2D, 0);
  glGenFramebuffers(1, &map.fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, map.fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, map.texture, 0);
  const GLenum none = GL_NONE;
  glDrawBuffers(1, &none);
  glReadBuffer(GL_NONE);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("the shadow map's framebuffer is incomplete (status " +
                             std::to_string(status) + ")");
  }
  return map;
}

void SunShadow::Render(const GpuScene& scene, const ShadowPlacement& placement,
                       const BodyPoses& bodies, const DetailLimit& detail) {
  // Casters are drawn at coarser looks than the camera needs: a look's error is seen through the
  // map's texels, which are wider than the camera's pixels over most of the shadowed view. The
  // looks are chosen for the nearest the camera can stand in the anchor's cell, so that the map is
  // the same for every camera in it.
  DetailLimit caster_detail = detail;
  caster_detail.tolerance_px *= kCasterToleranceFactor;
  caster_detail.eye_slack_m = 0.5 * std::sqrt(3.0) * placement.cell_m;
  const StaticKey key{scene.id(),        placement.cell,  placement.T_WM.linear().col(2),
                      placement.texel_m, detail.focal_px, detail.tolerance_px};
  last_triangles_ = 0;
  last_drew_static_ = !key_ || !(*key_ == key);
  if (last_drew_static_) {
    scene.CollectVisible(placement.T_WM, placement.planes_M, {}, visible_, caster_detail,
                         Collect::kStaticCasters);
    BeginDepthPass(static_map_.fbo, placement, true);
    Draw(scene, 0);
    key_ = key;
    bodies_map_synced_ = false;
  }
  // Every body casts, the camera's own vehicle too (a drone sees its shadow on the ground).
  BodyPoses casters = bodies;
  casters.hidden = -1;
  scene.CollectVisible(placement.T_WM, placement.planes_M, casters, visible_, caster_detail,
                       Collect::kBodies);
  sampled_ = static_map_.texture;
  if (visible_.instances.empty()) {
    CheckGl("shadow map");
    return;
  }
  if (bodies_map_.fbo == 0) bodies_map_ = MakeDepthMap();
  // Bring the bodies' map back to the static map, then draw this frame's bodies over it.
  if (!bodies_map_synced_) {
    Copy({0, 0, map_size_px_, map_size_px_});
  } else if (!bodies_rect_.empty()) {
    Copy(bodies_rect_);
  }
  bodies_map_synced_ = true;
  bodies_rect_ = BodiesRect(placement);
  BeginDepthPass(bodies_map_.fbo, placement, false);
  Draw(scene, 1);
  sampled_ = bodies_map_.texture;
  CheckGl("shadow map");
}

void SunShadow::BeginDepthPass(GLuint fbo, const ShadowPlacement& placement, bool clear) {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, map_size_px_, map_size_px_);
  glDepthMask(GL_TRUE);
  if (clear) {
    const GLfloat far_depth = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &far_depth);
  }
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  // The faces toward the sun cast (half the fragments of both; terrain, an open surface, faces
  // up). Winding as in the camera pass: the map's frame is x right, y down, z along the rays. The
  // slope-scaled offset keeps a lit face from shading itself (acne); the receiver's normal offset
  // does the rest.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(GL_CW);
  glUseProgram(program_.id());
  const Eigen::Matrix4f M = placement.clip_from_M.cast<float>();
  glUniformMatrix4fv(program_.Uniform("u_shadow_from_C"), 1, GL_FALSE, M.data());
}

void SunShadow::Draw(const GpuScene& scene, int buffer) {
  // Separate instance buffers for the static casters and the bodies: the bodies' upload does not
  // wait for the static map's draw.
  glBindBuffer(GL_ARRAY_BUFFER, instance_buffers_[buffer]);
  const std::size_t bytes = visible_.instances.size() * sizeof(GpuInstance);
  std::size_t& capacity = instance_capacities_[buffer];
  if (bytes > capacity) {
    capacity = std::max<std::size_t>(bytes, 2 * capacity);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity), nullptr, GL_STREAM_DRAW);
  }
  if (bytes > 0) {
    glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), visible_.instances.data());
  }
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, 2.0f);
  for (const VisibleSet::Draw& d : visible_.draws) {
    scene.DrawBatch(d.batch, instance_buffers_[buffer], d.first, d.count, {});
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  last_triangles_ += visible_.triangles;
}

void SunShadow::Copy(const TexelRect& r) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_map_.fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, bodies_map_.fbo);
  glBlitFramebuffer(r.x0, r.y0, r.x1, r.y1, r.x0, r.y0, r.x1, r.y1, GL_DEPTH_BUFFER_BIT,
                    GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

SunShadow::TexelRect SunShadow::BodiesRect(const ShadowPlacement& placement) const {
  // The bodies' bounds across the rays, in texels (M's x and y run from -R to R over the map), two
  // texels wider on each side than their spheres.
  const Eigen::AlignedBox3d& box = visible_.bodies_bounds_C;
  const auto texel = [&](double m) { return (m + placement.radius_m) / placement.texel_m; };
  const auto clamp = [&](double t) {
    return static_cast<int>(std::clamp(t, 0.0, static_cast<double>(map_size_px_)));
  };
  return {
      clamp(std::floor(texel(box.min().x())) - 2.0), clamp(std::floor(texel(box.min().y())) - 2.0),
      clamp(std::ceil(texel(box.max().x())) + 2.0), clamp(std::ceil(texel(box.max().y())) + 2.0)};
}

}  // namespace airis::engine
