#include "app/scale/scale_sweep.h"

#include <algorithm>
#include <array>
#include <functional>
#include <map>
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
#include "render/glyph_path.h"
#include "render/raster_glyphs.h"
#include "render/renderer.h"

namespace tg::app {

ScaleOptions parseScaleOptions(int argc, const char** argv, ScaleOptions o, const std::string& command) {
  OptionTable ap(command +
                 " -o CSV [options]\n"
                 "Frame time against glyph count (random tensors on a cubic grid, all in view; the camera turns by\n"
                 "a tenth of a degree before each frame, so that no frame reuses the last): per glyph path, ray-cast\n"
                 "ellipsoids and superquadrics and sub-pixel sprites (the per-glyph cost without fragment work); on\n"
                 "the raster path also both again without the occlusion pre-pass, and a tessellated superquadric\n"
                 "mesh per glyph as VTK's vtkTensorGlyph draws it.");
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
  ap.arg("--row-budget S").help("a row's timed frames stop once they have taken S seconds (at least one runs)")
      .range({1e-3, 1e6}).byDefault(formatNumber(o.rowBudgetS)).action([&](Args a) { o.rowBudgetS = parseDouble(a[0], a[1]); });
  ap.arg("--total-budget S").help("rows that would start after S seconds of the sweep are skipped; 0: none")
      .range({0, 1e6}).byDefault(formatNumber(o.totalBudgetS)).action([&](Args a) { o.totalBudgetS = parseDouble(a[0], a[1]); });
  ap.arg("--pipelines LIST").help("glyph paths to sweep, comma-separated: " + render::glyphPathNames())
      .byDefault([&] {
        std::string j;
        for (const std::string& name : o.pipelines) j += (j.empty() ? "" : ",") + name;
        return j;
      }()).action([&](Args a) {
        o.pipelines = parseList<std::string>("--pipelines", a[1], [](std::string_view, std::string_view t) { return std::string(t); });
      });
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
  for (std::size_t k = 0; k < o.counts.size(); ++k) {
    if (o.counts[k] != double(std::size_t(o.counts[k]))) throw UsageError("--n: each must be a whole number");
    if (std::find(o.counts.begin(), o.counts.begin() + std::ptrdiff_t(k), o.counts[k]) != o.counts.begin() + std::ptrdiff_t(k))
      throw UsageError("--n: " + formatNumber(o.counts[k]) + " is named twice");
  }
  checkFrameSize("--size", o.width, o.height);
  if (o.requireGpu && o.backend != "egl") throw UsageError("--require-gpu needs --backend egl");
  for (std::size_t k = 0; k < o.pipelines.size(); ++k) {
    const std::string& name = o.pipelines[k];
    if (name.empty()) throw UsageError("--pipelines: an empty name (a stray comma?); choose " + render::glyphPathNames());
    if (std::find(std::begin(render::kGlyphPathNames), std::end(render::kGlyphPathNames), name) ==
        std::end(render::kGlyphPathNames))
      throw UsageError("--pipelines: \"" + name + "\"; choose " + render::glyphPathNames());
    if (std::find(o.pipelines.begin(), o.pipelines.begin() + std::ptrdiff_t(k), name) != o.pipelines.begin() + std::ptrdiff_t(k))
      throw UsageError("--pipelines: \"" + name + "\" is named twice");
  }
  checkOutputPath("-o", o.csv);
}

namespace {

struct Method {
  std::string pipeline;
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
  int frames = 0;  // timed, after the warm-up
};

// Medians of at most `frames` frames after one warm-up, each finished, the
// camera turned by a tenth of a degree about the view's centre before each
// (cams alternates two such views), stopping once they have taken
// `budgetMs`: wall time as the caller sees it, and GPU time between two
// timestamps around the frame.
FrameTime timeFrames(const gl::Api& gl, render::GlyphRenderer& r, const std::array<render::Camera, 2>& cams,
                     const render::FrameParams& p, const render::GBuffer& t, int frames, double budgetMs,
                     const std::function<void()>& afterWarmUp = {}) {
  GLuint q[2];
  gl.CreateQueries(GL_TIMESTAMP, 2, q);
  int shown = 0;
  auto once = [&](double& gpuMs) {
    const auto t0 = Clock::now();
    gl.QueryCounter(q[0], GL_TIMESTAMP);
    r.render(cams[std::size_t(shown++ % 2)], p, t);
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
  if (afterWarmUp) afterWarmUp();  // cams[0]'s frame, whatever the timed frames' count
  std::vector<double> wall, gpuV;
  double spent = 0;
  for (int k = 0; k < frames && (k == 0 || spent < budgetMs); ++k) {
    wall.push_back(once(gpu));
    gpuV.push_back(gpu);
    spent += wall.back();
  }
  ft.frames = int(wall.size());
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

// cam turned about its look-at point by `degrees` around the up axis.
render::Camera turned(const render::Camera& cam, double degrees, const glm::dvec3& loWC, const glm::dvec3& hiWC) {
  render::CameraDesc d = cam.desc;
  const double a = degrees * (3.14159265358979323846 / 180.0);
  const glm::dvec3 v = d.eyeWC - d.lookAtWC, k = glm::normalize(d.upWC);
  // Rodrigues' rotation of v about k.
  d.eyeWC = d.lookAtWC + v * std::cos(a) + glm::cross(k, v) * std::sin(a) + k * glm::dot(k, v) * (1 - std::cos(a));
  return render::makeCamera(d, cam.width, cam.height, loWC, hiWC);
}

}  // namespace

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
  render::GlyphRenderer r(gl, lib, {}, m.pipeline);
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

// The sweep's methods, per path in `pipelines`' order.
std::vector<Method> sweepMethods(const ScaleOptions& o) {
  std::vector<Method> methods;
  for (const std::string& path : o.pipelines) {
    if (path != "raster") {
      methods.push_back({path, path + "-ellipsoid", render::GlyphKind::Ellipsoid});
      methods.push_back({path, path + "-superquadric", render::GlyphKind::Superquadric});
      methods.push_back({path, path + "-sprites-subpixel", render::GlyphKind::Superquadric, 0, 1.0 / 64.0});
      continue;
    }
    methods.push_back({path, "raycast-ellipsoid", render::GlyphKind::Ellipsoid});
    methods.push_back({path, "raycast-superquadric", render::GlyphKind::Superquadric});
    // 1/64 of the size: under a pixel, so almost no fragment runs.
    methods.push_back({path, "sprites-subpixel", render::GlyphKind::Superquadric, 0, 1.0 / 64.0});
    // The same two without the occlusion pre-pass: whether it pays is
    // measured per renderer (render::RendererProfile), GPUs included.
    methods.push_back({path, "raycast-superquadric-no-prepass", render::GlyphKind::Superquadric, 0, 1.0, false});
    methods.push_back({path, "sprites-subpixel-no-prepass", render::GlyphKind::Superquadric, 0, 1.0 / 64.0, false});
    for (int r : o.resolutions)
      methods.push_back({path, "tessellated-" + std::to_string(r), render::GlyphKind::Superquadric, r});
  }
  return methods;
}

// What a method draws, whatever the path ("ellipsoid", "sprites-subpixel"):
// the rows of one count and family are timed against each other.
std::string family(const Method& m) {
  if (m.pipeline != "raster") return m.name.substr(m.pipeline.size() + 1);
  return m.name.rfind("raycast-", 0) == 0 ? m.name.substr(8) : m.name;
}

}  // namespace

void runScaleSweep(gl::Context& ctx, const ScaleOptions& o, const util::ProgressSink& progress) {
  const gl::Api& gl = ctx.api();
  const gl::ShaderLibrary lib;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto sweepStart = Clock::now();
  std::vector<Method> methods = sweepMethods(o);
  for (Method& m : methods)
    if (m.scaleFactor == 1.0) m.coveragePct = coverageErrorPct(gl, lib, m, o.gamma);

  // The whole CSV after every row, each time through a temporary file.
  std::string text =
      "pipeline,method,resolution,n,width,height,frames,frame_ms,gpu_ms,empty_frame_ms,covered_pct,newton_mean,"
      "gpu_bytes_per_glyph,vtk_mesh_bytes_per_glyph,coverage_error_pct,prepass,device\n";
  auto save = [&] {
    io::AtomicFile out(o.csv);
    out.write(text.data(), text.size());
    out.commit(std::int64_t(text.size()));
  };
  save();  // an unwritable directory fails before the sweep
  std::fprintf(stderr, "scale sweep: %s (%s), %dx%d\n", ctx.backendName(), ctx.describe().c_str(), o.width, o.height);
  const double rows = double(o.counts.size() * methods.size());
  double rowsDone = 0;
  bool outOfTime = false;
  auto overBudget = [&] {
    if (!outOfTime && o.totalBudgetS > 0 && msSince(sweepStart) > 1000.0 * o.totalBudgetS) {
      outOfTime = true;
      if (progress) progress({}, 0, 0, {});
      std::fprintf(stderr, "  the sweep's %g s are spent: the remaining rows are skipped\n", o.totalBudgetS);
    }
    return outOfTime;
  };
  std::map<std::string, std::map<std::string, double>> frameMs;  // this count's frame times by path and family
  for (double nd : o.counts) {
    const auto n = std::size_t(nd);
    if (overBudget()) break;
    if (progress) progress("sweep", rowsDone, rows, "rows");
    const auto t0 = Clock::now();
    tensor::GlyphSet set;
    {
      const auto randomTensors = synth::randomField(n, 1);
      set = tensor::buildGlyphs(randomTensors.positions, randomTensors.tensors, randomTensors.ids);
    }
    const double scale = 0.5;  // the largest eigenvalue 1 gives a diameter of one grid spacing
    const auto [loWC, hiWC] = tensor::glyphBoxWC(set, scale);
    const render::Camera cam = sweepCamera(set, scale, o.width, o.height);
    const std::array<render::Camera, 2> cams{turned(cam, 0.1, loWC, hiWC), turned(cam, -0.1, loWC, hiWC)};
    if (progress) progress({}, 0, 0, {});  // the row lines below, not after the progress line
    std::fprintf(stderr, "  n %zu: generated and decomposed in %.0f ms\n", n, msSince(t0));
    frameMs.clear();
    for (std::size_t pk = 0; pk < o.pipelines.size(); ++pk) {
      const std::string& path = o.pipelines[pk];
      const bool any = std::any_of(methods.begin(), methods.end(), [&](const Method& m) { return m.pipeline == path && !m.skipped; });
      if (!any || overBudget()) {
        for (const Method& m : methods) rowsDone += m.pipeline == path ? 1 : 0;
        continue;
      }
      const auto u0 = Clock::now();
      render::GlyphRenderer r(gl, lib, {}, path);
      render::GBuffer target(gl, o.width, o.height);
      r.upload(set);
      gl.Finish();
      const bool last = std::none_of(o.pipelines.begin() + std::ptrdiff_t(pk) + 1, o.pipelines.end(), [&](const std::string& q) {
        return std::any_of(methods.begin(), methods.end(), [&](const Method& m) { return m.pipeline == q && !m.skipped; });
      });
      if (last) set.glyphs = {};
      if (progress) progress({}, 0, 0, {});
      std::fprintf(stderr, "  n %zu, %s path: uploaded in %.0f ms\n", n, path.c_str(), msSince(u0));
      // The frame's fixed part: clears and the deferred lighting pass, with
      // every glyph hidden by the threshold (the raster path compacts them
      // away in the warm-up; the others cull each glyph every frame).
      render::FrameParams empty;
      empty.scale = scale;
      empty.faMin = 10.0;
      const FrameTime emptyT = timeFrames(gl, r, cams, empty, target, o.frames, 1000.0 * o.rowBudgetS);
      for (Method& m : methods) {
        if (m.pipeline != path) continue;
        if (progress) progress("sweep", rowsDone, rows, "rows");
        ++rowsDone;
        if (m.skipped || overBudget()) continue;
        const render::FrameParams p = paramsFor(m, scale, o.gamma);
        // A tessellated frame of a million glyphs or more is long; one timed frame says enough.
        const int frames = m.tessellation > 0 && n >= 1000000 ? 1 : o.frames;
        const bool raster = path == "raster";
        const std::uint64_t prepassesBefore = raster ? render::asRaster(r.glyphPath()).occlusionPrepasses() : 0;
        double covered = nan;
        const FrameTime ft = timeFrames(gl, r, cams, p, target, frames, 1000.0 * o.rowBudgetS,
                                        [&] { covered = coveredPct(r.readback(cams[0], target)); });
        const bool prepassRan = raster && render::asRaster(r.glyphPath()).occlusionPrepasses() > prepassesBefore;
        m.skipped = ft.warmMs > 1000.0 * o.budgetS;
        double newton = nan;
        if (m.glyph == render::GlyphKind::Superquadric && m.tessellation == 0) {
          render::FrameParams st = p;
          st.iterationStats = true;
          r.render(cams[0], st, target);
          // Paths that keep no count (compute) report none.
          if (r.iterationStats().pixels > 0) newton = r.iterationStats().mean;
        }
        const double bytes = double(r.gpuBytes()) / double(n);
        const double vtk = m.tessellation > 0 ? double(render::TessellatedGlyphs::perGlyphMeshBytes(m.tessellation)) : nan;
        std::ostringstream f;
        f << m.pipeline << ',' << m.name << ',' << m.tessellation << ',' << n << ',' << o.width << ',' << o.height << ','
          << ft.frames << ',' << field(ft.wallMs, "%.3f") << ',' << field(ft.gpuMs, "%.3f") << ','
          << field(emptyT.wallMs, "%.3f") << ',' << field(covered, "%.2f") << ',' << field(newton, "%.3f") << ','
          << field(bytes, "%.2f") << ',' << field(vtk, "%.0f") << ',' << field(m.coveragePct, "%.4f") << ','
          << (prepassRan ? 1 : 0) << ",\"" << ctx.describe() << "\"\n";
        text += f.str();
        save();
        // Against the raster path's row of the family, whichever ran first.
        frameMs[path][family(m)] = ft.wallMs;
        std::string ratio;
        for (const auto& [other, byFamily] : frameMs) {
          const std::string& a = raster ? path : other;
          const std::string& b = raster ? other : path;
          if (a != "raster" || b == "raster" || !frameMs[a].count(family(m)) || !frameMs[b].count(family(m))) continue;
          char t[80];
          std::snprintf(t, sizeof t, "; raster/%s %.2f", b.c_str(), frameMs[a][family(m)] / frameMs[b][family(m)]);
          ratio += t;
        }
        if (progress) progress({}, 0, 0, {});
        std::fprintf(stderr, "  %-31s n %-10zu %10.2f ms (GPU %.2f, empty %.2f; %d frames), %.1f%% covered, %.1f B/glyph%s%s%s\n",
                     m.name.c_str(), n, ft.wallMs, ft.gpuMs, emptyT.wallMs, ft.frames, covered, bytes,
                     prepassRan ? ", pre-pass" : "", ratio.c_str(), m.skipped ? "; larger counts skipped" : "");
      }
    }
  }
}

}  // namespace tg::app
