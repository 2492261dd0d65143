#include "engine/render/egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "engine/core/error.h"

namespace airis::engine {

namespace {

constexpr EnumName<EglPlatform> kEglPlatformNames[] = {{EglPlatform::kAuto, "auto"},
                                                       {EglPlatform::kDevice, "device"},
                                                       {EglPlatform::kSurfaceless, "surfaceless"}};

bool HasToken(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n) {
    const bool starts = p == list || p[-1] == ' ';
    const bool ends = p[n] == ' ' || p[n] == '\0';
    if (starts && ends) return true;
  }
  return false;
}

std::string EglErrorText() {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "EGL error 0x%04X", static_cast<unsigned>(eglGetError()));
  return buffer;
}

// One way of making a display: a device (hardware or Mesa's software device) or the surfaceless
// platform.
struct Candidate {
  std::string name;
  EGLenum platform = 0;
  void* native = nullptr;
};

std::vector<Candidate> ListDevices(bool software, std::string& why_none) {
  std::vector<Candidate> out;
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!HasToken(client, "EGL_EXT_platform_device") ||
      !HasToken(client, "EGL_EXT_device_enumeration")) {
    why_none = "EGL_EXT_platform_device / EGL_EXT_device_enumeration not offered by libEGL";
    return out;
  }
  auto query_devices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  auto query_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
      eglGetProcAddress("eglQueryDeviceStringEXT"));
  EGLDeviceEXT devices[16];
  EGLint count = 0;
  if (query_devices == nullptr || !query_devices(16, devices, &count) || count == 0) {
    why_none = "no EGL device found";
    return out;
  }
  for (EGLint i = 0; i < count; ++i) {
    const char* ext = query_string ? query_string(devices[i], EGL_EXTENSIONS) : nullptr;
    const bool is_software = HasToken(ext, "EGL_MESA_device_software");
    if (is_software != software) continue;
    out.push_back({std::string(software ? "device (software) #" : "device #") + std::to_string(i),
                   EGL_PLATFORM_DEVICE_EXT, devices[i]});
  }
  if (out.empty()) why_none = software ? "no software EGL device" : "no hardware EGL device";
  return out;
}

}  // namespace

std::span<const EnumName<EglPlatform>> EnumNames(EglPlatform) { return kEglPlatformNames; }

struct EglContext::Handles {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
};

EglContext::EglContext(EglPlatform platform) : egl_(std::make_unique<Handles>()) {
  if (platform == EglPlatform::kAuto) {
    if (const char* env = std::getenv(kEglPlatformEnv); env != nullptr && *env != '\0') {
      const auto parsed = ParseEnum<EglPlatform>(env);
      if (!parsed) {
        throw ConfigError({}, kEglPlatformEnv,
                          std::string("unknown EGL platform (got '") + env + "'; expected " +
                              EnumChoices<EglPlatform>() + ")");
      }
      platform = *parsed;
    }
  }

  // The candidates in the order of EglPlatform's comment; every failure is kept for the message.
  std::vector<std::string> tried;
  std::vector<Candidate> candidates;
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (platform != EglPlatform::kSurfaceless) {
    std::string why;
    auto hardware = ListDevices(false, why);
    if (hardware.empty()) tried.push_back("device: " + why);
    candidates.insert(candidates.end(), hardware.begin(), hardware.end());
  }
  if (platform != EglPlatform::kDevice) {
    if (HasToken(client, "EGL_MESA_platform_surfaceless")) {
      candidates.push_back({"surfaceless", EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY});
    } else {
      tried.push_back("surfaceless: EGL_MESA_platform_surfaceless not offered by libEGL");
    }
  }
  if (platform != EglPlatform::kSurfaceless) {
    std::string why;
    auto software = ListDevices(true, why);
    candidates.insert(candidates.end(), software.begin(), software.end());
  }

  auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  for (const Candidate& c : candidates) {
    if (get_display == nullptr) {
      tried.push_back(c.name + ": eglGetPlatformDisplayEXT missing");
      continue;
    }
    EGLDisplay display = get_display(c.platform, c.native, nullptr);
    EGLint major = 0;
    EGLint minor = 0;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
      tried.push_back(c.name + ": eglInitialize failed (" + EglErrorText() + ")");
      continue;
    }
    const char* display_ext = eglQueryString(display, EGL_EXTENSIONS);
    if (!HasToken(display_ext, "EGL_KHR_surfaceless_context")) {
      tried.push_back(c.name + ": no EGL_KHR_surfaceless_context");
      continue;
    }
    if (!eglBindAPI(EGL_OPENGL_ES_API)) {
      tried.push_back(c.name + ": OpenGL ES API unavailable (" + EglErrorText() + ")");
      continue;
    }
    const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_SURFACE_TYPE,
                                        0, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    eglChooseConfig(display, config_attributes, &config, 1, &configs);
    if (configs == 0) {
      if (!HasToken(display_ext, "EGL_KHR_no_config_context")) {
        tried.push_back(c.name + ": no OpenGL ES 3 config");
        continue;
      }
      config = nullptr;  // EGL_NO_CONFIG_KHR
    }
    const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0,
                                         EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
    if (context == EGL_NO_CONTEXT) {
      tried.push_back(c.name + ": eglCreateContext(ES 3.0) failed (" + EglErrorText() + ")");
      continue;
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
      tried.push_back(c.name + ": eglMakeCurrent without a surface failed (" + EglErrorText() +
                      ")");
      eglDestroyContext(display, context);
      continue;
    }
    egl_->display = display;
    egl_->context = context;
    platform_ = c.name;
    break;
  }

  if (egl_->context == EGL_NO_CONTEXT) {
    std::string message = "cannot create a headless OpenGL ES 3 context with EGL. Tried (" +
                          std::string(ToString(platform)) + "):";
    for (const auto& t : tried) message += "\n  - " + t;
    if (tried.empty()) message += "\n  - nothing: libEGL offers neither platform";
    message +=
        "\nInstall Mesa's EGL and software rasteriser (Debian/Ubuntu: apt install libegl1 "
        "libegl-mesa0 "
        "libgl1-mesa-dri libgles2) or the NVIDIA driver's EGL (libEGL_nvidia), or pick a platform "
        "with " +
        std::string(kEglPlatformEnv) + "=device|surfaceless.";
    throw std::runtime_error(message);
  }

  auto gl_string = [](GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
  };
  gl_vendor_ = gl_string(GL_VENDOR);
  gl_renderer_ = gl_string(GL_RENDERER);
  gl_version_ = gl_string(GL_VERSION);
  gl_extensions_ = gl_string(GL_EXTENSIONS);
}

EglContext::~EglContext() {
  // The display is left initialised: EGL displays are shared per process and not reference counted,
  // so terminating it would break any other context on it.
  if (egl_->context != EGL_NO_CONTEXT) {
    if (eglGetCurrentContext() == egl_->context) {
      eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    eglDestroyContext(egl_->display, egl_->context);
  }
}

void EglContext::MakeCurrent() const {
  if (eglGetCurrentContext() == egl_->context) return;
  if (!eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, egl_->context)) {
    throw std::runtime_error("eglMakeCurrent failed (" + EglErrorText() + ")");
  }
}

bool EglContext::HasExtension(const char* name) const {
  return HasToken(gl_extensions_.c_str(), name);
}

}  // namespace airis::engine
