#pragma once
// Constructors of the three context backends. Each throws std::runtime_error
// with a one-line reason when its platform is unavailable.
#include <memory>

#include "gl/context.h"

namespace tg::gl {

// Software rendering into memory (Mesa llvmpipe); works everywhere.
std::unique_ptr<Context> createOSMesaContext();

struct EglOptions {
  bool allowSoftware = true;  // Mesa's surfaceless platform when no GPU device exists
};
// Headless GPU through EGL_EXT_platform_device (NVIDIA), else Mesa surfaceless.
std::unique_ptr<Context> createEglContext(const EglOptions& opt);
// True when createEglContext would find a hardware (non-software) device.
bool eglHasHardwareDevice();

struct GlfwOptions {
  int width = 1280, height = 800;
  bool visible = true;
  const char* title = "tensorglyph";
};
std::unique_ptr<Context> createGlfwContext(const GlfwOptions& opt);

}  // namespace tg::gl
