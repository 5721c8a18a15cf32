// `render`: one frame of a field (or the built-in scene) to an image file,
// through the same RenderSession the Python module draws with.
#include <malloc.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/field_flags.h"
#include "app/scale/option_table.h"
#include "app/pick.h"
#include "app/pick_json.h"
#include "app/progress.h"
#include "app/render_options.h"
#include "app/render_session.h"
#include "io/core/image_writer.h"
#include "render/legend/legend_pass.h"
#include "render/mesh_item.h"
#include "render/tract_item.h"

namespace tg::app {
namespace {

// Below a pixel the typical glyph is a speck or nothing; a clamp that
// shrinks more than this share of the glyphs has replaced their sizes.
constexpr double kSubPixelGlyph = 1.0;
constexpr double kClampWarnShare = 0.05;

}  // namespace

int cmdRender(int argc, const char** argv) {
  RenderOptions o;
  OptionTable table(kRenderUsage);
  addRenderOptions(table, o);
  parseCommandLine(table, argc, argv);
  validateRenderOptions(o, true);
  TerminalProgress progress(o.quiet);
  const util::ProgressSink sink = progress.sink();
  io::ReadOptions read = o.field.read;
  read.progress = sink;
  const auto t0 = Clock::now();
  Scene loaded = loadScene(o.input, read);
  attachWholeField(loaded, o.field, o.input, read);
  const double loadMs = msSince(t0);
  if (sink) sink({}, 0, 0, {});  // before the load's warnings
  reportLoad(loaded.field, "render", read);
  std::vector<io::MeshData> meshes = o.mesh.read(o.input, "render");
  // --pick keeps the samples (app/pick.h): 40 bytes a tensor; else they go
  // before the upload.
  std::optional<PickTable> pickTable;
  RenderSession session(o, std::move(loaded), std::move(meshes), false, "render", [&](io::TensorField& f) {
    if (!o.pick.pixels.empty()) pickTable.emplace(f, o.field.glyph);
    f.releaseSamples();
  }, sink);
  const Scene& scene = session.scene();
  const RenderSession::Frame fr = session.frame(o);
  const render::FrameParams& params = fr.params;
  const render::Camera& cam = fr.camera;
  render::GlyphRenderer& renderer = session.renderer();
  gl::Context& ctx = session.context();
  const std::size_t glyphCount = session.glyphCount();
  // A blank image needs its reason: an absolute --scale on a DTI field
  // (eigenvalues about 1e-3), a far camera; glyphs under a pixel are lost.
  // Measured at the depth of the glyphs' box centre, not of the look-at
  // point: an --eye or --look-at far from the glyphs makes the two differ.
  const glm::dvec3 centre = 0.5 * (fr.framing.lo + fr.framing.hi);
  const double depth = glm::dot(centre - cam.desc.eyeWC, cam.viewDirectionWC());
  const double lookDepth = glm::length(cam.desc.lookAtWC - cam.desc.eyeWC);
  const double perWorldUnit = cam.desc.projection == render::Projection::Orthographic || !(depth > 0.0)
                                  ? render::pixelsPerWorldUnit(cam)
                                  : render::pixelsPerWorldUnit(cam) * lookDepth / depth;
  const double typicalPx = depth > 0.0 ? 2.0 * fr.sized.typicalRadiusWC * perWorldUnit : 1.0;
  // The camera's options can be the reason too: an --eye far away, a wide
  // --ortho or --fov.
  const std::string cameraFlags = std::string(o.eye ? ", a nearer --eye" : "") + (o.ortho ? ", a smaller --ortho" : "") +
                                  (o.fov ? ", a smaller --fov" : "");
  if (typicalPx < kSubPixelGlyph) {
    if (sink) sink({}, 0, 0, {});
    std::fprintf(stderr,
                 "tensorglyph render: the typical glyph is %.2g pixels across, so the image shows almost nothing; a "
                 "larger --scale%s draws them (--scale alone is a factor on the automatic size)\n",
                 typicalPx, cameraFlags.c_str());
  }
  // The clamp the user did not ask for must not silently flatten the sizes
  // a --scale or --scale-mode asked for (on the defaults it is the design:
  // info and --verbose give its share).
  const bool sizeAsked = o.field.scale || o.field.scaleMode;
  if (sizeAsked && !o.field.sizing.clampSpacings && fr.sized.clampedFraction > kClampWarnShare) {
    if (sink) sink({}, 0, 0, {});
    std::fprintf(stderr,
                 "tensorglyph render: the default clamp (%g sample spacings across) shrinks %.0f%% of the glyphs at "
                 "this size, so their size no longer shows their magnitude; --clamp 0 turns it off (or give a larger "
                 "--clamp, a smaller --scale, --magnitude log)\n",
                 tensor::ScaleParams::kDefaultClamp, 100.0 * fr.sized.clampedFraction);
  }
  // Glyphs around the camera are not seen: each is drawn from outside.
  if (typicalPx > 100.0 * std::max(o.width, o.height)) {
    if (sink) sink({}, 0, 0, {});
    std::fprintf(stderr,
                 "tensorglyph render: the typical glyph is %.2g pixels across, far larger than the %d x %d image, so "
                 "the camera may be inside the glyphs and see none; a smaller --scale draws them\n",
                 typicalPx, o.width, o.height);
  }
  if (params.glyph == render::GlyphKind::Blob)
    if (const std::string hint = blobThresholdHint(params.blob, "--blob-threshold", "--blobbiness"); !hint.empty()) {
      if (sink) sink({}, 0, 0, {});
      std::fprintf(stderr, "tensorglyph render: %s\n", hint.c_str());
    }
  // An automatic sign window pinned by one peak (app/stress_defaults.h).
  if (params.color == render::ColorMode::Sign && !params.colorWindow) {
    if (const std::string hint = signWindowHint(renderer.colorWindow(params).y, session.magnitudes().sorted,
                                                params.legend.units);
        !hint.empty()) {
      if (sink) sink({}, 0, 0, {});
      std::fprintf(stderr, "tensorglyph render: %s\n", hint.c_str());
    }
  }
  // The first frame by its passes (one of many seconds on a large field
  // draws no line otherwise); the timed repeats by frames, unperturbed by
  // the waits a pass's report makes.
  if (sink) sink("rendering", 0, 0, util::kPassesUnit);
  const render::PassProgress passes = sink ? render::PassProgress([&sink](std::string_view, int done, int total) {
    sink("rendering", done, total, util::kPassesUnit);
  }) : render::PassProgress{};
  const auto t3 = Clock::now();
  session.draw(fr, passes);
  const double frameMs = msSince(t3);
  if (sink && o.repeat > 0) sink("timing", 0, o.repeat, "frames");
  if (const auto* legend = static_cast<const render::LegendPass*>(renderer.legendPass())) {
    const render::LegendRect& r = legend->layout().panel;
    if (sink && (r.x1 > float(o.width) || r.y1 > float(o.height))) sink({}, 0, 0, {});
    // Smaller text is a remedy only where the text is larger than 1.
    if (r.x1 > float(o.width) || r.y1 > float(o.height))
      std::fprintf(stderr,
                   "tensorglyph render: --legend: the legend needs %.0f x %.0f pixels and is cut off by the %d x %d "
                   "image; use a larger --size%s\n",
                   double(r.x1 - r.x0), double(r.y1 - r.y0), o.width, o.height,
                   legend->layout().textScale > 1 ? ", or --legend-text-scale 1" : "");
  }
  std::vector<double> times, cpuTimes;
  for (int k = 0; k < o.repeat; ++k) {
    const auto tk = Clock::now();
    const double cpuK = processCpuMs();
    session.draw(fr);
    times.push_back(msSince(tk));
    cpuTimes.push_back(processCpuMs() - cpuK);
    if (sink) sink("timing", 1.0 + k, o.repeat, "frames");
  }
  progress.finish();
  if (o.stats) {
    const render::IterationStats st = renderer.iterationStats();
    // Loop passes count every fragment's march, Newton or not: what the
    // grid search and the early rejections cost on a CPU.
    std::fprintf(stderr,
                 "tensorglyph render: Newton iterations: mean %.2f, max %u over %llu pixels; %llu march loop passes "
                 "over all superquadric fragments\n",
                 st.mean, st.max, static_cast<unsigned long long>(st.pixels),
                 static_cast<unsigned long long>(st.gaugeCalls));
  }
  const std::uint64_t drawn = renderer.drawnGlyphs();
  // --fa-min is a uniform, so a threshold above every glyph's FA cannot fail
  // the load; an empty image still needs its reason.
  if (drawn == 0 && glyphCount > 0 && !(typicalPx < kSubPixelGlyph)) {
    if (sink) sink({}, 0, 0, {});
    const std::string why = params.faMin > 0 ? "below --fa-min " + formatNumber(params.faMin) + " or outside" : "outside";
    const std::string flags = std::string(o.eye ? " --eye" : "") + (o.lookAt ? " --look-at" : "") + (o.up ? " --up" : "") +
                              (o.fov ? " --fov" : "") + (o.ortho ? " --ortho" : "");
    std::fprintf(stderr, "tensorglyph render: no glyph is drawn: all %zu are %s the view%s\n", glyphCount, why.c_str(),
                 flags.empty() ? "" : (" that" + flags + " set").c_str());
  }
  // The first frame's freed heap (llvmpipe's compile and scene memory)
  // goes back to the system before the readback allocates: a lower peak.
  malloc_trim(0);
  const render::FrameImage img =
      session.readback(fr, io::writesGeometryChannels(o.output) ? render::Channels::All : render::Channels::Rgba8);
  std::vector<std::string> picks;
  for (const PixelIJ& px : o.pick.pixels)
    picks.push_back(pickJson(pickPixel(ctx.api(), renderer, cam, session.target(), *pickTable, px)));
  io::writeImage(img, o.output);
  // After the image: a failed write prints no picks.
  for (const std::string& line : picks) std::printf("%s\n", line.c_str());
  if (o.verbose || o.repeat > 0) {
    std::sort(times.begin(), times.end());
    std::fprintf(stderr,
                 "tensorglyph render: %zu glyphs, %dx%d, %s (%s)\n"
                 "  load %.1f ms, eigen %.1f ms, upload %.1f ms, first frame %.1f ms",
                 glyphCount, o.width, o.height, ctx.backendName(), ctx.describe().c_str(), loadMs,
                 session.buildMs(), session.uploadMs(), frameMs);
    std::sort(cpuTimes.begin(), cpuTimes.end());
    if (!times.empty())
      std::fprintf(stderr, ", median of %zu frames %.2f ms (CPU, all threads: %.2f ms)", times.size(),
                   times[times.size() / 2], cpuTimes[cpuTimes.size() / 2]);
    std::fprintf(stderr, "\n  %llu glyphs drawn (after FA and frustum culling), scale %.6g, fa-min %.3g, peak RSS %.1f MiB\n",
                 static_cast<unsigned long long>(drawn), params.scale, params.faMin,
                 double(peakRssBytes()) / (1024.0 * 1024.0));
    const std::string framing = o.eye ? "--eye given; it looks by default at the centre of " + fr.framing.why
                                : scene.preferredCamera ? std::string("the built-in scene's own view")
                                                        : fr.framing.why;
    const std::string how = renderer.glyphPath().how();
    std::fprintf(stderr, "  glyph path: %s%s%s\n", renderer.glyphPath().name().data(),
                 session.pipelineWhy().empty() ? "" : (" (" + session.pipelineWhy() + ")").c_str(),
                 how.empty() ? "" : ("; " + how).c_str());
    std::fprintf(stderr, "  size: %s\n  framing: %s\n", fr.sized.why.c_str(), framing.c_str());
    if (scene.stress) std::fprintf(stderr, "  %s\n", stressDefaultsLine(*scene.stress).c_str());
    if (params.ao.enabled)
      std::fprintf(stderr, "  ambient occlusion: radius %.6g (%s), strength %.3g, %d samples\n",
                   renderer.aoRadiusWC(params), params.ao.radius > 0 ? "--ao-radius" : "auto",
                   params.ao.strength, params.ao.samples);
    if (params.outline.enabled)
      std::fprintf(stderr, "  outlines: width %.3g px, crease %.3g deg\n", params.outline.width, params.outline.creaseDeg);
    for (const auto& item : renderer.context())
      if (const auto* m = dynamic_cast<const render::MeshItem*>(item.get()))
        std::fprintf(stderr, "  %s: %zu triangles, %s, %.1f MiB of GPU memory\n", printable(m->label()).c_str(), m->triangleCount(),
                     render::meshModeName(m->params().mode), double(m->gpuBytes()) / (1024.0 * 1024.0));
      else if (const auto* t = dynamic_cast<const render::TractItem*>(item.get()))
        std::fprintf(stderr, "  %s: %zu streamlines, %zu segments, %s, %.1f MiB of GPU memory\n",
                     printable(t->label()).c_str(), t->streamlineCount(), t->segmentCount(),
                     t->params().byDirection ? "coloured by direction" : "one colour",
                     double(t->gpuBytes()) / (1024.0 * 1024.0));
    if (params.shadow.enabled)
      std::fprintf(stderr, "  shadows: map %d x %d texels, penumbra %.3g, %.1f MiB of GPU memory in all\n",
                   renderer.shadowMapSize(), renderer.shadowMapSize(), double(params.shadow.penumbra),
                   double(renderer.gpuBytes()) / (1024.0 * 1024.0));
  }
  return 0;
}

}  // namespace tg::app
