#pragma once

#include <memory>
#include <span>
#include <string>

#include "engine/core/config.h"

namespace airis::engine {

/// Which EGL platform makes the display. kAuto tries, in order: the device platform on a hardware
/// device (EGL_EXT_platform_device: NVIDIA's EGL, or Mesa on a GPU), Mesa's surfaceless platform
/// (EGL_MESA_platform_surfaceless: llvmpipe where there is no GPU), then any device (Mesa's
/// software device).
enum class EglPlatform { kAuto, kDevice, kSurfaceless };
std::span<const EnumName<EglPlatform>> EnumNames(EglPlatform);

/// Environment variable that overrides the platform: "auto", "device" or "surfaceless".
inline constexpr const char* kEglPlatformEnv = "AIRIS_EGL_PLATFORM";

/// An OpenGL ES 3 context with no window, no surface and no X server (EGL_KHR_surfaceless_context):
/// every render goes into framebuffer objects. The context is made current on the constructing
/// thread; call MakeCurrent() before using it from another thread (one thread at a time).
class EglContext {
 public:
  /// Creates the display and an ES 3.0+ context. `platform` kAuto defers to $AIRIS_EGL_PLATFORM,
  /// then to the automatic order. Throws std::runtime_error naming every platform tried, why each
  /// failed and what to install, when no context can be made; ConfigError on a bad
  /// $AIRIS_EGL_PLATFORM.
  explicit EglContext(EglPlatform platform = EglPlatform::kAuto);
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  /// Makes this context current on the calling thread (cheap when it already is).
  void MakeCurrent() const;

  /// The platform that succeeded ("device", "surfaceless").
  const std::string& platform() const { return platform_; }
  /// GL_VENDOR, GL_RENDERER, GL_VERSION strings (e.g. "Mesa", "llvmpipe (LLVM 15.0.6, 256 bits)").
  const std::string& gl_vendor() const { return gl_vendor_; }
  const std::string& gl_renderer() const { return gl_renderer_; }
  const std::string& gl_version() const { return gl_version_; }
  /// True when the GL extension `name` is supported.
  bool HasExtension(const char* name) const;

 private:
  struct Handles;
  std::unique_ptr<Handles> egl_;
  std::string platform_;
  std::string gl_vendor_;
  std::string gl_renderer_;
  std::string gl_version_;
  std::string gl_extensions_;
};

}  // namespace airis::engine
