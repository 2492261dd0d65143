#pragma once

#include <memory>

#include "engine/render/egl_context.h"
#include "engine/render/gpu_scene.h"
#include "engine/scene/static_scene.h"

namespace airis::engine {

/// What every camera of a simulation shares: the EGL context and the static scene uploaded once.
/// Cameras hold it by shared_ptr; all use it from one thread (the simulation thread).
class RenderScene {
 public:
  /// Creates the context (see EglContext) and uploads `scene`. Throws what EglContext and GpuScene
  /// throw.
  explicit RenderScene(const StaticScene& scene, EglPlatform platform = EglPlatform::kAuto)
      : context_(platform), gpu_scene_((context_.MakeCurrent(), scene)) {}

  /// Makes the context current so the scene's GL objects are deleted in it.
  ~RenderScene() { context_.MakeCurrent(); }
  RenderScene(const RenderScene&) = delete;
  RenderScene& operator=(const RenderScene&) = delete;

  const EglContext& context() const { return context_; }
  const GpuScene& gpu_scene() const { return gpu_scene_; }

 private:
  EglContext context_;
  GpuScene gpu_scene_;
};

}  // namespace airis::engine
