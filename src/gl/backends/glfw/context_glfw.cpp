#include "gl/backends/glfw/context_glfw.h"

#define GLFW_INCLUDE_NONE  // our entry points come from glcorearb.h, not gl.h
#include <GLFW/glfw3.h>

#include <stdexcept>
#include <string>

namespace tg::gl {
namespace {

std::string glfwReason() {
  const char* desc = nullptr;
  glfwGetError(&desc);
  return desc ? desc : "unknown GLFW error";
}

class GlfwBackend final : public Context {
 public:
  explicit GlfwBackend(const GlfwOptions& opt) {
    if (!glfwInit()) throw std::runtime_error("createGlfwContext: " + glfwReason());
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, opt.visible ? GLFW_TRUE : GLFW_FALSE);
    window_ = glfwCreateWindow(opt.width, opt.height, opt.title, nullptr, nullptr);
    if (!window_) {
      const std::string why = glfwReason();
      glfwTerminate();
      throw std::runtime_error("createGlfwContext: " + why);
    }
    makeCurrent();
    loadEntryPoints();
  }
  ~GlfwBackend() override {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  const char* backendName() const override { return "glfw"; }
  void makeCurrent() override { glfwMakeContextCurrent(window_); }
  void releaseCurrent() override { glfwMakeContextCurrent(nullptr); }
  void* procAddress(const char* name) const override { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }
  GLFWwindow* window() const { return window_; }

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace

std::unique_ptr<Context> createGlfwContext(const GlfwOptions& opt) { return std::make_unique<GlfwBackend>(opt); }

GLFWwindow* glfwWindowOf(Context& ctx) {
  auto* g = dynamic_cast<GlfwBackend*>(&ctx);
  return g ? g->window() : nullptr;
}

}  // namespace tg::gl
