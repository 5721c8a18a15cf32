#include "app/cli_common.h"

#include <sys/resource.h>

#include <charconv>
#include <cmath>

#include "gl/backends.h"

namespace tg::app {

double parseDouble(std::string_view flag, std::string_view text) {
  double v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty() || !std::isfinite(v))
    throw UsageError(std::string(flag) + ": \"" + std::string(text) + "\" is not a finite number");
  return v;
}

long long parseInt(std::string_view flag, std::string_view text) {
  long long v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty())
    throw UsageError(std::string(flag) + ": \"" + std::string(text) + "\" is not an integer");
  return v;
}

glm::dvec3 parseVec3(std::string_view flag, std::span<const char* const> a) {
  if (a.size() != 3) throw UsageError(std::string(flag) + " needs 3 numbers");
  return {parseDouble(flag, a[0]), parseDouble(flag, a[1]), parseDouble(flag, a[2])};
}

void checkBackend(std::string_view backend) {
  if (backend != "osmesa" && backend != "egl" && backend != "glfw" && backend != "auto")
    throw UsageError("--backend: unknown backend \"" + std::string(backend) + "\"; choose osmesa, egl, glfw or auto");
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
