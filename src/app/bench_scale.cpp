// tensorglyph bench scale: frame time against glyph count at a fixed image
// size, for the ray-cast ellipsoids and superquadrics and the tessellated
// baseline (render/tessellated.h) at several resolutions, with the GPU memory
// per glyph and each method's coverage error against the exact reference.
#include <OpenImageIO/argparse.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "app/bench.h"
#include "app/cli_common.h"
#include "data-synthetic/generators.h"
#include "gl/shader_library.h"
#include "io/atomic_file.h"
#include "ref/image_diff.h"
#include "ref/superquadric_ref.h"
#include "render/renderer.h"

namespace tg::app {
namespace {

struct Options {
  std::string csv, backend = "osmesa";
  std::vector<double> counts{1e4, 1e5, 1e6};
  std::vector<int> resolutions{8, 16, 32, 64};
  int width = 1920, height = 1080, frames = 3;
  double budgetS = 20.0;
  double gamma = 3.0;
};

Options parse(int argc, const char** argv) {
  Options o;
  OIIO::ArgParse ap;
  ap.intro("tensorglyph bench scale -o CSV [options]\n"
           "Frame time against glyph count (random tensors on a cubic grid, all in view), ray-cast\n"
           "ellipsoids and superquadrics against a tessellated superquadric mesh per glyph.")
      .exit_on_error(false);
  using Args = OIIO::cspan<const char*>;
  ap.arg("-o CSV").help("results, one row per method and count").action([&](auto&, Args a) { o.csv = a[1]; });
  ap.arg("--n LIST").help("glyph counts, comma-separated (default 1e4,1e5,1e6)").action([&](auto&, Args a) {
    o.counts = parseList<double>("--n", a[1], parseDouble);
  });
  ap.arg("--resolutions LIST").help("tessellation resolutions (default 8,16,32,64)").action([&](auto&, Args a) {
    o.resolutions = parseList<int>("--resolutions", a[1], parseInt);
  });
  ap.arg("--size W H").help("image size (default 1920 1080)").action([&](auto&, Args a) {
    o.width = int(parseInt("--size", a[1]));
    o.height = int(parseInt("--size", a[2]));
  });
  ap.arg("--frames N").help("timed frames per row; the median is reported (default 3)").action([&](auto&, Args a) {
    o.frames = int(parseInt("--frames", a[1]));
  });
  ap.arg("--budget S").help("a method whose frame took longer than S seconds skips larger counts (default 20)")
      .action([&](auto&, Args a) { o.budgetS = parseDouble("--budget", a[1]); });
  ap.arg("--backend NAME").help("osmesa (default), egl, glfw or auto").action([&](auto&, Args a) { o.backend = a[1]; });
  if (ap.parse_args(argc, argv) < 0) throw UsageError(ap.geterror());
  return o;
}

void validate(const Options& o) {
  if (o.csv.empty()) throw UsageError("-o CSV is required");
  for (double n : o.counts)
    if (!(n >= 1 && n <= 2e8 && n == double(std::size_t(n)))) throw UsageError("--n: each must be a whole number within 1..2e8");
  for (int r : o.resolutions)
    if (r < render::TessellatedGlyphs::kMinResolution || r > render::TessellatedGlyphs::kMaxResolution)
      throw UsageError("--resolutions: each must be within 4..64");
  if (o.width < 16 || o.height < 16 || o.width > 8192 || o.height > 8192) throw UsageError("--size must be within 16..8192");
  if (o.frames < 1 || o.frames > 1000) throw UsageError("--frames must be within 1..1000");
  if (!(o.budgetS > 0.0)) throw UsageError("--budget must be positive");
  checkBackend(o.backend);
}

struct Method {
  std::string name;
  render::GlyphKind glyph;
  int tessellation;
  double coveragePct = 0;
  bool skipped = false;  // a smaller count exceeded the budget
};

// Median wall time of `frames` frames after one warm-up, each finished.
double frameMs(const gl::Api& gl, render::GlyphRenderer& r, const render::Camera& cam, const render::FrameParams& p,
               const render::GBuffer& t, int frames, double* warmMs = nullptr) {
  auto once = [&] {
    const auto t0 = Clock::now();
    r.render(cam, p, t);
    gl.Finish();
    return msSince(t0);
  };
  const double warm = once();
  if (warmMs) *warmMs = warm;
  std::vector<double> v;
  for (int k = 0; k < frames; ++k) v.push_back(once());
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

render::Camera framing(const tensor::GlyphSet& set, double scale, int w, int h) {
  const auto [lo, hi] = tensor::glyphBoxWC(set, scale);
  render::CameraDesc d = render::frameBox(lo, hi, render::Projection::Perspective, 30.0, double(w) / h);
  d.eyeWC = d.lookAtWC + glm::length(d.eyeWC - d.lookAtWC) * glm::normalize(glm::dvec3(0.5, -0.7, 1.0));
  d.upWC = {0, 1, 0};
  return render::makeCamera(d, w, h, lo, hi);
}

// Coverage error against the double-precision reference on a small scene
// where glyphs span many pixels, so that it measures the shape, not aliasing.
double coverageErrorPct(const gl::Api& gl, const gl::ShaderLibrary& lib, const Method& m, double gamma) {
  const auto f = synth::randomField(64, 3);
  const auto set = tensor::buildGlyphs(f.positions, f.tensors, f.ids);
  const double scale = 0.6;
  const render::Camera cam = framing(set, scale, 480, 360);
  render::GlyphRenderer r(gl, lib);
  render::GBuffer t(gl, cam.width, cam.height);
  r.upload(set);
  render::FrameParams p;
  p.scale = scale;
  p.glyph = m.glyph;
  p.gamma = gamma;
  p.tessellation = m.tessellation;
  r.render(cam, p, t);
  const ref::RefImage reference = m.glyph == render::GlyphKind::Ellipsoid
                                      ? ref::renderEllipsoids(cam, set.glyphs, {scale, 0.0})
                                      : ref::renderSuperquadrics(cam, set.glyphs, {scale, 0.0}, gamma);
  const ref::ImageDiff d = ref::diffImages(r.readback(cam, t), reference, cam);
  return 100.0 * double(d.coverageMismatch) / double(std::max<std::size_t>(d.refCovered, 1));
}

}  // namespace

int benchScale(int argc, const char** argv) {
  const Options o = parse(argc, argv);
  validate(o);
  auto ctx = createContext(o.backend, o.width, o.height);
  const gl::Api& gl = ctx->api();
  const gl::ShaderLibrary lib;
  std::vector<Method> methods{{"raycast-ellipsoid", render::GlyphKind::Ellipsoid, 0},
                              {"raycast-superquadric", render::GlyphKind::Superquadric, 0}};
  for (int r : o.resolutions)
    methods.push_back({"tessellated-" + std::to_string(r), render::GlyphKind::Superquadric, r});
  for (Method& m : methods) m.coveragePct = coverageErrorPct(gl, lib, m, o.gamma);

  io::AtomicOutput out(o.csv);
  std::ofstream f(out.tempPath());
  f << "method,resolution,n,width,height,frame_ms,empty_frame_ms,gpu_bytes_per_glyph,vtk_mesh_bytes_per_glyph,"
       "coverage_error_pct,device\n";
  std::fprintf(stderr, "tensorglyph bench scale: %s (%s), %dx%d\n", ctx->backendName(), ctx->describe().c_str(),
               o.width, o.height);
  for (double nd : o.counts) {
    const auto n = std::size_t(nd);
    tensor::GlyphSet set;
    {
      const auto field = synth::randomField(n, 1);
      set = tensor::buildGlyphs(field.positions, field.tensors, field.ids);
    }
    const double scale = 0.5;  // the largest eigenvalue 1 gives a diameter of one grid spacing
    const render::Camera cam = framing(set, scale, o.width, o.height);
    render::GlyphRenderer r(gl, lib);
    render::GBuffer target(gl, o.width, o.height);
    r.upload(set);
    set.glyphs = {};
    // The frame's fixed part: clears and the deferred lighting pass, with
    // every glyph hidden by the threshold (compacted away after the warm-up).
    render::FrameParams empty;
    empty.scale = scale;
    empty.faMin = 10.0;
    const double emptyMs = frameMs(gl, r, cam, empty, target, o.frames);
    for (Method& m : methods) {
      if (m.skipped) continue;
      render::FrameParams p;
      p.scale = scale;
      p.glyph = m.glyph;
      p.gamma = o.gamma;
      p.tessellation = m.tessellation;
      double warm = 0;
      const double ms = frameMs(gl, r, cam, p, target, m.tessellation > 0 && n >= 1000000 ? 1 : o.frames, &warm);
      m.skipped = warm > 1000.0 * o.budgetS;
      const double bytes = double(r.gpuBytes()) / double(n);
      const double vtk = m.tessellation > 0 ? double(render::TessellatedGlyphs::perGlyphMeshBytes(m.tessellation)) : 0.0;
      char line[512];
      std::snprintf(line, sizeof line, "%s,%d,%zu,%d,%d,%.3f,%.3f,%.2f,%.0f,%.4f,\"%s\"\n", m.name.c_str(),
                    m.tessellation, n, o.width, o.height, ms, emptyMs, bytes, vtk, m.coveragePct,
                    ctx->describe().c_str());
      f << line;
      std::fprintf(stderr, "  %-22s n %-10zu %10.2f ms (empty frame %.2f ms), %.1f B/glyph, coverage error %.3f%%%s\n",
                   m.name.c_str(), n, ms, emptyMs, bytes, m.coveragePct, m.skipped ? "; larger counts skipped" : "");
    }
  }
  f.close();
  if (!f) throw std::runtime_error("bench scale: " + o.csv + ": write failed");
  out.commit();
  return 0;
}

}  // namespace tg::app
