#include "gl/program.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "gl/program_cache.h"

namespace tg::gl {
namespace {

std::string shaderLog(const Api& gl, GLuint s) {
  GLint len = 0;
  gl.GetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
  std::string log(std::size_t(std::max(len, 1)), '\0');
  gl.GetShaderInfoLog(s, len, nullptr, log.data());
  return log.c_str();
}

}  // namespace

Program::Program(const Api& gl, const ShaderLibrary& lib, std::initializer_list<StageSource> stages,
                 std::vector<std::string_view> enable)
    : gl_(&gl) {
  const std::vector<std::string_view>& wanted = enable;
  std::vector<ComposedSource> sources;
  for (const StageSource& st : stages) sources.push_back(lib.compose(st.path, wanted));
  for (std::string_view e : wanted) {
    const bool declared = std::any_of(sources.begin(), sources.end(), [&](const ComposedSource& c) {
      return std::find(c.options.begin(), c.options.end(), e) != c.options.end();
    });
    if (!declared)
      throw std::runtime_error("Program: no stage of " + std::string(stages.begin()->path) + " declares option \"" +
                               std::string(e) + "\"");
  }
  const ProgramCache cache(gl);
  std::string key;
  if (cache.enabled()) {
    std::vector<std::pair<GLenum, std::string_view>> keyed;
    for (std::size_t k = 0; k < sources.size(); ++k) keyed.emplace_back(stages.begin()[k].stage, sources[k].text);
    key = cache.key(keyed);
    id_ = gl.CreateProgram();
    if (cache.load(id_, key)) return;
    gl.DeleteProgram(id_);
  }
  id_ = gl.CreateProgram();
  if (cache.enabled()) gl.ProgramParameteri(id_, GL_PROGRAM_BINARY_RETRIEVABLE_HINT, GL_TRUE);
  std::vector<GLuint> shaders;
  auto cleanup = [&] {
    for (GLuint s : shaders) gl.DeleteShader(s);
  };
  for (std::size_t k = 0; k < sources.size(); ++k) {
    const StageSource& st = stages.begin()[k];
    const ComposedSource& src = sources[k];
    const GLuint s = gl.CreateShader(st.stage);
    shaders.push_back(s);
    const char* text = src.text.c_str();
    gl.ShaderSource(s, 1, &text, nullptr);
    gl.CompileShader(s);
    GLint ok = 0;
    gl.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      const std::string log = ShaderLibrary::mapLog(shaderLog(gl, s), src);
      cleanup();
      gl.DeleteProgram(id_);
      throw std::runtime_error("Program: compiling " + std::string(st.path) + " failed:\n" + log);
    }
    gl.AttachShader(id_, s);
  }
  gl.LinkProgram(id_);
  GLint ok = 0;
  gl.GetProgramiv(id_, GL_LINK_STATUS, &ok);
  for (GLuint s : shaders) gl.DetachShader(id_, s);
  cleanup();
  if (!ok) {
    GLint len = 0;
    gl.GetProgramiv(id_, GL_INFO_LOG_LENGTH, &len);
    std::string log(std::size_t(std::max(len, 1)), '\0');
    gl.GetProgramInfoLog(id_, len, nullptr, log.data());
    gl.DeleteProgram(id_);
    throw std::runtime_error("Program: linking " + std::string(stages.begin()->path) + " failed:\n" + log.c_str());
  }
  cache.store(id_, key);
}

Program::~Program() {
  if (id_) gl_->DeleteProgram(id_);
}

GLint Program::location(const char* name) const {
  for (const auto& [n, loc] : locations_)
    if (n == name) return loc;
  const GLint loc = gl_->GetUniformLocation(id_, name);
  locations_.emplace_back(name, loc);
  return loc;
}

void Program::set(const char* n, int v) const { gl_->ProgramUniform1i(id_, location(n), v); }
void Program::set(const char* n, float v) const { gl_->ProgramUniform1f(id_, location(n), v); }
void Program::set(const char* n, const glm::vec2& v) const {
  gl_->ProgramUniform2f(id_, location(n), v.x, v.y);
}
void Program::set(const char* n, const glm::vec3& v) const {
  gl_->ProgramUniform3f(id_, location(n), v.x, v.y, v.z);
}
void Program::set(const char* n, const glm::vec4& v) const {
  gl_->ProgramUniform4f(id_, location(n), v.x, v.y, v.z, v.w);
}
void Program::set(const char* n, std::span<const glm::vec4> v) const {
  gl_->ProgramUniform4fv(id_, location(n), GLsizei(v.size()), glm::value_ptr(v[0]));
}
void Program::set(const char* n, const glm::mat3& v) const {
  gl_->ProgramUniformMatrix3fv(id_, location(n), 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::mat4& v) const {
  gl_->ProgramUniformMatrix4fv(id_, location(n), 1, GL_FALSE, glm::value_ptr(v));
}

}  // namespace tg::gl
