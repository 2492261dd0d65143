#include "engine/render/gl_program.h"

#include <cstdio>
#include <stdexcept>
#include <vector>

namespace airis::engine {

namespace {

GLuint Compile(GLenum type, std::string_view name, std::string_view body,
               const std::string& defines) {
  const std::string source = "#version 300 es\n" + defines + std::string(body);
  const GLuint shader = glCreateShader(type);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length) + 1, '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    throw std::runtime_error(std::string("shader ") + std::string(name) +
                             (type == GL_VERTEX_SHADER ? " (vertex)" : " (fragment)") +
                             " does not compile:\n" + log.data());
  }
  return shader;
}

}  // namespace

GlProgram::GlProgram(std::string_view name, std::string_view vertex, std::string_view fragment,
                     const std::string& defines) {
  const GLuint vs = Compile(GL_VERTEX_SHADER, name, vertex, defines);
  GLuint fs = 0;
  try {
    fs = Compile(GL_FRAGMENT_SHADER, name, fragment, defines);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glLinkProgram(id_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length) + 1, '\0');
    glGetProgramInfoLog(id_, length, nullptr, log.data());
    glDeleteProgram(id_);
    id_ = 0;
    throw std::runtime_error("shader program " + std::string(name) + " does not link:\n" +
                             log.data());
  }
}

GlProgram::~GlProgram() {
  if (id_ != 0) glDeleteProgram(id_);
}

GlProgram& GlProgram::operator=(GlProgram&& other) noexcept {
  if (this != &other) {
    if (id_ != 0) glDeleteProgram(id_);
    id_ = other.id_;
    other.id_ = 0;
  }
  return *this;
}

void CheckGl(const char* what) {
  const GLenum error = glGetError();
  if (error == GL_NO_ERROR) return;
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "0x%04X", static_cast<unsigned>(error));
  throw std::runtime_error(std::string("OpenGL error ") + buffer + " in " + what);
}

}  // namespace airis::engine
