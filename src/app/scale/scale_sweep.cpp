#include "app/scale/scale_sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <limits>

#include "app/scale/cli_values.h"
#include "app/scale/option_table.h"
#include "app/scale/frame_size.h"
#include "data-synthetic/generators.h"
#include "gl/shader_library.h"
#include "io/field/atomic_file.h"
#include "ref/image_diff.h"
#include "ref/superquadric_ref.h"
#include "render/raster_glyphs.h"
#include "render/renderer.h"

namespace tg::app {

ScaleOptions parseScaleOptions(int argc, const char** argv, ScaleOptions o, const std::string& command) {
  OptionTable ap(command +
                 " -o CSV [options]\n"
                 "Frame time against glyph count (random tensors on a cubic grid, all in view): ray-cast ellipsoids\n"
                 "and superquadrics, sub-pixel sprites (the per-glyph cost without fragment work), both again without\n"
                 "the occlusion pre-pass, and a tessellated superquadric mesh per glyph as VTK's vtkTensorGlyph draws it.");
  using Args = OptionArgs;
  ap.arg("-o CSV").help("results, one row per method and count").action([&](Args a) { o.csv = a[1]; });
  ap.arg("--n LIST").help("glyph counts, comma-separated, whole numbers")
      .rangeList({1, 2e8}).byDefault(formatList(o.counts)).action([&](Args a) { o.counts = parseList<double>("--n", a[1], parseDouble); });
  ap.arg("--resolutions LIST").help("tessellation resolutions")
      .rangeList({render::TessellatedGlyphs::kMinResolution, render::TessellatedGlyphs::kMaxResolution, true})
      .byDefault(formatList(o.resolutions))
      .action([&](Args a) { o.resolutions = parseList<int>("--resolutions", a[1], [](auto f, auto t) { return parseInt(f, t); }); });
  ap.arg("--size W H").help("image size")
      .range(ranges::kBenchFrameSide).byDefault(formatSize(o.width, o.height)).action([&](Args a) {
        o.width = int(parseInt(a[0], a[1]));
        o.height = int(parseInt(a[0], a[2]));
      });
  ap.arg("--frames N").help("timed frames per row after one warm-up; medians are reported")
      .range(ranges::kFrames).byDefault(std::to_string(o.frames)).action([&](Args a) { o.frames = int(parseInt(a[0], a[1])); });
  ap.arg("--budget S").help("a method whose warm-up frame took over S seconds skips larger counts")
      .range({1e-3, 1e6}).byDefault(formatNumber(o.budgetS)).action([&](Args a) { o.budgetS = parseDouble(a[0], a[1]); });
  ap.arg("--gamma G").help("superquadric sharpness").range(ranges::kGamma).byDefault(formatNumber(o.gamma)).action([&](Args a) {
    o.gamma = parseDouble(a[0], a[1]);
  });
  ap.arg("--backend NAME").help("osmesa, egl, glfw or auto (default " + o.backend + ")").action([&](Args a) {
    o.backend = a[1];
  });
  ap.arg("--require-gpu").help("with egl: fail rather than fall back to Mesa's software renderer").action([&](Args) {
    o.requireGpu = true;
  });
  ap.arg("-q,--quiet").help("no progress line on a terminal's stderr").action([&](Args) { o.quiet = true; });
  parseCommandLine(ap, argc, argv);
  return o;
}

void checkScaleOptions(const ScaleOptions& o) {
  if (o.csv.empty()) throw UsageError("-o CSV is required");
  for (double n : o.counts)
    if (n != double(std::size_t(n))) throw UsageError("--n: each must be a whole number");
  checkFrameSize("--size", o.width, o.height);
  if (o.requireGpu && o.backend != "egl") throw UsageError("--require-gpu needs --backend egl");
  checkOutputPath("-o", o.csv);
}

namespace {

struct Method {
  std::string name;
  render::GlyphKind glyph;
  int tessellation = 0;
  double scaleFactor = 1.0;  // of the sweep's glyph scale
  bool prepass = true;       // the occlusion pre-pass where the renderer's profile runs it
  double coveragePct = std::numeric_limits<double>::quiet_NaN();
  bool skipped = false;  // a smaller count exceeded the budget
};

struct FrameTime {
  double wallMs = 0, gpuMs = 0, warmMs = 0;
};

// Medians of `frames` frames after one warm-up, each finished: wall time as
// the caller sees it, and GPU time between two timestamps around the frame.
FrameTime timeFrames(const gl::Api& gl, render::GlyphRenderer& r, const render::Camera& cam,
                     const render::FrameParams& p, const render::GBuffer& t, int frames) {
  GLuint q[2];
  gl.CreateQueries(GL_TIMESTAMP, 2, q);
  auto once = [&](double& gpuMs) {
    const auto t0 = Clock::now();
    gl.QueryCounter(q[0], GL_TIMESTAMP);
    r.render(cam, p, t);
    gl.QueryCounter(q[1], GL_TIMESTAMP);
    gl.Finish();
    const double wall = msSince(t0);
    GLuint64 ns[2] = {0, 0};
    gl.GetQueryObjectui64v(q[0], GL_QUERY_RESULT, &ns[0]);
    gl.GetQueryObjectui64v(q[1], GL_QUERY_RESULT, &ns[1]);
    // On multi-second frames (an H200 at 10^8 glyphs) the second stamp came
    // back below the first: the unsigned span wrapped to 1.8e12 ms. Such a
    // frame has no GPU time.
    gpuMs = ns[1] >= ns[0] ? double(ns[1] - ns[0]) * 1e-6 : std::nan("");
    return wall;
  };
  FrameTime ft;
  double gpu = 0;
  ft.warmMs = once(gpu);
  std::vector<double> wall, gpuV;
  for (int k = 0; k < frames; ++k) {
    wall.push_back(once(gpu));
    gpuV.push_back(gpu);
  }
  gl.DeleteQueries(2, q);
  std::sort(wall.begin(), wall.end());
  ft.wallMs = wall[wall.size() / 2];
  // One frame without a GPU time makes the column's median meaningless: none.
  if (std::any_of(gpuV.begin(), gpuV.end(), [](double g) { return std::isnan(g); })) {
    ft.gpuMs = std::nan("");
  } else {
    std::sort(gpuV.begin(), gpuV.end());
    ft.gpuMs = gpuV[gpuV.size() / 2];
  }
  return ft;
}

}  // namespace

render::Camera sweepCamera(const tensor::GlyphSet& set, double scale, int w, int h) {
  const auto [lo, hi] = tensor::glyphBoxWC(set, scale);
  render::CameraDesc d = render::frameBox(lo, hi, render::Projection::Perspective, 30.0, double(w) / h);
  d.eyeWC = d.lookAtWC + glm::length(d.eyeWC - d.lookAtWC) * glm::normalize(glm::dvec3(0.5, -0.7, 1.0));
  d.upWC = {0, 1, 0};
  return render::makeCamera(d, w, h, lo, hi);
}

namespace {

render::FrameParams paramsFor(const Method& m, double scale, double gamma) {
  render::FrameParams p;
  p.scale = scale * m.scaleFactor;
  p.glyph = m.glyph;
  p.gamma = gamma;
  p.tessellation = m.tessellation;
  p.occlusionPrepass = m.prepass;
  return p;
}

// Coverage error against the double-precision reference on a small scene
// where glyphs span many pixels, so that it measures the shape, not aliasing.
double coverageErrorPct(const gl::Api& gl, const gl::ShaderLibrary& lib, const Method& m, double gamma) {
  const auto f = synth::randomField(64, 3);
  const auto set = tensor::buildGlyphs(f.positions, f.tensors, f.ids);
  const double scale = 0.6;
  const render::Camera cam = sweepCamera(set, scale, 480, 360);
  render::GlyphRenderer r(gl, lib);
  render::GBuffer t(gl, cam.width, cam.height);
  r.upload(set);
  r.render(cam, paramsFor(m, scale, gamma), t);
  const ref::RefImage reference = m.glyph == render::GlyphKind::Ellipsoid
                                      ? ref::renderEllipsoids(cam, set.glyphs, {scale, 0.0})
                                      : ref::renderSuperquadrics(cam, set.glyphs, {scale, 0.0}, gamma);
  const ref::ImageDiff d = ref::diffImages(r.readback(cam, t), reference, cam);
  return 100.0 * double(d.coverageMismatch) / double(std::max<std::size_t>(d.refCovered, 1));
}

double coveredPct(const render::FrameImage& img) {
  const auto covered = std::count_if(img.id.begin(), img.id.end(), [](std::uint32_t id) { return id != 0xFFFFFFFFu; });
  return 100.0 * double(covered) / double(std::max<std::size_t>(img.id.size(), 1));
}

// "" where a column does not apply, so that a CSV reader sees a missing value.
std::string field(double v, const char* fmt) {
  if (std::isnan(v)) return "";
  char b[64];
  std::snprintf(b, sizeof b, fmt, v);
  return b;
}

}  // namespace

void runScaleSweep(gl::Context& ctx, const ScaleOptions& o, const util::ProgressSink& progress) {
  const gl::Api& gl = ctx.api();
  const gl::ShaderLibrary lib;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Method> methods{{"raycast-ellipsoid", render::GlyphKind::Ellipsoid},
                              {"raycast-superquadric", render::GlyphKind::Superquadric},
                              // 1/64 of the size: under a pixel, so almost no fragment runs.
                              {"sprites-subpixel", render::GlyphKind::Superquadric, 0, 1.0 / 64.0},
                              // The same two without the occlusion pre-pass: whether it pays is
                              // measured per renderer (render::RendererProfile), GPUs included.
                              {"raycast-superquadric-no-prepass", render::GlyphKind::Superquadric, 0, 1.0, false},
                              {"sprites-subpixel-no-prepass", render::GlyphKind::Superquadric, 0, 1.0 / 64.0, false}};
  for (int r : o.resolutions)
    methods.push_back({"tessellated-" + std::to_string(r), render::GlyphKind::Superquadric, r});
  for (Method& m : methods)
    if (m.scaleFactor == 1.0) m.coveragePct = coverageErrorPct(gl, lib, m, o.gamma);

  io::AtomicFile out(o.csv);  // created now: an unwritable directory fails before the sweep
  std::ostringstream f;
  f << "method,resolution,n,width,height,frame_ms,gpu_ms,empty_frame_ms,covered_pct,newton_mean,"
       "gpu_bytes_per_glyph,vtk_mesh_bytes_per_glyph,coverage_error_pct,prepass,device\n";
  std::fprintf(stderr, "scale sweep: %s (%s), %dx%d\n", ctx.backendName(), ctx.describe().c_str(), o.width, o.height);
  const double rows = double(o.counts.size() * methods.size());
  double rowsDone = 0;
  for (double nd : o.counts) {
    const auto n = std::size_t(nd);
    if (progress) progress("sweep", rowsDone, rows, "rows");
    const auto t0 = Clock::now();
    tensor::GlyphSet set;
    {
      const auto randomTensors = synth::randomField(n, 1);
      set = tensor::buildGlyphs(randomTensors.positions, randomTensors.tensors, randomTensors.ids);
    }
    const double scale = 0.5;  // the largest eigenvalue 1 gives a diameter of one grid spacing
    const render::Camera cam = sweepCamera(set, scale, o.width, o.height);
    render::GlyphRenderer r(gl, lib);
    render::GBuffer target(gl, o.width, o.height);
    r.upload(set);
    set.glyphs = {};
    if (progress) progress({}, 0, 0, {});  // the row lines below, not after the progress line
    std::fprintf(stderr, "  n %zu: generated, decomposed and uploaded in %.0f ms\n", n, msSince(t0));
    // The frame's fixed part: clears and the deferred lighting pass, with
    // every glyph hidden by the threshold (compacted away in the warm-up).
    render::FrameParams empty;
    empty.scale = scale;
    empty.faMin = 10.0;
    const FrameTime emptyT = timeFrames(gl, r, cam, empty, target, o.frames);
    for (Method& m : methods) {
      if (progress) progress("sweep", rowsDone, rows, "rows");
      ++rowsDone;
      if (m.skipped) continue;
      const render::FrameParams p = paramsFor(m, scale, o.gamma);
      // A tessellated frame of a million glyphs or more is long; one timed frame says enough.
      const int frames = m.tessellation > 0 && n >= 1000000 ? 1 : o.frames;
      const std::uint64_t prepassesBefore = render::asRaster(r.glyphPath()).occlusionPrepasses();
      const FrameTime ft = timeFrames(gl, r, cam, p, target, frames);
      const bool prepassRan = render::asRaster(r.glyphPath()).occlusionPrepasses() > prepassesBefore;
      m.skipped = ft.warmMs > 1000.0 * o.budgetS;
      const double covered = coveredPct(r.readback(cam, target));
      double newton = nan;
      if (m.glyph == render::GlyphKind::Superquadric && m.tessellation == 0) {
        render::FrameParams s = p;
        s.iterationStats = true;
        r.render(cam, s, target);
        newton = r.iterationStats().mean;
      }
      const double bytes = double(r.gpuBytes()) / double(n);
      const double vtk = m.tessellation > 0 ? double(render::TessellatedGlyphs::perGlyphMeshBytes(m.tessellation)) : nan;
      f << m.name << ',' << m.tessellation << ',' << n << ',' << o.width << ',' << o.height << ','
        << field(ft.wallMs, "%.3f") << ',' << field(ft.gpuMs, "%.3f") << ',' << field(emptyT.wallMs, "%.3f") << ','
        << field(covered, "%.2f") << ',' << field(newton, "%.3f") << ',' << field(bytes, "%.2f") << ','
        << field(vtk, "%.0f") << ',' << field(m.coveragePct, "%.4f") << ',' << (prepassRan ? 1 : 0) << ",\""
        << ctx.describe() << "\"\n";
      if (progress) progress({}, 0, 0, {});
      std::fprintf(stderr, "  %-31s n %-10zu %10.2f ms (GPU %.2f, empty %.2f), %.1f%% covered, %.1f B/glyph%s%s\n",
                   m.name.c_str(), n, ft.wallMs, ft.gpuMs, emptyT.wallMs, covered, bytes, prepassRan ? ", pre-pass" : "",
                   m.skipped ? "; larger counts skipped" : "");
    }
  }
  const std::string text = f.str();
  out.write(text.data(), text.size());
  out.commit(std::int64_t(text.size()));
}

}  // namespace tg::app
