#pragma once

#include <GLES3/gl3.h>

#include <string>
#include <string_view>

namespace airis::engine {

/// A linked GLSL ES 3.00 program (owns the GL object; move-only). Needs a current context.
class GlProgram {
 public:
  GlProgram() = default;
  /// Compiles `vertex` and `fragment` (sources without `#version`), each prefixed with
  /// "#version 300 es\n" and `defines` (lines like "#define OUT_RGB 1\n"). Throws
  /// std::runtime_error with the compiler's log and `name` when compiling or linking fails.
  GlProgram(std::string_view name, std::string_view vertex, std::string_view fragment,
            const std::string& defines);
  ~GlProgram();
  GlProgram(GlProgram&& other) noexcept : id_(other.id_) { other.id_ = 0; }
  GlProgram& operator=(GlProgram&& other) noexcept;
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  GLuint id() const { return id_; }
  /// Location of uniform `name`, -1 if the program does not use it.
  GLint Uniform(const char* name) const { return glGetUniformLocation(id_, name); }

 private:
  GLuint id_ = 0;
};

/// Throws std::runtime_error naming `what` and the GL error if glGetError() reports one.
void CheckGl(const char* what);

}  // namespace airis::engine
