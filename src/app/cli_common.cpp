#include "app/cli_common.h"

#include <sys/resource.h>

#include "gl/backends.h"

namespace tg::app {

void checkBackend(std::string_view backend) {
  if (backend != "osmesa" && backend != "egl" && backend != "glfw" && backend != "auto")
    throw UsageError("--backend: unknown backend \"" + std::string(backend) + "\"; choose " + kBackendNames);
}

std::unique_ptr<gl::Context> createContext(std::string_view backend, int width, int height) {
  checkBackend(backend);
  if (backend == "egl") return gl::createEglContext({});
  if (backend == "glfw") return gl::createGlfwContext({width, height, false, "tensorglyph"});
  if (backend == "auto" && gl::eglHasHardwareDevice()) return gl::createEglContext({false});
  return gl::createOSMesaContext();  // "osmesa", or "auto" without a GPU
}

std::size_t peakRssBytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return std::size_t(u.ru_maxrss) * 1024;
}

}  // namespace tg::app
