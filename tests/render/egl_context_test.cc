#include "engine/render/egl_context.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include "tests/render/render_test_util.h"

namespace airis::engine {
namespace {

TEST(EglContextTest, ReportsTheGlStrings) {
  const EglContext& context = testing::SharedContext();
  EXPECT_FALSE(context.gl_vendor().empty());
  EXPECT_FALSE(context.gl_renderer().empty());
  EXPECT_NE(context.gl_version().find("OpenGL ES 3"), std::string::npos) << context.gl_version();
  EXPECT_FALSE(context.platform().empty());
  // Float32 depth needs float render targets; llvmpipe and NVIDIA both offer them.
  EXPECT_TRUE(context.HasExtension("GL_EXT_color_buffer_float"));
  EXPECT_FALSE(context.HasExtension("GL_EXT_color_buffer"));  // whole tokens only
  std::printf("EGL platform: %s, GL: %s | %s | %s\n", context.platform().c_str(),
              context.gl_vendor().c_str(), context.gl_renderer().c_str(),
              context.gl_version().c_str());
}

TEST(EglContextTest, UnknownPlatformInEnvironmentIsAConfigError) {
  setenv(kEglPlatformEnv, "wayland", 1);
  try {
    EglContext context;
    unsetenv(kEglPlatformEnv);
    FAIL() << "expected ConfigError";
  } catch (const ConfigError& e) {
    unsetenv(kEglPlatformEnv);
    const std::string message = e.what();
    EXPECT_NE(message.find("AIRIS_EGL_PLATFORM"), std::string::npos) << message;
    EXPECT_NE(message.find("wayland"), std::string::npos) << message;
    EXPECT_NE(message.find("surfaceless"), std::string::npos) << message;
  }
}

TEST(EglContextTest, ExplicitPlatformIsHonoured) {
  // Mesa offers the surfaceless platform with llvmpipe; an NVIDIA-only libEGL offers the device
  // platform. Whichever the automatic choice used, asking for it by name must give the same kind.
  const std::string automatic = testing::SharedContext().platform();
  const EglPlatform kind =
      automatic == "surfaceless" ? EglPlatform::kSurfaceless : EglPlatform::kDevice;
  EglContext context(kind);
  EXPECT_EQ(context.platform().rfind(automatic == "surfaceless" ? "surfaceless" : "device", 0), 0u)
      << context.platform();
  testing::SharedContext();  // current again for the other tests
}

}  // namespace
}  // namespace airis::engine
