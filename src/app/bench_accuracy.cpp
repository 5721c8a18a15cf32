// `tensorglyph bench accuracy`: the superquadric march's speed/accuracy trade.
// Sweeps maximum iterations x epsilon on one scene and measures, per setting,
// the frame time, the Newton iteration statistics and the error against the
// double-precision reference (src/ref/superquadric_ref).

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "app/scale/option_ranges.h"
#include "app/scale/option_table.h"
#include "app/bench.h"
#include "app/field_flags.h"
#include "app/scale/frame_size.h"
#include "app/output_check.h"
#include "app/cli_common.h"
#include "app/progress.h"
#include "app/plot.h"
#include "app/scene.h"
#include "gl/shader_library.h"
#include "io/field/atomic_file.h"
#include "ref/blob_ref.h"
#include "ref/image_diff.h"
#include "ref/superquadric_ref.h"
#include "render/renderer.h"

namespace tg::app {
namespace {


struct Options {
  std::string input, csv, plot, backend = "osmesa";
  FieldFlags field;
  int width = 640, height = 480, frames = 5, repeats = 3;
  double gamma = 3.0;
  bool quiet = false;
  std::optional<double> faMin;
  std::vector<int> iterations{1, 2, 3, 4, 5, 6, 8, 10, 12, 15, 20, 30};
  std::vector<double> epsilons{1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7};
  // --glyph blob sweeps the blob's samples per span and cutoff instead.
  bool blob = false;
  render::BlobParams blobParams;
  std::vector<int> steps{1, 2, 3, 4, 6, 8, 12};
  std::vector<double> cutoffs{1e-1, 1e-2, 1e-3, 1e-4, 1e-5};
  std::string sweepFlag;  // the first sweep option given, refused for the other kind
};

Options parse(int argc, const char** argv) {
  Options o;
  OptionTable ap("tensorglyph bench accuracy [INPUT] -o CSV [options]\n"
           "Superquadric march: frame time, Newton iterations and error against the\n"
           "double-precision reference, over maximum iterations x epsilon; with --glyph\n"
           "blob, Blinn's blobs on the cpu path over samples per span x cutoff.");
  using Args = OptionArgs;
  addInputArg(ap, o.input);
  ap.arg("-o CSV").help("one row per setting").action([&](Args a) { o.csv = a[1]; });
  ap.arg("--plot PNG").help("error against frame time (default: the CSV path with .png)").action([&](Args a) {
    o.plot = a[1];
  });
  ap.arg("--size W H").help("image size in pixels").range(ranges::kBenchFrameSide)
      .byDefault(formatSize(o.width, o.height)).action([&](Args a) {
    o.width = int(parseInt(a[0], a[1]));
    o.height = int(parseInt(a[0], a[2]));
  });
  ap.arg("--gamma G").help("superquadric sharpness").range(ranges::kGamma).byDefault(formatNumber(o.gamma)).action([&](Args a) {
    o.gamma = parseDouble("--gamma", a[1]);
  });
  ap.arg("--glyph KIND").help("superquadric (default) or blob").oneOf("superquadric or blob").action([&](Args a) {
    if (std::string(a[1]) != "superquadric" && std::string(a[1]) != "blob")
      throw UsageError(std::string("--glyph: bench accuracy measures superquadric or blob, not \"") + a[1] + "\"");
    o.blob = std::string(a[1]) == "blob";
  });
  auto swept = [&o](const char* flag) {
    if (o.sweepFlag.empty()) o.sweepFlag = flag;
  };
  ap.arg("--iterations LIST").help("maximum iterations, comma-separated")
      .rangeList(ranges::kIterations).byDefault(formatList(o.iterations)).action([&, swept](Args a) {
        o.iterations = parseList<int>("--iterations", a[1], [](auto f, auto t) { return parseInt(f, t); });
        swept("--iterations");
      });
  ap.arg("--epsilon LIST").help("tolerances, comma-separated").rangeList(ranges::kEpsilon)
      .byDefault(formatList(o.epsilons))
      .action([&, swept](Args a) {
        o.epsilons = parseList<double>("--epsilon", a[1], parseDouble);
        swept("--epsilon");
      });
  ap.arg("--blob-steps LIST").help("blob: samples per span, comma-separated").rangeList(ranges::kBlobSteps)
      .byDefault(formatList(o.steps)).action([&, swept](Args a) {
        o.steps = parseList<int>("--blob-steps", a[1], [](auto f, auto t) { return parseInt(f, t); });
        swept("--blob-steps");
      });
  ap.arg("--blob-cutoff LIST").help("blob: cutoffs, comma-separated").rangeList(ranges::kBlobCutoff)
      .byDefault(formatList(o.cutoffs)).action([&, swept](Args a) {
        o.cutoffs = parseList<double>("--blob-cutoff", a[1], parseDouble);
        swept("--blob-cutoff");
      });
  ap.arg("--blob-threshold T").help("blob: the threshold (render's --blob-threshold)").range(ranges::kBlobThreshold)
      .byDefault(formatNumber(o.blobParams.threshold)).action([&](Args a) { o.blobParams.threshold = parseDouble(a[0], a[1]); });
  ap.arg("--blobbiness B").help("blob: Blinn's blobbiness (render's --blobbiness)").range(ranges::kBlobbiness)
      .byDefault(formatNumber(o.blobParams.blobbiness)).action([&](Args a) { o.blobParams.blobbiness = parseDouble(a[0], a[1]); });
  ap.arg("--frames N").help("timed frames per setting; the median is reported").range(ranges::kFrames)
      .byDefault(std::to_string(o.frames))
      .action([&](Args a) { o.frames = int(parseInt(a[0], a[1])); });
  ap.arg("--repeats N")
      .help("times each setting is measured, in rounds over all settings (each round in the reverse order of the "
            "last, so that drift falls on every setting alike); the frame time reported is the median of the rounds' "
            "medians, with their minimum and maximum")
      .range(ranges::kRepeats).byDefault(std::to_string(o.repeats))
      .action([&](Args a) { o.repeats = int(parseInt(a[0], a[1])); });
  ap.arg("--fa-min F").help("hide glyphs with FA below F").range(ranges::kUnit).action([&](Args a) {
    o.faMin = parseDouble(a[0], a[1]);
  });
  ap.arg("--backend NAME").help("osmesa (default), egl, glfw or auto").action([&](Args a) { o.backend = a[1]; });
  ap.arg("-q,--quiet").help("no progress line on a terminal's stderr").action([&](Args) { o.quiet = true; });
  o.field.addTo(ap, true);
  parseCommandLine(ap, argc, argv);
  return o;
}

std::string withExtension(const std::string& path, const std::string& ext) {
  const auto slash = path.find_last_of('/'), dot = path.find_last_of('.');
  const bool hasExt = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (hasExt ? path.substr(0, dot) : path) + ext;
}

void validate(Options& o) {
  if (o.csv.empty()) throw UsageError("-o CSV is required");
  if (o.plot.empty()) o.plot = withExtension(o.csv, ".png");
  checkFrameSize("--size", o.width, o.height);
  if (!o.sweepFlag.empty() && o.blob != (o.sweepFlag == "--blob-steps" || o.sweepFlag == "--blob-cutoff"))
    throw UsageError(o.sweepFlag + " sweeps " + (o.blob ? "the superquadric march" : "blobs (--glyph blob)") +
                     "; this run measures " + (o.blob ? "blobs" : "superquadrics"));
  // Within the range, but nothing to measure: gamma 0 draws no march.
  if (!o.blob && o.gamma == 0.0) throw UsageError("--gamma 0 draws definite glyphs as ellipsoids, without the march bench accuracy measures; give a gamma above 0");
  o.field.validate();
  checkBackend(o.backend);
  refuseOutputsOverInputs({{"-o", o.csv}, {"--plot", o.plot}},
                          {{"INPUT", o.input}, {"--mask", o.field.read.selection.maskPath}});
}

// A superquadric row's march, or a blob row's steps (in `iterations`) and cutoff (in `epsilon`).
struct Row {
  int iterations;
  double epsilon;
  std::vector<double> roundMs;  // each round's median frame time
  render::IterationStats stats;
  ref::ImageDiff diff;
  bool isDefault = false;  // render's default march (render::MarchParams)
  // The median of the rounds (the mean of the middle two for an even count), and their range.
  double frameMs() const {
    std::vector<double> t = roundMs;
    std::sort(t.begin(), t.end());
    const std::size_t n = t.size();
    return n == 0 ? 0.0 : n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
  }
  double minMs() const { return roundMs.empty() ? 0.0 : *std::min_element(roundMs.begin(), roundMs.end()); }
  double maxMs() const { return roundMs.empty() ? 0.0 : *std::max_element(roundMs.begin(), roundMs.end()); }
  // Percentages of the reference's glyph pixels.
  double percent(std::size_t n) const { return 100.0 * double(n) / double(std::max<std::size_t>(diff.refCovered, 1)); }
  double coveragePct() const { return percent(diff.coverageMismatch); }
  double interiorPct() const { return percent(diff.interiorMismatch); }
};

// The CSV's bytes into `out`, not yet committed. Units in the names: depth
// errors in glyph sizes (each glyph's largest semi-axis, the unit of epsilon).
void writeCsv(const std::vector<Row>& rows, bool blob, io::AtomicFile& out) {
  std::string f = std::string(blob ? "steps,cutoff" : "iterations,epsilon") +
      ",frame_ms,mean_iterations,max_iterations,coverage_error_pct,interior_error_pct,"
      "depth_err_median_sizes,depth_err_p99_sizes,depth_err_max_sizes,normal_err_median_deg,normal_err_p99_deg,"
      "normal_err_max_deg,frame_ms_min,frame_ms_max,repeats,default\n";
  char line[600], march[64];
  for (const Row& r : rows) {
    // Blobs do not march: their iteration columns are empty.
    if (blob) march[0] = ',', march[1] = '\0';
    else std::snprintf(march, sizeof march, "%.3f,%u", r.stats.mean, r.stats.max);
    std::snprintf(line, sizeof line, "%d,%g,%.3f,%s,%.4f,%.4f,%.3g,%.3g,%.3g,%.3g,%.3g,%.3g,%.3f,%.3f,%zu,%d\n",
                  r.iterations, r.epsilon, r.frameMs(), march, r.coveragePct(), r.interiorPct(),
                  r.diff.depth.median, r.diff.depth.p99, r.diff.depth.max, r.diff.normalDeg.median,
                  r.diff.normalDeg.p99, r.diff.normalDeg.max, r.minMs(), r.maxMs(), r.roundMs.size(),
                  int(r.isDefault));
    f += line;
  }
  out.write(f.data(), f.size());
}

// The table on stdout: units in a second header line, * on the default row.
void printTable(const std::vector<Row>& rows, bool blob) {
  std::printf("%5s %8s %9s %17s %6s %4s %9s %10s %10s %9s %7s\n", blob ? "steps" : "iter", blob ? "cutoff" : "eps", "frame", "frame min-max", "mean",
              "max", "cover", "depth_p99", "depth_max", "norm_p99", "default");
  std::printf("%5s %8s %9s %17s %6s %4s %9s %10s %10s %9s %7s\n", "", blob ? "[T]" : "[sizes]", "[ms]", "[ms]", "[iter]", "[it]",
              "[%]", "[sizes]", "[sizes]", "[deg]", "");
  for (const Row& r : rows) {
    char range[40];
    std::snprintf(range, sizeof range, "%.2f-%.2f", r.minMs(), r.maxMs());
    char mean[16] = "-", most[16] = "-";
    if (!blob) {
      std::snprintf(mean, sizeof mean, "%.2f", r.stats.mean);
      std::snprintf(most, sizeof most, "%u", r.stats.max);
    }
    std::printf("%5d %8.0e %9.2f %17s %6s %4s %9.4f %10.2e %10.2e %9.3f %7s\n", r.iterations, r.epsilon,
                r.frameMs(), range, mean, most, r.coveragePct(), r.diff.depth.p99, r.diff.depth.max,
                r.diff.normalDeg.p99, r.isDefault ? "*" : "");
  }
  std::fflush(stdout);
}

bool plot(const std::vector<Row>& rows, const std::vector<double>& epsilons, int repeats, bool blob,
          const std::string& path) {
  // One series per epsilon, its points in order of maximum iterations, each
  // labelled with its iterations and barred with its rounds' range.
  const std::string x = "frame time (ms): median of " + std::to_string(repeats) + " rounds, bars min-max; labels: " +
                        (blob ? "steps" : "iterations");
  PlotPanel cover{"Coverage error vs frame time", x, "% glyph pixels", true, {}};
  PlotPanel depth{"Depth error (p99) vs frame time", x, "glyph sizes", true, {}};
  PlotPanel normal{"Normal error (p99) vs frame time", x, "degrees", true, {}};
  const std::array<float, 3> palette[] = {{0.85f, 0.1f, 0.1f}, {0.9f, 0.55f, 0.0f}, {0.2f, 0.65f, 0.2f},
                                          {0.1f, 0.6f, 0.8f},  {0.2f, 0.3f, 0.85f}, {0.6f, 0.2f, 0.7f}};
  for (std::size_t k = 0; k < epsilons.size(); ++k) {
    char label[32];
    std::snprintf(label, sizeof label, blob ? "cutoff %g" : "eps %g", epsilons[k]);
    PlotSeries c{label, palette[k % 6], {}, {}, {}, -1, "default"};
    for (const Row& r : rows)
      if (r.epsilon == epsilons[k]) {
        if (r.isDefault) c.marked = int(c.points.size());
        c.points.push_back({r.frameMs(), r.coveragePct()});
        c.pointLabels.push_back(std::to_string(r.iterations));
        c.xSpread.push_back({r.minMs(), r.maxMs()});
      }
    PlotSeries d = c, n = c;
    std::size_t j = 0;
    for (const Row& r : rows)
      if (r.epsilon == epsilons[k]) {
        d.points[j] = {r.frameMs(), r.diff.depth.p99};
        n.points[j++] = {r.frameMs(), r.diff.normalDeg.p99};
      }
    cover.series.push_back(c);
    depth.series.push_back(d);
    normal.series.push_back(n);
  }
  return writePlot({cover, depth, normal}, path);
}

}  // namespace

int benchAccuracy(int argc, const char** argv) {
  Options o = parse(argc, argv);
  validate(o);
  TerminalProgress progress(o.quiet);
  const util::ProgressSink sink = progress.sink();
  o.field.read.progress = sink;
  Scene scene = loadScene(o.input, o.field.read);
  if (sink) sink({}, 0, 0, {});
  reportLoad(scene.field, "bench accuracy", o.field.read);
  const tensor::GlyphSet glyphs =
      tensor::buildGlyphs(scene.field.positions, scene.field.tensors, scene.field.ids, 0, o.field.glyph, sink);
  if (sink) sink("reference", 0, 0, {});
  checkDrawable(glyphs, scene.field.path);
  render::FrameParams params;
  const tensor::ResolvedScale sized =
      tensor::resolveScale(o.field.scaleParams(), tensor::sampleMagnitudes(glyphs, scene.field.sampleSpacing));
  params.scale = sized.scale;
  params.sizing = sized.mapping;
  params.faMin = o.faMin.value_or(scene.preferredFaMin.value_or(0.0));
  params.glyph = o.blob ? render::GlyphKind::Blob : render::GlyphKind::Superquadric;
  params.gamma = o.gamma;
  params.blob = o.blobParams;
  auto [lo, hi] = tensor::glyphBoxWC(glyphs, params.scale, params.sizing);
  // A blob reaches where its bump still adds (render::kindPadWC), farthest at the smallest cutoff swept.
  double pad = render::kindPadWC(params, glyphs.maxAbsEigenvalue);
  for (const double c : o.cutoffs) {
    render::FrameParams q = params;
    q.blob.cutoff = c;
    pad = std::max(pad, render::kindPadWC(q, glyphs.maxAbsEigenvalue));
  }
  lo -= pad;
  hi += pad;
  const tensor::FramingBox frame = tensor::framingBox(glyphs, !scene.field.grid, sized.typicalRadiusWC);
  const render::Camera cam = render::makeCamera(
      sceneCamera(scene, frame.lo, frame.hi, render::Projection::Perspective, 30.0, double(o.width) / o.height),
      o.width, o.height, lo, hi);

  const auto tr = Clock::now();
  ref::RefParams refParams{params.scale, params.faMin, params.sizing};
  refParams.blobThreshold = o.blobParams.threshold;
  refParams.blobBlobbiness = o.blobParams.blobbiness;
  const ref::RefImage reference = o.blob ? ref::renderBlobs(cam, glyphs.glyphs, refParams, o.gamma)
                                         : ref::renderSuperquadrics(cam, glyphs.glyphs, refParams, o.gamma);
  const double refMs = msSince(tr);
  // Depth errors in units of each glyph's largest semi-axis, the unit of epsilon.
  std::unordered_map<std::uint32_t, double> size;
  for (const auto& g : glyphs.glyphs)
    size[g.id] = tensor::glyphRadiusWC(params.scale, params.sizing,
                                       std::max(std::abs(double(g.eigenvalues[0])), std::abs(double(g.eigenvalues[2]))));
  ref::DiffOptions diffOpt;
  diffOpt.depthUnit = [&](std::uint32_t id, double) { return size.at(id); };

  auto ctx = createContext(o.backend, o.width, o.height);
  const gl::ShaderLibrary lib;
  render::GlyphRenderer renderer(ctx->api(), lib, nullptr, o.blob ? "cpu" : "raster");
  render::GBuffer target(ctx->api(), o.width, o.height);
  renderer.upload(glyphs);
  if (sink) sink({}, 0, 0, {});
  const auto refPixels =
      std::size_t(std::count_if(reference.id.begin(), reference.id.end(), [](auto id) { return id != ref::kNoGlyph; }));
  // Every error is a share of these pixels: with none, each row would claim 0%.
  if (refPixels == 0)
    throw io::InputError("bench accuracy: " + scene.field.path +
                         ": no glyph covers a pixel at this scale and size, so there is nothing to compare (try a "
                         "larger --scale, or --scale-mode spacing)");
  // One summary line, with how to read the table: a failure's own line follows it alone.
  const render::MarchParams march;
  const render::BlobParams blob;
  const std::vector<int>& counts = o.blob ? o.steps : o.iterations;
  const std::vector<double>& tolerances = o.blob ? o.cutoffs : o.epsilons;
  const int defaultCount = o.blob ? blob.steps : march.maxIterations;
  const double defaultTolerance = o.blob ? blob.cutoff : march.epsilon;
  bool defaultSwept = false;
  for (double eps : tolerances)
    for (int it : counts) defaultSwept |= it == defaultCount && eps == defaultTolerance;
  std::fprintf(stderr,
               "bench accuracy: %s, %zu glyphs, %s, gamma %g, %dx%d, %s (%s); reference %.0f ms, %zu glyph pixels; frame "
               "time: the median of %d rounds (each the median of %d frames), with their min-max; depth in glyph "
               "sizes (the largest semi-axis); %s (%s %d, %s %g)\n",
               scene.field.path.c_str(), glyphs.glyphs.size(), o.blob ? "blobs" : "superquadrics", o.gamma, o.width,
               o.height, ctx->backendName(), ctx->describe().c_str(), refMs, refPixels, o.repeats, o.frames,
               defaultSwept ? "* marks the default setting" : "the default setting is not swept",
               o.blob ? "steps" : "iterations", defaultCount, o.blob ? "cutoff" : "epsilon", defaultTolerance);

  // Round 0 measures the errors and the iteration counts (the same in every
  // round); every round times each setting, alternate rounds in reverse order.
  std::vector<Row> rows;
  for (double eps : tolerances)
    for (int it : counts) rows.push_back({it, eps, {}, {}, {}, it == defaultCount && eps == defaultTolerance});
  const double total = double(rows.size()) * o.repeats;
  double done = 0;
  for (int round = 0; round < o.repeats; ++round)
    for (std::size_t j = 0; j < rows.size(); ++j) {
      Row& r = rows[round % 2 ? rows.size() - 1 - j : j];
      if (sink) sink("settings", done++, total, "settings");
      if (o.blob) {
        params.blob.steps = r.iterations;
        params.blob.cutoff = r.epsilon;
      } else {
        params.march = {r.iterations, r.epsilon};
      }
      params.iterationStats = false;
      renderer.render(cam, params, target);  // warm-up: compiles and caches state
      ctx->api().Finish();
      std::vector<double> times;
      for (int f = 0; f < o.frames; ++f) {
        const auto t0 = Clock::now();
        renderer.render(cam, params, target);
        ctx->api().Finish();
        times.push_back(msSince(t0));
      }
      std::sort(times.begin(), times.end());
      r.roundMs.push_back(times[times.size() / 2]);
      if (round > 0) continue;
      const render::FrameImage img = renderer.readback(cam, target, render::Channels::All);
      if (!o.blob) {
        params.iterationStats = true;  // a separate frame: the counters cost time
        renderer.render(cam, params, target);
        r.stats = renderer.iterationStats();
      }
      r.diff = ref::diffImages(img, reference, cam, diffOpt);
      if (r.diff.nonFinite && sink) sink({}, 0, 0, {});
      if (r.diff.nonFinite) std::fprintf(stderr, "bench accuracy: %zu non-finite GPU values\n", r.diff.nonFinite);
    }
  if (sink) sink({}, 0, 0, {});  // the table goes to stdout, often the same terminal
  printTable(rows, o.blob);
  progress.finish();
  // The CSV is committed after the plot, so that a failure leaves neither.
  io::AtomicFile csv(o.csv);
  writeCsv(rows, o.blob, csv);
  if (!plot(rows, tolerances, o.repeats, o.blob, o.plot))
    std::fprintf(stderr, "bench accuracy: %s: no font found, so the plot has no labels\n", printable(o.plot).c_str());
  csv.commit(std::int64_t(csv.bytesWritten()));
  std::fprintf(stderr, "bench accuracy: wrote %s and %s\n", printable(o.csv).c_str(), printable(o.plot).c_str());
  return 0;
}

}  // namespace tg::app
