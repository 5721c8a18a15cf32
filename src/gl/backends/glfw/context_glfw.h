#pragma once
// The windowed backend, with access to its window for the viewer.
#include "gl/backends.h"

struct GLFWwindow;

namespace tg::gl {

// The GLFW window behind a context made by createGlfwContext, or nullptr.
GLFWwindow* glfwWindowOf(Context& ctx);

}  // namespace tg::gl
