
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "app/scale/option_table.h"
#include "app/cli_common.h"
#include "app/commands.h"
#include "app/field_flags.h"
#include "app/progress.h"
#include "app/scene.h"
#include "io/core/readers.h"
#include "render/glyph_kind.h"
#include "tensor/glyph.h"
#include "tensor/glyph_scale.h"

namespace tg::app {

int cmdInfo(int argc, const char** argv) {
  std::string input;
  FieldFlags flags;
  bool quiet = false;
  OptionTable ap("tensorglyph info INPUT [selection flags]");
  addInputArg(ap, input);
  flags.addTo(ap, true);  // the size flags change what info reports as the default render's size
  ap.arg("-q,--quiet").help("no progress line on a terminal's stderr").action([&](OptionArgs) { quiet = true; });
  parseCommandLine(ap, argc, argv);
  if (input.empty()) throw UsageError("INPUT is required");
  flags.validate();

  checkOptionsApply(input, flags.read);
  TerminalProgress progress(quiet);
  flags.read.progress = progress.sink();
  Scene scene;
  scene.field = [&] {
    try {
      return io::readTensorField(input, flags.read);
    } catch (const io::SliceOutOfRange& e) {
      throw sliceUsageError(e, *flags.read.selection.slice, input);
    }
  }();
  const io::TensorField& f = scene.field;
  checkLoaded(f, flags.read);
  if (flags.read.progress) flags.read.progress({}, 0, 0, {});
  const FrameCheck frameCheck = reportLoad(f, "info", flags.read);
  const tensor::GlyphSet g = tensor::buildGlyphs(f.positions, f.tensors, f.ids, 0, flags.glyph, flags.read.progress);
  attachWholeField(scene, flags, input, flags.read);
  const tensor::FieldStats stats = sizingStats(scene, g);
  decideStressDefaults(scene, stats);
  progress.finish();
  std::size_t negDef = 0, indefinite = 0, zero = 0;
  constexpr double inf = std::numeric_limits<double>::infinity();
  double lmin[3] = {inf, inf, inf}, lmax[3] = {-inf, -inf, -inf}, faMin = inf, faMax = -inf;
  for (const auto& r : g.glyphs) {
    const float* l = r.eigenvalues;
    if (l[0] == 0 && l[2] == 0) ++zero;
    else if (l[0] < 0) ++negDef;
    else if (l[2] < 0) ++indefinite;
    for (int k = 0; k < 3; ++k) {
      lmin[k] = std::min(lmin[k], double(l[k]));
      lmax[k] = std::max(lmax[k], double(l[k]));
    }
    faMin = std::min(faMin, double(r.fa));
    faMax = std::max(faMax, double(r.fa));
  }
  std::printf("file: %s\n", printable(f.path).c_str());
  std::printf("dataset: %s\n", f.description.c_str());
  if (!f.arrayName.empty()) std::printf("tensor array: %s\n", f.arrayName.c_str());
  if (!f.layout.empty()) std::printf("components: %s\n", f.layout.c_str());
  std::printf("space: %s\n", f.space.empty() ? "(none given)" : f.space.c_str());
  std::printf("length units: %s\n", f.lengthUnits.empty() ? "(none given)" : printable(f.lengthUnits).c_str());
  std::printf("tensor frame: %s\n", f.frame.empty() ? "(not stated)" : f.frame.c_str());
  if (f.measurementFrame) {
    const auto& m = *f.measurementFrame;
    std::printf("measurement frame (columns): (%g,%g,%g) (%g,%g,%g) (%g,%g,%g)\n", m[0], m[3], m[6], m[1], m[4], m[7],
                m[2], m[5], m[8]);
  }
  // The whole map applied, mirror included: a reflection shows as det -1.
  if (f.tensorToWC) {
    const auto& t = *f.tensorToWC;
    const double det = t[0] * (t[4] * t[8] - t[5] * t[7]) - t[1] * (t[3] * t[8] - t[5] * t[6]) +
                       t[2] * (t[3] * t[7] - t[4] * t[6]);
    std::printf("tensors to world, D = T D Tᵀ, T (rows): [%.6g %.6g %.6g] [%.6g %.6g %.6g] [%.6g %.6g %.6g]%s\n", t[0],
                t[1], t[2], t[3], t[4], t[5], t[6], t[7], t[8], det < 0 ? " (a reflection)" : "");
  } else {
    std::printf("tensors to world: identity (stored in world axes)\n");
  }
  if (f.grid) {
    const io::GridInfo& gr = *f.grid;
    std::printf("grid: %d x %d x %d, spacing %g %g %g, origin %g %g %g\n", gr.dims[0], gr.dims[1], gr.dims[2],
                gr.spacing[0], gr.spacing[1], gr.spacing[2], gr.origin[0], gr.origin[1], gr.origin[2]);
    std::printf("directions (columns): [%g %g %g] [%g %g %g] [%g %g %g]\n", gr.directions[0], gr.directions[3],
                gr.directions[6], gr.directions[1], gr.directions[4], gr.directions[7], gr.directions[2],
                gr.directions[5], gr.directions[8]);
  }
  std::printf("sample spacing: %g\n", f.sampleSpacing);
  std::printf("tensors: %zu total, %zu masked, %zu outside the selection, %zu skipped (NaN/Inf), %zu skipped "
              "(overflow), %zu below cl/cp, %zu drawn\n",
              f.totalPoints, f.masked, f.unselected, f.skippedNonFinite, f.skippedOverflow, g.droppedByShape,
              g.glyphs.size());
  std::printf("  positive semi-definite: %zu, indefinite: %zu, negative definite: %zu, zero: %zu\n",
              g.glyphs.size() - negDef - indefinite - zero, indefinite, negDef, zero);
  if (!g.glyphs.empty()) {
    for (int k = 0; k < 3; ++k) std::printf("eigenvalue %d: [%g, %g]\n", k + 1, lmin[k], lmax[k]);
    if (scene.stress) {
      // Of the field the sizes come from (the whole one unless --sizes-from selection).
      const char* from = scene.wholeField ? " (whole field)" : "";
      for (int k = 0; k < 3; ++k)
        std::printf("principal stress %d%s: [%g, %g]\n", k + 1, from, stats.principalMin[k], stats.principalMax[k]);
      std::printf("von Mises%s: [%g, %g]\n", from, stats.vonMisesMin, stats.vonMisesMax);
      std::printf("%s\n", stressDefaultsLine(*scene.stress).c_str());
    } else {
      std::printf("FA: [%g, %g]\nMD: [%g, %g]\n", faMin, faMax, g.mdMin, g.mdMax);
    }
    std::printf("bounds: [%g %g %g] - [%g %g %g]\n", g.boundsMinWC.x, g.boundsMinWC.y, g.boundsMinWC.z,
                g.boundsMaxWC.x, g.boundsMaxWC.y, g.boundsMaxWC.z);
    // What `render` with the same flags would choose, and why.
    const tensor::ResolvedScale sized =
        tensor::resolveScale(sizingParams(flags, scene), sizingSample(scene, stats));
    const tensor::FramingBox frame = tensor::framingBox(g, !f.grid, sized.typicalRadiusWC);
    std::printf("size: %s\nframing: %s\n", sized.why.c_str(), frame.why.c_str());
  }
  std::printf("%s", frameCheckReport(frameCheck).c_str());
  // Every kind of the table reads the eigen-decomposed record these tensors made.
  std::printf("glyph kinds: %s\n", render::glyphKindNames().c_str());
  // Load and eigen-decomposition both done, both buffers alive: the
  // streaming loader's peak (see docs/design.md, "Memory").
  std::printf("peak memory: %.1f MiB\n", double(peakRssBytes()) / (1024.0 * 1024.0));
  return 0;
}

}  // namespace tg::app
