// tensorglyph-gpubench: `tensorglyph bench scale` through EGL alone. It links
// the render core and libEGL and nothing else (no VTK, OpenImageIO, Teem or
// GLFW), so that it can be built here and carried to a GPU machine that has
// none of them.
#include <cstdio>
#include <exception>

#include "app/scale/cli_values.h"
#include "app/scale/scale_sweep.h"
#include "gl/backends.h"

int main(int argc, const char** argv) {
  using namespace tg::app;
  try {
    ScaleOptions defaults;
    defaults.backend = "egl";
    const ScaleOptions o = parseScaleOptions(argc, argv, defaults, "tensorglyph-gpubench");
    checkScaleOptions(o);
    if (o.backend != "egl") throw UsageError("--backend: this executable has only egl");
    auto ctx = tg::gl::createEglContext({!o.requireGpu});
    runScaleSweep(*ctx, o);
    return 0;
  } catch (const HelpShown&) {
    return 0;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "tensorglyph-gpubench: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tensorglyph-gpubench: %s\n", e.what());
    return 1;
  }
}
