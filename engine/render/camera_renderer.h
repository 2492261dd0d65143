#pragma once

#include <GLES3/gl3.h>

#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/camera_frame.h"
#include "engine/core/camera_model.h"
#include "engine/render/egl_context.h"
#include "engine/render/gl_program.h"
#include "engine/render/gpu_scene.h"
#include "engine/render/sun_shadow.h"

namespace airis::engine {

struct SkyShading;

/// Renders one camera's images of a GpuScene: frustum culling, one instanced geometry pass into
/// multiple render targets (RGB, planar depth, perspective depth, class id, instance id, normals),
/// the sky, the lens distortion remap when the camera has one, and readback.
///
/// Projection: pinhole with the camera's intrinsics; image rows are rendered top-down (row 0 of the
/// GL framebuffer is image row 0), so readback needs no flip. With distortion, the scene is first
/// rendered undistorted at the same focal length over the (larger) region that the distorted image
/// sees, then every output pixel takes the undistorted sample its ray maps to
/// (CameraIntrinsics::CalcRay of the pixel centre, i.e. the Brown-Conrady model inverted by
/// Newton's method, once, into a lookup texture).
///
/// Readback: Render() reads straight into the frame's buffers (no staging copy). Submit()/Collect()
/// read into pixel buffer objects instead, so the GPU renders the next frame (another camera, or
/// this camera's next pose) while the previous transfer completes; Collect() copies each image once
/// from the mapped buffer. All calls need `context` current.
class CameraRenderer {
 public:
  /// How far (in pixels) a far object's coarser look may stray from its own surfaces by default
  /// (DetailLimit; 0 draws every object with its own parts).
  static constexpr double kDefaultDetailTolerancePx = 1.0;
  /// Frames that may be in flight between Submit() and Collect().
  static constexpr int kMaxInFlight = 2;

  /// Builds the render targets and shader variants. Throws InvalidField on bad intrinsics or
  /// outputs (also when the distortion model folds inside the image), std::runtime_error when the
  /// GL lacks float render targets (EXT_color_buffer_float) or a shader fails to build.
  /// `detail_tolerance_px`: how far a far object's coarser look may stray (DetailLimit).
  CameraRenderer(const EglContext& context, const CameraIntrinsics& intrinsics,
                 const RenderOutputs& outputs,
                 double detail_tolerance_px = kDefaultDetailTolerancePx);
  ~CameraRenderer();
  CameraRenderer(const CameraRenderer&) = delete;
  CameraRenderer& operator=(const CameraRenderer&) = delete;

  /// Renders `scene` seen from T_WC (optical frame C -> world NED) at simulated time `time_ns`,
  /// its vehicle bodies where `bodies` puts them (none by default), and reads the enabled outputs
  /// into `out` (reusing its buffers).
  void Render(const GpuScene& scene, const Eigen::Isometry3d& T_WC, TimeNs time_ns,
              CameraFrame& out, const BodyPoses& bodies = {});

  /// Renders and starts an asynchronous readback. Requires frames_in_flight() < kMaxInFlight.
  void Submit(const GpuScene& scene, const Eigen::Isometry3d& T_WC, TimeNs time_ns,
              const BodyPoses& bodies = {});
  /// Completes the oldest submitted frame into `out` (waiting for it if needed). Returns false when
  /// none is in flight.
  bool Collect(CameraFrame& out);
  int frames_in_flight() const { return in_flight_; }

  /// Lights the next frames with `lighting` instead of the scene's (a dataset's randomized sun and
  /// fog); nullopt returns to the scene's.
  void set_lighting(std::optional<SceneLighting> lighting) { lighting_ = std::move(lighting); }
  /// Changes the materials of these classes in the next frames' colour images (a dataset's
  /// randomized materials; ChangeBaseColour); empty for the scene's own.
  void set_class_materials(std::vector<ClassMaterialChange> changes) {
    class_materials_ = std::move(changes);
  }
  /// The time the shutter is open (s; default 1/125 s): how long the rain's streaks are. A camera
  /// sensor sets its CameraEffectsConfig::exposure_time_s.
  void set_exposure_time_s(double exposure_s) { exposure_time_s_ = exposure_s; }
  /// The air's velocity at the camera (world NED, m/s) for the next frames: the rain's drops
  /// drift with it (zero by default). A camera sensor sets the environment's wind there.
  void set_wind_W(const Eigen::Vector3d& wind_W) { wind_W_ = wind_W; }

  const CameraIntrinsics& intrinsics() const { return intrinsics_; }
  /// Intrinsics of the undistorted image the geometry pass renders (equal to intrinsics() without
  /// distortion).
  const CameraIntrinsics& render_intrinsics() const { return render_intrinsics_; }
  const RenderOutputs& outputs() const { return outputs_; }
  /// Draw calls and triangles submitted by the last frame (after culling).
  std::size_t last_draw_calls() const { return last_draw_calls_; }
  std::size_t last_triangles() const { return last_triangles_; }
  /// Triangles the last frame drew into the sun's shadow map (0 without shadows): the bodies', and
  /// the static casters' in a frame that drew them again (SunShadow keeps their map).
  std::size_t last_shadow_triangles() const { return last_shadow_triangles_; }
  /// Whether the last frame drew the static casters into the sun's map (false without shadows, or
  /// when it kept the map of an earlier frame).
  bool last_shadow_map_redrawn() const { return shadow_ && sun_shadow_->last_drew_static(); }

 private:
  static constexpr int kTargets = 6;  // attachment index = fragment output location in the shaders
  struct RenderTarget {
    GLuint fbo = 0;
    GLuint depth = 0;  // renderbuffer, geometry pass only
    std::array<GLuint, kTargets> textures{};
    int width = 0;
    int height = 0;
  };
  struct ReadFormat {
    GLenum format = 0;
    GLenum type = 0;
    int bytes_per_pixel = 0;
    bool direct = false;  // the bytes are already the frame's layout
  };
  struct Slot {
    GLuint pbo = 0;
    std::array<std::size_t, kTargets> offset{};
    GLsync fence = nullptr;
    TimeNs time_ns = 0;
    Eigen::Isometry3d T_WC = Eigen::Isometry3d::Identity();
  };

  bool Enabled(int target) const;
  RenderTarget CreateTarget(int width, int height, bool sampled, bool with_depth) const;
  void DestroyTarget(RenderTarget& target) const;
  void DrawFrame(const GpuScene& scene, const Eigen::Isometry3d& T_WC, TimeNs time_ns,
                 const BodyPoses& bodies);
  // Rain streaks over the colour image (rain_program_; docs/rendering.md, "Rain"), after the sky.
  void DrawRain(const SceneLighting& light, const SkyShading& sky, const Eigen::Isometry3d& T_WC,
                TimeNs time_ns, const Eigen::Matrix4f& projection);
  // Draws the sun's shadow map for this frame when the lighting asks for shadows and the sun is up.
  void DrawShadow(const GpuScene& scene, const Eigen::Isometry3d& T_WC, const BodyPoses& bodies,
                  const SceneLighting& light, const DetailLimit& detail);
  // What every scene program needs of a frame.
  struct FrameUniforms {
    Eigen::Matrix4f projection;
    Eigen::Vector3f to_sun_C;
    Eigen::Vector3f up_C;
    float camera_height_m = 0.0f;
    const SkyShading& sky;
    const SceneLighting& light;
  };
  // Scene programs: one per surface pattern, with and without maps (scene.frag's PATTERN and
  // TEXTURED), made on first use. The index of the one that draws `batch`, and that program.
  static constexpr std::size_t kScenePrograms = 2 * kSurfacePatterns;
  std::size_t SceneProgramIndex(const GpuScene::Batch& batch) const;
  const GlProgram& SceneProgram(std::size_t index);
  // `program`'s uniforms for this frame (the program in use).
  void SetSceneUniforms(const GlProgram& program, const FrameUniforms& frame);
  void SetShadowUniforms(const GlProgram& program, const std::optional<ShadowFrame>& shadow,
                         const SceneLighting& light);
  // The sky program's uniforms for this frame (sky_program_ in use).
  void SetSkyUniforms(const SkyShading& sky, const SceneLighting& light, float camera_height_m);
  void PrepareFrame(CameraFrame& out, TimeNs time_ns, const Eigen::Isometry3d& T_WC) const;
  void DeliverFromBytes(int target, const void* bytes, CameraFrame& out) const;
  void* FrameBuffer(int target, CameraFrame& out) const;

  const EglContext& context_;
  CameraIntrinsics intrinsics_;
  CameraIntrinsics render_intrinsics_;
  double exposure_time_s_ = 1.0 / 125.0;
  Eigen::Vector3d wind_W_ = Eigen::Vector3d::Zero();
  RenderOutputs outputs_;
  double detail_tolerance_px_;
  std::optional<SceneLighting> lighting_;  // replaces the scene's when set
  std::vector<ClassMaterialChange> class_materials_;
  bool distorted_ = false;
  std::string scene_defines_;  // the outputs' defines of every scene program
  std::array<GlProgram, kScenePrograms> scene_programs_;  // by SceneProgramIndex
  GlProgram sky_program_;
  GlProgram rain_program_;  // made when a frame first has rain
  GlProgram remap_program_;
  RenderTarget geometry_target_;
  RenderTarget output_target_;  // == geometry_target_ without distortion
  GLuint remap_texture_ = 0;
  GLuint empty_vao_ = 0;
  GLuint instance_buffer_ = 0;
  std::size_t instance_capacity_ = 0;
  std::array<ReadFormat, kTargets> read_formats_{};
  std::array<Slot, kMaxInFlight> slots_{};
  int next_slot_ = 0;
  int in_flight_ = 0;
  std::vector<Eigen::Vector4d> planes_C_;
  VisibleSet visible_;
  std::vector<unsigned char> scratch_;
  std::size_t last_draw_calls_ = 0;
  std::size_t last_triangles_ = 0;
  std::size_t last_shadow_triangles_ = 0;
  std::unique_ptr<SunShadow> sun_shadow_;  // made at the first frame with shadows
  std::optional<ShadowFrame> shadow_;      // this frame's, when drawn
};

}  // namespace airis::engine
