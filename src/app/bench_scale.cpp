// tensorglyph bench scale: the scale sweep (app/scale/scale_sweep.h) on any backend.
#include <cstdio>

#include "app/bench.h"
#include "app/cli_common.h"
#include "app/progress.h"
#include "app/scale/scale_sweep.h"
#include "gl/backends.h"

namespace tg::app {

int benchScale(int argc, const char** argv) {
  const ScaleOptions o = parseScaleOptions(argc, argv, ScaleOptions{}, "tensorglyph bench scale");
  checkScaleOptions(o);
  checkBackend(o.backend);
  auto ctx = o.requireGpu ? gl::createEglContext({false}) : createContext(o.backend, o.width, o.height);
  TerminalProgress progress(o.quiet);
  runScaleSweep(*ctx, o, progress.sink());
  return 0;
}

}  // namespace tg::app
