#pragma once
// A linked GLSL program composed from the shader library.
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "gl/loader.h"
#include "gl/shader_library.h"

namespace tg::gl {

struct StageSource {
  GLenum stage;
  std::string_view path;
};

class Program {
 public:
  // Throws std::runtime_error with file:line messages on compile or link
  // errors, and for an option in `enable` that no stage declares. `enable`
  // is a list callers can build at run time (a variant's options).
  Program(const Api& gl, const ShaderLibrary& lib, std::initializer_list<StageSource> stages,
          std::vector<std::string_view> enable = {});
  ~Program();
  Program(Program&& o) noexcept
      : gl_(o.gl_), id_(std::exchange(o.id_, 0)), locations_(std::move(o.locations_)) {}
  Program& operator=(Program&&) = delete;
  Program(const Program&) = delete;

  GLuint id() const { return id_; }
  void set(const char* name, int v) const;
  void set(const char* name, float v) const;
  void set(const char* name, const glm::vec2& v) const;
  void set(const char* name, const glm::vec3& v) const;
  void set(const char* name, const glm::vec4& v) const;
  void set(const char* name, std::span<const glm::vec4> v) const;
  void set(const char* name, const glm::mat3& v) const;
  void set(const char* name, const glm::mat4& v) const;

 private:
  // Uniform locations as first asked for: glGetUniformLocation parses and
  // hashes the name on every call, which was most of a parameter change's
  // CPU time. A cache, so const.
  GLint location(const char* name) const;
  const Api* gl_;
  GLuint id_ = 0;
  mutable std::vector<std::pair<std::string, GLint>> locations_;
};

}  // namespace tg::gl
