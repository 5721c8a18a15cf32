#pragma once
// The scale benchmark behind `tensorglyph bench scale` and the EGL-only
// executable tensorglyph-gpubench: frame time against glyph count for the
// ray-cast ellipsoids and superquadrics on each glyph path asked for (raster,
// compute, cpu) and the tessellated baseline (render/tessellated.h), with
// the GPU memory per glyph and each method's coverage error against the
// exact reference. It needs only the render core, so that the GPU machine,
// which has no VTK or OpenImageIO, can run it.
#include <string>
#include <vector>

#include "gl/context.h"
#include "tensor/glyph.h"
#include "view/camera.h"
#include "util/progress.h"

namespace tg::app {

struct ScaleOptions {
  std::string csv;
  std::string backend = "osmesa";
  bool requireGpu = false;  // refuse a software renderer (a GPU run must not time llvmpipe)
  bool quiet = false;
  std::vector<double> counts{1e4, 1e5, 1e6};
  std::vector<int> resolutions{8, 16, 32, 64};
  int width = 1920, height = 1080, frames = 3;
  double budgetS = 20.0;
  double rowBudgetS = 10.0;   // a row's timed frames stop after about this long
  double totalBudgetS = 0.0;  // rows that would start after this long are skipped (0: none)
  double gamma = 3.0;
  std::vector<std::string> pipelines{"raster", "compute"};
};

// Parses the options after the command name (argv[0] is the command), over
// `defaults`, through the option table as every command (ranges included);
// `command` begins the usage line. Throws UsageError, or HelpShown after
// --help. What needs more than one option: checkScaleOptions.
ScaleOptions parseScaleOptions(int argc, const char** argv, ScaleOptions defaults, const std::string& command);
// Teem's habit: every parameter checked before anything is generated.
void checkScaleOptions(const ScaleOptions& o);

// The sweep's view of `set` at `scale`: every glyph in a w x h frame, seen
// obliquely (the calibration of --pipeline auto frames its fields the same).
render::Camera sweepCamera(const tensor::GlyphSet& set, double scale, int w, int h);

// Runs the sweep on `ctx` (current) and writes the CSV after every row,
// each time whole through a temporary file renamed into place, so that a
// run cut short (a device's time limit) keeps the rows it finished.
// `progress` hears ("sweep", rows done, rows, "rows") before each row.
void runScaleSweep(gl::Context& ctx, const ScaleOptions& o, const util::ProgressSink& progress = {});

}  // namespace tg::app
