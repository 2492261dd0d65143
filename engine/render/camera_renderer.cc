#include "engine/render/camera_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "engine/core/config.h"
#include "engine/core/error.h"
#include "engine/core/limits.h"
#include "engine/render/daylight.h"
#include "engine/render/rain.h"
#include "engine/render/shader_sources.h"

namespace airis::engine {

namespace {

enum Target { kRgb = 0, kDepthPlanar, kDepthPerspective, kClass, kInstance, kNormal };

// Instance ids are 32-bit unsigned integers on the GPU (exact through every driver, llvmpipe
// included: no colour channel or normalisation touches them); files store 24 bits of them.
constexpr GLenum kInternalFormat[] = {GL_SRGB8_ALPHA8, GL_R32F,  GL_R32F,
                                      GL_R8UI,         GL_R32UI, GL_RGBA32F};
constexpr const char* kDefine[] = {"OUT_RGB",   "OUT_DEPTH_PLANAR", "OUT_DEPTH_PERSPECTIVE",
                                   "OUT_CLASS", "OUT_INSTANCE",     "OUT_NORMAL"};
constexpr const char* kRemapSampler[] = {"u_rgb",   "u_depth_planar", "u_depth_perspective",
                                         "u_class", "u_instance",     "u_normal"};
// What the frame stores per pixel, and the read format that delivers exactly that.
constexpr GLenum kPreferredFormat[] = {GL_RGBA,        GL_RED,         GL_RED,
                                       GL_RED_INTEGER, GL_RED_INTEGER, GL_RGBA};
constexpr GLenum kPreferredType[] = {GL_UNSIGNED_BYTE, GL_FLOAT,        GL_FLOAT,
                                     GL_UNSIGNED_BYTE, GL_UNSIGNED_INT, GL_FLOAT};
constexpr int kPreferredBytes[] = {4, 4, 4, 1, 4, 16};
// The combination every ES 3.0 implementation must accept for that kind of buffer (fallback,
// converted).
constexpr GLenum kFallbackFormat[] = {GL_RGBA,         GL_RGBA,         GL_RGBA,
                                      GL_RGBA_INTEGER, GL_RGBA_INTEGER, GL_RGBA};
constexpr GLenum kFallbackType[] = {GL_UNSIGNED_BYTE, GL_FLOAT,        GL_FLOAT,
                                    GL_UNSIGNED_INT,  GL_UNSIGNED_INT, GL_FLOAT};

// Pinhole projection from the camera frame (x right, y down, z forward) to clip space, with window
// row 0 = image row 0 (so the image is stored top-down) and pixel centres at integer image
// coordinates.
Eigen::Matrix4f CalcProjection(const CameraIntrinsics& k) {
  const double w = k.width_px;
  const double h = k.height_px;
  const double n = k.near_m;
  const double f = k.far_m;
  Eigen::Matrix4d P = Eigen::Matrix4d::Zero();
  P(0, 0) = 2.0 * k.fx_px / w;
  P(0, 2) = 2.0 * (k.cx_px + 0.5) / w - 1.0;
  P(1, 1) = 2.0 * k.fy_px / h;
  P(1, 2) = 2.0 * (k.cy_px + 0.5) / h - 1.0;
  P(2, 2) = (f + n) / (f - n);
  P(2, 3) = -2.0 * f * n / (f - n);
  P(3, 2) = 1.0;
  return P.cast<float>();
}

// Inward planes of the view volume in the camera frame (image edges at the outer pixel borders).
std::vector<Eigen::Vector4d> CalcFrustumPlanes(const CameraIntrinsics& k) {
  const double x_left = (-0.5 - k.cx_px) / k.fx_px;
  const double x_right = (k.width_px - 0.5 - k.cx_px) / k.fx_px;
  const double y_top = (-0.5 - k.cy_px) / k.fy_px;
  const double y_bottom = (k.height_px - 0.5 - k.cy_px) / k.fy_px;
  std::vector<Eigen::Vector4d> planes = {{1.0, 0.0, -x_left, 0.0},
                                         {-1.0, 0.0, x_right, 0.0},
                                         {0.0, 1.0, -y_top, 0.0},
                                         {0.0, -1.0, y_bottom, 0.0}};
  for (auto& p : planes) p /= p.head<3>().norm();
  planes.emplace_back(0.0, 0.0, 1.0, -k.near_m);
  planes.emplace_back(0.0, 0.0, -1.0, k.far_m);
  return planes;
}

}  // namespace

bool CameraRenderer::Enabled(int target) const {
  switch (target) {
    case kRgb:
      return outputs_.rgb;
    case kDepthPlanar:
      return outputs_.depth_planar;
    case kDepthPerspective:
      return outputs_.depth_perspective;
    case kClass:
    case kInstance:
      return outputs_.segmentation;
    case kNormal:
      return outputs_.normals;
    default:
      return false;
  }
}

CameraRenderer::CameraRenderer(const EglContext& context, const CameraIntrinsics& intrinsics,
                               const RenderOutputs& outputs, double detail_tolerance_px)
    : context_(context),
      intrinsics_(intrinsics),
      render_intrinsics_(intrinsics),
      outputs_(outputs),
      detail_tolerance_px_(detail_tolerance_px) {
  intrinsics_.Validate();
  outputs_.Validate();
  RequireInRange("detail_tolerance_px", detail_tolerance_px, 0.0, kMaxDetailTolerance_px);
  context_.MakeCurrent();
  const bool float_targets =
      outputs_.depth_planar || outputs_.depth_perspective || outputs_.normals;
  if (float_targets && !context_.HasExtension("GL_EXT_color_buffer_float")) {
    throw std::runtime_error(
        "the OpenGL ES driver (" + context_.gl_renderer() +
        ") lacks GL_EXT_color_buffer_float, needed for float32 depth and normals");
  }

  // With distortion: the undistorted region every output pixel's ray needs, at the same focal
  // length.
  distorted_ = !intrinsics_.distortion.IsIdentity();
  std::vector<float> map;
  if (distorted_) {
    const int w = intrinsics_.width_px;
    const int h = intrinsics_.height_px;
    map.resize(static_cast<std::size_t>(w) * h * 2);
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300);
    Eigen::Vector2d hi = Eigen::Vector2d::Constant(-1e300);
    for (int v = 0; v < h; ++v) {
      for (int u = 0; u < w; ++u) {
        const auto ray = intrinsics_.CalcRay({u, v});
        if (!ray) {
          throw InvalidField("distortion", "the model cannot be inverted at pixel (" +
                                               std::to_string(u) + ", " + std::to_string(v) +
                                               "): it folds inside the image");
        }
        const Eigen::Vector2d xy = ray->head<2>() / ray->z();
        lo = lo.cwiseMin(xy);
        hi = hi.cwiseMax(xy);
        map[(static_cast<std::size_t>(v) * w + u) * 2] = static_cast<float>(xy.x());
        map[(static_cast<std::size_t>(v) * w + u) * 2 + 1] = static_cast<float>(xy.y());
      }
    }
    constexpr int kMarginPx = 2;  // room for the bilinear footprint at the border
    CameraIntrinsics& r = render_intrinsics_;
    r.distortion = BrownConradyDistortion{};
    r.cx_px = -lo.x() * r.fx_px + kMarginPx;
    r.cy_px = -lo.y() * r.fy_px + kMarginPx;
    r.width_px = static_cast<int>(std::ceil((hi.x() - lo.x()) * r.fx_px)) + 2 * kMarginPx + 1;
    r.height_px = static_cast<int>(std::ceil((hi.y() - lo.y()) * r.fy_px)) + 2 * kMarginPx + 1;
    CheckUndistortedExtent(intrinsics_, lo, hi);
    for (std::size_t i = 0; i < map.size(); i += 2) {
      map[i] = static_cast<float>(r.fx_px * map[i] + r.cx_px);
      map[i + 1] = static_cast<float>(r.fy_px * map[i + 1] + r.cy_px);
    }
  }

  std::string defines;
  for (int t = 0; t < kTargets; ++t) {
    if (Enabled(t)) defines += std::string("#define ") + kDefine[t] + " 1\n";
  }
  scene_defines_ = defines;
  if (outputs_.rgb) sky_program_ = GlProgram("sky", shaders::k_sky_vert, shaders::k_sky_frag, "");

  geometry_target_ =
      CreateTarget(render_intrinsics_.width_px, render_intrinsics_.height_px, distorted_, true);
  if (distorted_) {
    output_target_ = CreateTarget(intrinsics_.width_px, intrinsics_.height_px, false, false);
    remap_program_ = GlProgram("remap", shaders::k_sky_vert, shaders::k_remap_frag, defines);
    glUseProgram(remap_program_.id());
    for (int t = 0; t < kTargets; ++t) {
      if (Enabled(t)) glUniform1i(remap_program_.Uniform(kRemapSampler[t]), t);
    }
    glUniform1i(remap_program_.Uniform("u_map"), kTargets);
    glUniform2f(remap_program_.Uniform("u_source_size"),
                static_cast<float>(render_intrinsics_.width_px),
                static_cast<float>(render_intrinsics_.height_px));
    glGenTextures(1, &remap_texture_);
    glBindTexture(GL_TEXTURE_2D, remap_texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, intrinsics_.width_px, intrinsics_.height_px, 0, GL_RG,
                 GL_FLOAT, map.data());
  } else {
    output_target_ = geometry_target_;
  }
  glGenVertexArrays(1, &empty_vao_);
  glGenBuffers(1, &instance_buffer_);
  planes_C_ = CalcFrustumPlanes(render_intrinsics_);

  // Read formats: the implementation's own format when it is the frame's layout (no conversion),
  // else the combination ES 3.0 guarantees, converted on the CPU.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, output_target_.fbo);
  std::size_t pbo_bytes = 0;
  const std::size_t pixels = static_cast<std::size_t>(intrinsics_.width_px) * intrinsics_.height_px;
  for (int t = 0; t < kTargets; ++t) {
    if (!Enabled(t)) continue;
    glReadBuffer(GL_COLOR_ATTACHMENT0 + t);
    GLint format = 0;
    GLint type = 0;
    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_FORMAT, &format);
    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_TYPE, &type);
    ReadFormat& r = read_formats_[t];
    const bool preferred = (static_cast<GLenum>(format) == kPreferredFormat[t] &&
                            static_cast<GLenum>(type) == kPreferredType[t]) ||
                           kPreferredFormat[t] == kFallbackFormat[t];
    r.format = preferred ? kPreferredFormat[t] : kFallbackFormat[t];
    r.type = preferred ? kPreferredType[t] : kFallbackType[t];
    r.bytes_per_pixel = preferred ? kPreferredBytes[t] : 16;
    r.direct = preferred && t != kNormal;
    // Each image starts on a 16-byte boundary: glReadPixels into a buffer needs an offset that is
    // a multiple of the type's size (a 32-bit instance image after an odd-sized 8-bit class image
    // would be refused).
    pbo_bytes = (pbo_bytes + 15) / 16 * 16;
    for (auto& slot : slots_) slot.offset[t] = pbo_bytes;
    pbo_bytes += pixels * r.bytes_per_pixel;
  }
  for (auto& slot : slots_) {
    glGenBuffers(1, &slot.pbo);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, slot.pbo);
    glBufferData(GL_PIXEL_PACK_BUFFER, static_cast<GLsizeiptr>(pbo_bytes), nullptr, GL_STREAM_READ);
  }
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  CheckGl("camera renderer setup");
}

CameraRenderer::~CameraRenderer() {
  context_.MakeCurrent();
  for (auto& slot : slots_) {
    if (slot.fence != nullptr) glDeleteSync(slot.fence);
    glDeleteBuffers(1, &slot.pbo);
  }
  if (distorted_) DestroyTarget(output_target_);
  DestroyTarget(geometry_target_);
  if (remap_texture_ != 0) glDeleteTextures(1, &remap_texture_);
  glDeleteVertexArrays(1, &empty_vao_);
  glDeleteBuffers(1, &instance_buffer_);
}

CameraRenderer::RenderTarget CameraRenderer::CreateTarget(int width, int height, bool sampled,
                                                          bool with_depth) const {
  RenderTarget target;
  target.width = width;
  target.height = height;
  glGenFramebuffers(1, &target.fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, target.fbo);
  for (int t = 0; t < kTargets; ++t) {
    if (!Enabled(t)) continue;
    glGenTextures(1, &target.textures[t]);
    glBindTexture(GL_TEXTURE_2D, target.textures[t]);
    glTexStorage2D(GL_TEXTURE_2D, 1, kInternalFormat[t], width, height);
    // Only the RGB source of the distortion remap is filtered; everything else is read texel by
    // texel.
    const GLint filter = (sampled && t == kRgb) ? GL_LINEAR : GL_NEAREST;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + t, GL_TEXTURE_2D,
                           target.textures[t], 0);
  }
  if (with_depth) {
    glGenRenderbuffers(1, &target.depth);
    glBindRenderbuffer(GL_RENDERBUFFER, target.depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, target.depth);
  }
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("render target " + std::to_string(width) + "x" +
                             std::to_string(height) + " is incomplete (status " +
                             std::to_string(status) + ") on " + context_.gl_renderer());
  }
  CheckGl("render target");
  return target;
}

void CameraRenderer::DestroyTarget(RenderTarget& target) const {
  glDeleteFramebuffers(1, &target.fbo);
  if (target.depth != 0) glDeleteRenderbuffers(1, &target.depth);
  for (GLuint texture : target.textures) {
    if (texture != 0) glDeleteTextures(1, &texture);
  }
  target = RenderTarget{};
}

void CameraRenderer::DrawShadow(const GpuScene& scene, const Eigen::Isometry3d& T_WC,
                                const BodyPoses& bodies, const SceneLighting& light,
                                const DetailLimit& detail) {
  shadow_.reset();
  last_shadow_triangles_ = 0;
  // Under an overcast sky there is no direct sun to cast them.
  if (!outputs_.rgb || !light.shadows.enabled || light.sky == SkyModel::kOvercast) return;
  const std::optional<ShadowPlacement> placement =
      PlaceShadowMap(T_WC.translation(), light.sun_direction_W, light.shadows.distance_m,
                     light.shadows.map_size_px);
  if (!placement) return;
  if (!sun_shadow_ || sun_shadow_->map_size_px() != light.shadows.map_size_px) {
    sun_shadow_ = std::make_unique<SunShadow>(light.shadows.map_size_px);
  }
  sun_shadow_->Render(scene, *placement, bodies, detail);
  shadow_ = ShadowFrame{placement->CalcClipFromC(T_WC), placement->texel_m};
  last_shadow_triangles_ = sun_shadow_->last_triangles();
}

std::size_t CameraRenderer::SceneProgramIndex(const GpuScene::Batch& batch) const {
  // Patterns and maps only colour the RGB image: without it every part is drawn by one program.
  if (!outputs_.rgb) return 0;
  return 2 * static_cast<std::size_t>(batch.pattern) + (batch.textured_material >= 0 ? 1 : 0);
}

const GlProgram& CameraRenderer::SceneProgram(std::size_t index) {
  GlProgram& program = scene_programs_[index];
  if (program.id() != 0) return program;
  const std::string fragment =
      std::string(shaders::k_surface_glsl) + std::string(shaders::k_scene_frag);
  const std::string defines = scene_defines_ + "#define PATTERN " + std::to_string(index / 2) +
                              "\n#define TEXTURED " + std::to_string(index % 2) + "\n";
  program = GlProgram("scene", shaders::k_scene_vert, fragment, defines);
  glUseProgram(program.id());
  glUniform1i(program.Uniform("u_texture"), 0);
  if (outputs_.rgb) {
    glUniform1i(program.Uniform("u_shadow_map"), 1);
    glUniform1i(program.Uniform("u_normal_map"), 2);
    glUniform1i(program.Uniform("u_metallic_roughness_map"), 3);
  }
  return program;
}

void CameraRenderer::SetSceneUniforms(const GlProgram& program, const FrameUniforms& frame) {
  const SkyShading& sky = frame.sky;
  glUniformMatrix4fv(program.Uniform("u_projection"), 1, GL_FALSE, frame.projection.data());
  glUniform3fv(program.Uniform("u_to_sun_C"), 1, frame.to_sun_C.data());
  glUniform3fv(program.Uniform("u_up_C"), 1, frame.up_C.data());
  glUniform1f(program.Uniform("u_camera_height_m"), frame.camera_height_m);
  glUniform3fv(program.Uniform("u_sun_rgb"), 1, sky.sun_rgb.data());
  glUniform3fv(program.Uniform("u_sky_zenith_rgb"), 1, sky.zenith_rgb.data());
  glUniform3fv(program.Uniform("u_sky_horizon_rgb"), 1, sky.horizon_rgb.data());
  glUniform1f(program.Uniform("u_ambient"), sky.ambient);
  glUniform1f(program.Uniform("u_fog_distance_m"), frame.light.fog_distance_m);
  glUniform1f(program.Uniform("u_fog_height_m"), frame.light.fog_height_m);
  glUniform1f(program.Uniform("u_rain_extinction_per_m"),
              static_cast<float>(rain::CalcExtinction_per_m(frame.light.rain_mm_per_h)));
  SetShadowUniforms(program, shadow_, frame.light);
}

void CameraRenderer::SetShadowUniforms(const GlProgram& program,
                                       const std::optional<ShadowFrame>& shadow,
                                       const SceneLighting& light) {
  glUniform1i(program.Uniform("u_has_shadow"), shadow ? 1 : 0);
  if (!shadow) return;
  const Eigen::Matrix4f M = shadow->shadow_from_C.cast<float>();
  glUniformMatrix4fv(program.Uniform("u_shadow_from_C"), 1, GL_FALSE, M.data());
  glUniform1f(program.Uniform("u_shadow_texel"),
              1.0f / static_cast<float>(sun_shadow_->map_size_px()));
  // One and a half texels out along the normal: past the map's depth steps on sloped receivers.
  glUniform1f(program.Uniform("u_shadow_offset_m"), static_cast<float>(1.5 * shadow->texel_m));
  glUniform1f(program.Uniform("u_shadow_distance_m"), light.shadows.distance_m);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, sun_shadow_->texture());
  glActiveTexture(GL_TEXTURE0);
}

void CameraRenderer::SetSkyUniforms(const SkyShading& sky, const SceneLighting& light,
                                    float camera_height_m) {
  glUniform3fv(sky_program_.Uniform("u_sun_rgb"), 1, sky.sun_rgb.data());
  glUniform3fv(sky_program_.Uniform("u_sky_zenith_rgb"), 1, sky.zenith_rgb.data());
  glUniform3fv(sky_program_.Uniform("u_sky_horizon_rgb"), 1, sky.horizon_rgb.data());
  glUniform1i(sky_program_.Uniform("u_sky_model"), static_cast<GLint>(sky.model));
  if (sky.model == SkyModel::kClear) {
    float perez[15];
    for (int k = 0; k < 5; ++k) {
      for (int c = 0; c < 3; ++c) perez[3 * k + c] = sky.perez[k][c];
    }
    glUniform3fv(sky_program_.Uniform("u_perez"), 5, perez);
    glUniform3fv(sky_program_.Uniform("u_zenith_over_perez"), 1, sky.zenith_over_perez.data());
  }
  glUniform1f(sky_program_.Uniform("u_fog_distance_m"), light.fog_distance_m);
  glUniform1f(sky_program_.Uniform("u_fog_height_m"), light.fog_height_m);
  glUniform1f(sky_program_.Uniform("u_camera_height_m"), camera_height_m);
}

void CameraRenderer::DrawRain(const SceneLighting& light, const SkyShading& sky,
                              const Eigen::Isometry3d& T_WC, TimeNs time_ns,
                              const Eigen::Matrix4f& projection) {
  constexpr double kBox_m = 16.0;          // the cube of drops around the camera
  constexpr double kMinDiameter_mm = 2.5;  // the drops drawn as streaks
  constexpr double kMaxDrops = 30000.0;
  constexpr double kPeriod_s =
      60.0;  // the drops are drawn anew each period (float time stays exact)
  const double rate = light.rain_mm_per_h;
  const double drops =
      std::min(kMaxDrops, rain::CalcDropsPerM3(rate, kMinDiameter_mm) * kBox_m * kBox_m * kBox_m);
  if (drops < 1.0) return;
  if (rain_program_.id() == 0) {
    rain_program_ = GlProgram("rain", shaders::k_rain_vert, shaders::k_rain_frag, "");
  }
  const GlProgram& p = rain_program_;
  glUseProgram(p.id());
  const double t_s = static_cast<double>(time_ns) * 1e-9;
  const double period = std::floor(t_s / kPeriod_s);
  const Eigen::Matrix3f R_CW = T_WC.linear().transpose().cast<float>();
  Eigen::Vector3f camera_mod;
  for (int i = 0; i < 3; ++i) {
    const double x = std::fmod(T_WC.translation()[i], kBox_m);
    camera_mod[i] = static_cast<float>(x < 0.0 ? x + kBox_m : x);
  }
  const CameraIntrinsics& k = render_intrinsics_;
  const Eigen::Vector3f drop_rgb = 0.5f * (sky.zenith_rgb + sky.horizon_rgb);
  glUniformMatrix4fv(p.Uniform("u_projection"), 1, GL_FALSE, projection.data());
  glUniformMatrix3fv(p.Uniform("u_R_CW"), 1, GL_FALSE, R_CW.data());
  glUniform3fv(p.Uniform("u_camera_mod_m"), 1, camera_mod.data());
  glUniform1f(p.Uniform("u_box_m"), static_cast<float>(kBox_m));
  glUniform1f(p.Uniform("u_time_s"), static_cast<float>(t_s - period * kPeriod_s));
  glUniform1ui(p.Uniform("u_seed"),
               static_cast<GLuint>(0x5EED0000u ^ static_cast<std::uint32_t>(period)));
  glUniform1f(p.Uniform("u_min_diameter_mm"), static_cast<float>(kMinDiameter_mm));
  glUniform1f(p.Uniform("u_slope_per_mm"), static_cast<float>(rain::CalcSlope_per_mm(rate)));
  glUniform1f(p.Uniform("u_exposure_s"), static_cast<float>(exposure_time_s_));
  const Eigen::Vector3f wind_W = wind_W_.cast<float>();
  glUniform3fv(p.Uniform("u_wind_W"), 1, wind_W.data());
  glUniform2f(p.Uniform("u_pixel_ndc"), 2.0f / static_cast<float>(k.width_px),
              2.0f / static_cast<float>(k.height_px));
  glUniform1f(p.Uniform("u_pixel_rad"), static_cast<float>(1.0 / k.fx_px));
  glUniform3fv(p.Uniform("u_drop_rgb"), 1, drop_rgb.data());
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(drops));
  glDisable(GL_BLEND);
}

void CameraRenderer::DrawFrame(const GpuScene& scene, const Eigen::Isometry3d& T_WC, TimeNs time_ns,
                               const BodyPoses& bodies) {
  const CameraIntrinsics& k = render_intrinsics_;
  const Eigen::Matrix3d R_CW = T_WC.linear().transpose();
  const SceneLighting& light = lighting_ ? *lighting_ : scene.lighting();
  const Eigen::Vector3f to_sun_C = (R_CW * -light.sun_direction_W.normalized()).cast<float>();
  const Eigen::Vector3f up_C = (R_CW * Eigen::Vector3d(0.0, 0.0, -1.0)).cast<float>();
  const SkyShading sky = CalcSkyShading(light);
  const auto camera_height_m = static_cast<float>(-T_WC.translation().z());

  const DetailLimit detail{std::max(k.fx_px, k.fy_px), detail_tolerance_px_};
  DrawShadow(scene, T_WC, bodies, light, detail);
  scene.CollectVisible(T_WC, planes_C_, bodies, visible_, detail);
  if (outputs_.rgb) ApplyClassMaterials(class_materials_, visible_.instances);
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

  // Geometry pass into every enabled target.
  glBindFramebuffer(GL_FRAMEBUFFER, geometry_target_.fbo);
  glViewport(0, 0, k.width_px, k.height_px);
  GLenum buffers[kTargets];
  for (int t = 0; t < kTargets; ++t) buffers[t] = Enabled(t) ? GL_COLOR_ATTACHMENT0 + t : GL_NONE;
  glDrawBuffers(kTargets, buffers);
  const GLfloat zero4[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const GLfloat sky_depth[4] = {kSkyDepthM, 0.0f, 0.0f, 0.0f};
  const GLuint no_label[4] = {0, 0, 0, 0};
  const GLfloat far_depth = 1.0f;
  glDepthMask(GL_TRUE);
  glClearBufferfv(GL_DEPTH, 0, &far_depth);
  if (outputs_.rgb) glClearBufferfv(GL_COLOR, kRgb, zero4);
  if (outputs_.depth_planar) glClearBufferfv(GL_COLOR, kDepthPlanar, sky_depth);
  if (outputs_.depth_perspective) glClearBufferfv(GL_COLOR, kDepthPerspective, sky_depth);
  if (outputs_.segmentation) {
    glClearBufferuiv(GL_COLOR, kClass, no_label);
    glClearBufferuiv(GL_COLOR, kInstance, no_label);
  }
  if (outputs_.normals) glClearBufferfv(GL_COLOR, kNormal, zero4);

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  // Rows run top-down in window space, which mirrors the image: outward (counter-clockwise) faces
  // arrive clockwise.
  glFrontFace(GL_CW);
  glDisable(GL_BLEND);

  // Each draw by the program of its batch's pattern and maps, given this frame's uniforms on first
  // use.
  const FrameUniforms frame{CalcProjection(k), to_sun_C, up_C, camera_height_m, sky, light};
  std::array<bool, kScenePrograms> ready{};
  const GlProgram* in_use = nullptr;
  for (const VisibleSet::Draw& d : visible_.draws) {
    const std::size_t index = SceneProgramIndex(scene.batches()[d.batch]);
    const GlProgram& program = SceneProgram(index);
    if (&program != in_use) {
      glUseProgram(program.id());
      in_use = &program;
    }
    if (!ready[index]) {
      SetSceneUniforms(program, frame);
      ready[index] = true;
    }
    scene.DrawBatch(
        d.batch, instance_buffer_, d.first, d.count,
        {program.Uniform("u_has_texture"), program.Uniform("u_has_normal_map"),
         program.Uniform("u_has_metallic_roughness_map"), program.Uniform("u_normal_scale")});
  }
  last_draw_calls_ = visible_.draws.size();
  last_triangles_ = visible_.triangles;
  glDisable(GL_CULL_FACE);
  if (shadow_) {  // the map is drawn into again next frame: not bound while it is
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
  }

  // Sky behind the geometry: only where the depth buffer still holds the far plane.
  if (outputs_.rgb) {
    GLenum rgb_only[kTargets] = {GL_COLOR_ATTACHMENT0, GL_NONE, GL_NONE, GL_NONE, GL_NONE, GL_NONE};
    glDrawBuffers(kTargets, rgb_only);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glUseProgram(sky_program_.id());
    glUniform4f(sky_program_.Uniform("u_intrinsics"), static_cast<float>(k.fx_px),
                static_cast<float>(k.fy_px), static_cast<float>(k.cx_px),
                static_cast<float>(k.cy_px));
    glUniform3fv(sky_program_.Uniform("u_to_sun_C"), 1, to_sun_C.data());
    glUniform3fv(sky_program_.Uniform("u_up_C"), 1, up_C.data());
    SetSkyUniforms(sky, light, camera_height_m);
    glBindVertexArray(empty_vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    if (light.rain_mm_per_h > 0.0f) DrawRain(light, sky, T_WC, time_ns, frame.projection);
    glDepthMask(GL_TRUE);
  }
  glDisable(GL_DEPTH_TEST);

  if (distorted_) {
    glBindFramebuffer(GL_FRAMEBUFFER, output_target_.fbo);
    glViewport(0, 0, intrinsics_.width_px, intrinsics_.height_px);
    glDrawBuffers(kTargets, buffers);
    glUseProgram(remap_program_.id());
    for (int t = 0; t < kTargets; ++t) {
      if (!Enabled(t)) continue;
      glActiveTexture(GL_TEXTURE0 + t);
      glBindTexture(GL_TEXTURE_2D, geometry_target_.textures[t]);
    }
    glActiveTexture(GL_TEXTURE0 + kTargets);
    glBindTexture(GL_TEXTURE_2D, remap_texture_);
    glBindVertexArray(empty_vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glActiveTexture(GL_TEXTURE0);
  }
  glBindVertexArray(0);
  CheckGl("camera frame");
}

void CameraRenderer::PrepareFrame(CameraFrame& out, TimeNs time_ns,
                                  const Eigen::Isometry3d& T_WC) const {
  const int w = intrinsics_.width_px;
  const int h = intrinsics_.height_px;
  out.time_ns = time_ns;
  out.T_WC = T_WC;
  auto shape = [&](auto& image, bool enabled, int channels) {
    if (enabled) {
      image.Resize(w, h, channels);
    } else {
      image = {};
    }
  };
  shape(out.rgba, outputs_.rgb, 4);
  shape(out.depth_planar_m, outputs_.depth_planar, 1);
  shape(out.depth_perspective_m, outputs_.depth_perspective, 1);
  shape(out.class_id, outputs_.segmentation, 1);
  shape(out.instance_id, outputs_.segmentation, 1);
  shape(out.normal_C, outputs_.normals, 3);
}

void* CameraRenderer::FrameBuffer(int target, CameraFrame& out) const {
  switch (target) {
    case kRgb:
      return out.rgba.pixels.data();
    case kDepthPlanar:
      return out.depth_planar_m.pixels.data();
    case kDepthPerspective:
      return out.depth_perspective_m.pixels.data();
    case kClass:
      return out.class_id.pixels.data();
    case kInstance:
      return out.instance_id.pixels.data();
    default:
      return out.normal_C.pixels.data();
  }
}

void CameraRenderer::DeliverFromBytes(int target, const void* bytes, CameraFrame& out) const {
  const std::size_t pixels = static_cast<std::size_t>(intrinsics_.width_px) * intrinsics_.height_px;
  const ReadFormat& r = read_formats_[target];
  if (r.direct) {
    std::memcpy(FrameBuffer(target, out), bytes, pixels * r.bytes_per_pixel);
    return;
  }
  // Four components per pixel: take the first (or the first three for normals).
  if (r.type == GL_FLOAT) {
    const auto* src = static_cast<const float*>(bytes);
    auto* dst = static_cast<float*>(FrameBuffer(target, out));
    const int channels = target == kNormal ? 3 : 1;
    for (std::size_t i = 0; i < pixels; ++i) {
      for (int c = 0; c < channels; ++c) dst[i * channels + c] = src[i * 4 + c];
    }
  } else {
    const auto* src = static_cast<const std::uint32_t*>(bytes);
    for (std::size_t i = 0; i < pixels; ++i) {
      if (target == kClass) {
        out.class_id.pixels[i] = static_cast<std::uint8_t>(src[i * 4]);
      } else {
        out.instance_id.pixels[i] = src[i * 4];
      }
    }
  }
}

void CameraRenderer::Render(const GpuScene& scene, const Eigen::Isometry3d& T_WC, TimeNs time_ns,
                            CameraFrame& out, const BodyPoses& bodies) {
  context_.MakeCurrent();
  DrawFrame(scene, T_WC, time_ns, bodies);
  PrepareFrame(out, time_ns, T_WC);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, output_target_.fbo);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  const std::size_t pixels = static_cast<std::size_t>(intrinsics_.width_px) * intrinsics_.height_px;
  for (int t = 0; t < kTargets; ++t) {
    if (!Enabled(t)) continue;
    const ReadFormat& r = read_formats_[t];
    glReadBuffer(GL_COLOR_ATTACHMENT0 + t);
    void* destination = FrameBuffer(t, out);
    if (!r.direct) {
      scratch_.resize(pixels * r.bytes_per_pixel);
      destination = scratch_.data();
    }
    glReadPixels(0, 0, intrinsics_.width_px, intrinsics_.height_px, r.format, r.type, destination);
    if (!r.direct) DeliverFromBytes(t, scratch_.data(), out);
  }
  CheckGl("camera readback");
}

void CameraRenderer::Submit(const GpuScene& scene, const Eigen::Isometry3d& T_WC, TimeNs time_ns,
                            const BodyPoses& bodies) {
  AIRIS_DEMAND(in_flight_ < kMaxInFlight);
  context_.MakeCurrent();
  DrawFrame(scene, T_WC, time_ns, bodies);
  Slot& slot = slots_[(next_slot_ + in_flight_) % kMaxInFlight];
  glBindFramebuffer(GL_READ_FRAMEBUFFER, output_target_.fbo);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, slot.pbo);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  for (int t = 0; t < kTargets; ++t) {
    if (!Enabled(t)) continue;
    glReadBuffer(GL_COLOR_ATTACHMENT0 + t);
    glReadPixels(0, 0, intrinsics_.width_px, intrinsics_.height_px, read_formats_[t].format,
                 read_formats_[t].type, reinterpret_cast<void*>(slot.offset[t]));
  }
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  slot.fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  glFlush();
  slot.time_ns = time_ns;
  slot.T_WC = T_WC;
  ++in_flight_;
  CheckGl("camera submit");
}

bool CameraRenderer::Collect(CameraFrame& out) {
  if (in_flight_ == 0) return false;
  context_.MakeCurrent();
  Slot& slot = slots_[next_slot_];
  glClientWaitSync(slot.fence, GL_SYNC_FLUSH_COMMANDS_BIT, GL_TIMEOUT_IGNORED);
  glDeleteSync(slot.fence);
  slot.fence = nullptr;
  PrepareFrame(out, slot.time_ns, slot.T_WC);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, slot.pbo);
  const std::size_t pixels = static_cast<std::size_t>(intrinsics_.width_px) * intrinsics_.height_px;
  for (int t = 0; t < kTargets; ++t) {
    if (!Enabled(t)) continue;
    const std::size_t length = pixels * read_formats_[t].bytes_per_pixel;
    const void* mapped =
        glMapBufferRange(GL_PIXEL_PACK_BUFFER, static_cast<GLintptr>(slot.offset[t]),
                         static_cast<GLsizeiptr>(length), GL_MAP_READ_BIT);
    if (mapped == nullptr) throw std::runtime_error("cannot map the readback buffer");
    DeliverFromBytes(t, mapped, out);
    glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
  }
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  next_slot_ = (next_slot_ + 1) % kMaxInFlight;
  --in_flight_;
  CheckGl("camera collect");
  return true;
}

}  // namespace airis::engine
