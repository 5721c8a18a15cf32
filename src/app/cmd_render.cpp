#include <chrono>
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "app/arg_parse.h"
#include "app/cli_common.h"
#include "app/effect_flags.h"
#include "app/commands.h"
#include "app/scene_flags.h"
#include "app/field_flags.h"
#include "app/frame_size.h"
#include "app/legend_flags.h"
#include "app/look_flags.h"
#include "app/mesh_flags.h"
#include "app/names.h"
#include "app/output_check.h"
#include "app/pick_flags.h"
#include "app/pick_json.h"
#include "app/scene.h"
#include "app/shadow_flags.h"
#include "app/slice_flags.h"
#include "gl/shader_library.h"
#include "io/image_writer.h"
#include "io/readers.h"
#include "render/legend_pass.h"
#include "render/renderer.h"
#include "tensor/glyph_scale.h"

namespace tg::app {
namespace {

struct RenderOptions : SceneFlags {
  std::string input, output, backend = "osmesa", glyph = "ellipsoid", color = "dec";
  PickFlags pick;
  int width = 1024, height = 768;
  double gamma = 3.0;
  std::optional<double> faMin, fov, ortho;
  std::optional<glm::dvec3> eye, lookAt, up;
  glm::vec4 background{0.08f, 0.08f, 0.10f, 1.0f};
  int repeat = 0, tessellate = 0, maxIterations = render::MarchParams{}.maxIterations;
  double epsilon = render::MarchParams{}.epsilon;
  bool verbose = false, stats = false;
};

RenderOptions parse(int argc, const char** argv) {
  RenderOptions o;
  OIIO::ArgParse ap;
  ap.intro("tensorglyph render [INPUT] -o OUT [options]").exit_on_error(false);
  using Args = OIIO::cspan<const char*>;
  auto rest = [](Args a) { return std::span<const char* const>(a.data() + 1, a.size() - 1); };
  addInputArg(ap, o.input);
  ap.arg("-o OUT").help("output image: .png (8-bit RGBA), .exr (float RGBA Z N id), other OIIO formats")
      .action([&](auto&, Args a) { o.output = a[1]; });
  ap.arg("--size W H").help("image size in pixels (default 1024 768)").action([&](auto&, Args a) {
    o.width = parseIntIn("--size", a[1], 1, kMaxFrameSide);
    o.height = parseIntIn("--size", a[2], 1, kMaxFrameSide);
  });
  ap.arg("--glyph KIND").help("ellipsoid (default; the built-in scene: superquadric), superquadric, "
                                  "or Teem's cylinder or box").action([&](auto&, Args a) {
    o.glyph = a[1];
    o.look.glyphGiven = true;
  });
  ap.arg("--iterations N").help("superquadric Newton iterations at most (default 10)").action([&](auto&, Args a) {
    o.maxIterations = parseIntIn("--iterations", a[1], 1, 1000);
  });
  ap.arg("--epsilon E").help("superquadric hit tolerance, relative to glyph size (default 1e-4)")
      .action([&](auto&, Args a) { o.epsilon = parseDouble("--epsilon", a[1]); });
  ap.arg("--tessellate R").help("draw the tessellated baseline instead: an R x R superquadric mesh per glyph, "
                                 "as VTK's vtkTensorGlyph (4..64; needs --glyph superquadric)")
      .action([&](auto&, Args a) { o.tessellate = parseIntIn("--tessellate", a[1], 0, render::TessellatedGlyphs::kMaxResolution); });
  ap.arg("--stats").help("report Newton iteration statistics on stderr").action([&](auto&, Args) { o.stats = true; });
  ap.arg("--gamma G").help("superquadric sharpness (Kindlmann 2004), >= 0").action([&](auto&, Args a) {
    o.gamma = parseDouble("--gamma", a[1]);
  });
  ap.arg("--fa-min F").help("hide glyphs with FA below F").action([&](auto&, Args a) { o.faMin = parseDoubleIn("--fa-min", a[1], 0.0, 1.0); });
  ap.arg("--eye X Y Z").help("camera position (WC)").action([&](auto&, Args a) { o.eye = parseVec3("--eye", rest(a)); });
  ap.arg("--look-at X Y Z").help("point the camera looks at (WC)").action([&](auto&, Args a) {
    o.lookAt = parseVec3("--look-at", rest(a));
  });
  ap.arg("--up X Y Z").help("camera up vector (WC)").action([&](auto&, Args a) { o.up = parseVec3("--up", rest(a)); });
  ap.arg("--fov DEG").help("perspective, vertical field of view (default 30)").action([&](auto&, Args a) {
    o.fov = parseDouble("--fov", a[1]);
  });
  ap.arg("--ortho HEIGHT").help("orthographic, view height in world units").action([&](auto&, Args a) {
    o.ortho = parseDouble("--ortho", a[1]);
  });
  ap.arg("--color MODE").help("dec, fa, md, cl, cp or sign (normal stress: orange tension, blue compression)").action([&](auto&, Args a) { o.color = a[1]; });
  ap.arg("--background R G B A").help("background colour, 0..1 (default 0.08 0.08 0.1 1)").action([&](auto&, Args a) {
    for (int k = 0; k < 4; ++k) o.background[k] = float(parseDouble("--background", a[1 + k]));
  });
  ap.arg("--backend NAME").help("osmesa (default), egl, glfw or auto").action([&](auto&, Args a) { o.backend = a[1]; });
  o.addSceneFlags(ap);
  o.pick.addTo(ap);
  ap.arg("--repeat N").help("render N more frames and report the median frame time").action([&](auto&, Args a) {
    o.repeat = parseIntIn("--repeat", a[1], 0, 10000);
  });
  ap.arg("--verbose").help("report timings and memory on stderr").action([&](auto&, Args) { o.verbose = true; });
  parseArgs(ap, argc, argv);
  return o;
}

// Every parameter is checked before anything is loaded or created.
void validate(const RenderOptions& o) {
  if (o.output.empty()) throw UsageError("-o OUT is required");
  checkFrameSize("--size", o.width, o.height);
  o.pick.validate(o.width, o.height);
  if (!glyphKindNamed(o.glyph))
    throw UsageError("--glyph: unknown kind \"" + o.glyph + "\"; choose " + kGlyphKindNames);
  if (!(o.gamma >= 0.0 && o.gamma <= 1e4)) throw UsageError("--gamma must be within 0..10000");
  if (o.tessellate != 0 && (o.tessellate < render::TessellatedGlyphs::kMinResolution ||
                            o.tessellate > render::TessellatedGlyphs::kMaxResolution))
    throw UsageError("--tessellate must be within 4..64");
  if (o.tessellate != 0 && o.glyph != "superquadric") throw UsageError("--tessellate needs --glyph superquadric");
  if (o.tessellate != 0 && o.stats) throw UsageError("--stats counts the ray march; --tessellate has none");
  if (o.maxIterations < 1 || o.maxIterations > 1000) throw UsageError("--iterations must be within 1..1000");
  if (!(o.epsilon >= 1e-9 && o.epsilon <= 0.5)) throw UsageError("--epsilon must be within 1e-9..0.5");
  o.validateSceneFlags(o.input);
  if (o.fov && o.ortho) throw UsageError("--fov and --ortho exclude each other");
  if ((o.lookAt || o.up) && !o.eye) throw UsageError("--look-at and --up need --eye");
  if (!colorModeNamed(o.color))
    throw UsageError("--color: unknown mode \"" + o.color + "\"; choose " + kColorModeNames);
  if (o.repeat < 0 || o.repeat > 10000) throw UsageError("--repeat must be within 0..10000");
  checkBackend(o.backend);
  if (!io::canWriteImage(o.output))
    throw UsageError("-o: no image format for \"" + o.output + "\"");
  std::vector<NamedPath> inputs = {{"INPUT", o.input}, {"--mask", o.field.read.selection.maskPath},
                                   {"--underlay", o.slices.fromField() ? "" : o.slices.underlay}};
  for (const NamedPath& m : o.mesh.inputs()) inputs.push_back(m);
  refuseOutputsOverInputs({{"-o", o.output}}, inputs);
}

// Frames `frame` (the sample positions, tensor::framingBox), not the glyphs'
// whole box: one singular glyph must not shrink the view.
render::CameraDesc chooseCamera(const RenderOptions& o, const Scene& s, const tensor::FramingBox& frame) {
  const render::Projection proj = o.ortho ? render::Projection::Orthographic : render::Projection::Perspective;
  const double aspect = double(o.width) / o.height;
  const glm::dvec3 lo = frame.lo, hi = frame.hi;
  render::CameraDesc d = sceneCamera(s, lo, hi, proj, o.fov.value_or(30.0), aspect);
  if (o.eye) {
    d.eyeWC = *o.eye;
    d.lookAtWC = o.lookAt.value_or(0.5 * (lo + hi));
    d.upWC = o.up.value_or(glm::dvec3(0, 1, 0));
  }
  if (o.ortho) d.orthoHeight = *o.ortho;
  if (const char* err = render::validateCamera(d); *err) {
    // A camera framed from the data alone fails only on the data's extent.
    if (o.eye || o.ortho || o.fov) throw UsageError(err);
    throw io::InputError("render: " + s.field.path + ": the field cannot be framed (" + err + ")");
  }
  return d;
}

}  // namespace

int cmdRender(int argc, const char** argv) {
  const RenderOptions o = parse(argc, argv);
  validate(o);
  const auto t0 = Clock::now();
  Scene scene = loadScene(o.input, o.field.read);
  const double loadMs = msSince(t0);
  reportLoad(scene.field, "render");
  std::vector<io::MeshData> meshes = o.mesh.read(o.input, "render");

  const auto t1 = Clock::now();
  tensor::GlyphSet glyphs =
      tensor::buildGlyphs(scene.field.positions, scene.field.tensors, scene.field.ids, 0, o.field.glyph);
  checkDrawable(glyphs, scene.field.path);
  const double buildMs = msSince(t1);
  std::optional<render::UnderlayVolume> underlay;
  if (o.slices.any()) underlay = loadUnderlay(o.slices, scene.field);
  // Each stage frees what the next no longer needs, so that peak memory holds
  // at most two copies of the glyphs (here the records and the GL buffer).
  // --pick keeps the samples instead (app/pick.h): 40 bytes a tensor.
  std::optional<PickTable> pickTable;
  if (!o.pick.pixels.empty()) pickTable.emplace(scene.field, o.field.glyph);
  scene.field.releaseSamples();
  render::FrameParams params;
  const tensor::ResolvedScale sized =
      tensor::resolveScale(o.field.scaleParams(), tensor::sampleMagnitudes(glyphs, scene.field.sampleSpacing));
  params.scale = sized.scale;
  params.sizing = sized.mapping;
  params.faMin = o.faMin.value_or(scene.preferredFaMin.value_or(0.0));
  params.color = *colorModeNamed(o.color);
  params.glyph = *glyphKindNamed(o.glyph);
  params.gamma = o.gamma;
  params.march = {o.maxIterations, o.epsilon};
  params.iterationStats = o.stats;
  params.tessellation = o.tessellate;
  params.background = o.background;
  params.legend = o.legend.params;
  params.ao = o.effects.ao;
  params.outline = o.effects.outline;
  params.shadow = o.shadow.params;
  if (scene.preferredLook) o.look.apply(*scene.preferredLook, params, o.height);

  auto [lo, hi] = tensor::glyphBoxWC(glyphs, params.scale, params.sizing);
  if (underlay) {
    for (const std::string& w : underlayWarnings(o.slices, *underlay, lo, hi))
      std::fprintf(stderr, "tensorglyph render: --underlay %s: %s\n", underlay->name.c_str(), w.c_str());
    // The camera's depth range holds the planes too (framing stays on the glyphs).
    const auto [ulo, uhi] = underlay->boundsWC();
    growDepthRange(lo, hi, ulo, uhi);
  }
  // The GPU works in single precision: a box beyond FLT_MAX draws nothing.
  const double extent = std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x), std::abs(hi.y),
                                  std::abs(hi.z)});
  if (!(extent <= double(FLT_MAX)))
    throw io::InputError("render: " + scene.field.path + ": the glyphs extend beyond the floating-point range (scale " +
                         std::to_string(params.scale) + ")");
  const tensor::FramingBox frame = tensor::framingBox(glyphs, !scene.field.grid, sized.typicalRadiusWC);
  glm::dvec3 meshLo(INFINITY), meshHi(-INFINITY);
  growByMeshes(meshes, meshLo, meshHi);
  growDepthRange(lo, hi, meshLo, meshHi);
  const render::Camera cam = render::makeCamera(chooseCamera(o, scene, frame), o.width, o.height, lo, hi);

  auto ctx = createContext(o.backend, o.width, o.height);
  const gl::ShaderLibrary lib;
  render::GlyphRenderer renderer(ctx->api(), lib, render::makeLegendPass);
  render::GBuffer target(ctx->api(), o.width, o.height);
  if (underlay) addSlicePlanes(renderer, ctx->api(), lib, o.slices, std::move(*underlay), glyphs.maxAbsEigenvalue);
  const auto t2 = Clock::now();
  renderer.upload(glyphs);
  addMeshes(renderer, ctx->api(), lib, meshes, o.mesh.params);
  meshes.clear();
  ctx->api().Finish();
  const double uploadMs = msSince(t2);
  const std::size_t glyphCount = glyphs.glyphs.size();
  glyphs.glyphs = {};
  const auto t3 = Clock::now();
  renderer.render(cam, params, target);
  ctx->api().Finish();
  const double frameMs = msSince(t3);
  if (const auto* legend = static_cast<const render::LegendPass*>(renderer.legendPass())) {
    const render::LegendRect& r = legend->layout().panel;
    if (r.x1 > float(o.width) || r.y1 > float(o.height))
      std::fprintf(stderr,
                   "tensorglyph render: --legend: the legend needs %.0f x %.0f pixels and is cut off by the %d x %d "
                   "image; use a larger --size, or --legend-text-scale 1\n",
                   double(r.x1 - r.x0), double(r.y1 - r.y0), o.width, o.height);
  }
  std::vector<double> times, cpuTimes;
  for (int k = 0; k < o.repeat; ++k) {
    const auto tk = Clock::now();
    const double cpuK = processCpuMs();
    renderer.render(cam, params, target);
    ctx->api().Finish();
    times.push_back(msSince(tk));
    cpuTimes.push_back(processCpuMs() - cpuK);
  }
  if (o.stats) {
    const render::IterationStats st = renderer.iterationStats();
    std::fprintf(stderr, "tensorglyph render: Newton iterations: mean %.2f, max %u over %llu pixels\n", st.mean,
                 st.max, static_cast<unsigned long long>(st.pixels));
  }
  const std::uint64_t drawn = renderer.drawnGlyphs();
  const render::FrameImage img = renderer.readback(
      cam, target, io::writesGeometryChannels(o.output) ? render::Channels::All : render::Channels::Color);
  std::vector<std::string> picks;
  for (const PixelIJ& px : o.pick.pixels)
    picks.push_back(pickJson(pickPixel(ctx->api(), renderer, cam, target, *pickTable, px)));
  io::writeImage(img, o.output);
  // After the image: a failed write prints no picks.
  for (const std::string& line : picks) std::printf("%s\n", line.c_str());
  if (o.verbose || o.repeat > 0) {
    std::sort(times.begin(), times.end());
    std::fprintf(stderr,
                 "tensorglyph render: %zu glyphs, %dx%d, %s (%s)\n"
                 "  load %.1f ms, eigen %.1f ms, upload %.1f ms, first frame %.1f ms",
                 glyphCount, o.width, o.height, ctx->backendName(), ctx->describe().c_str(), loadMs,
                 buildMs, uploadMs, frameMs);
    std::sort(cpuTimes.begin(), cpuTimes.end());
    if (!times.empty())
      std::fprintf(stderr, ", median of %zu frames %.2f ms (CPU, all threads: %.2f ms)", times.size(),
                   times[times.size() / 2], cpuTimes[cpuTimes.size() / 2]);
    std::fprintf(stderr, "\n  %llu glyphs drawn (after FA and frustum culling), scale %.6g, fa-min %.3g, peak RSS %.1f MiB\n",
                 static_cast<unsigned long long>(drawn), params.scale, params.faMin,
                 double(peakRssBytes()) / (1024.0 * 1024.0));
    const std::string framing = o.eye ? "--eye given; it looks by default at the centre of " + frame.why
                                : scene.preferredCamera ? std::string("the built-in scene's own view")
                                                        : frame.why;
    std::fprintf(stderr, "  size: %s\n  framing: %s\n", sized.why.c_str(), framing.c_str());
    if (params.ao.enabled)
      std::fprintf(stderr, "  ambient occlusion: radius %.6g (%s), strength %.3g, %d samples\n",
                   renderer.aoRadiusWC(params), params.ao.radius > 0 ? "--ao-radius" : "auto",
                   params.ao.strength, params.ao.samples);
    if (params.outline.enabled)
      std::fprintf(stderr, "  outlines: width %.3g px, crease %.3g deg\n", params.outline.width, params.outline.creaseDeg);
    for (const auto& item : renderer.context())
      if (const auto* m = dynamic_cast<const render::MeshItem*>(item.get()))
        std::fprintf(stderr, "  %s: %zu triangles, %s, %.1f MiB of GPU memory\n", m->label().c_str(), m->triangleCount(),
                     render::meshModeName(m->params().mode), double(m->gpuBytes()) / (1024.0 * 1024.0));
    if (params.shadow.enabled)
      std::fprintf(stderr, "  shadows: map %d x %d texels, penumbra %.3g, %.1f MiB of GPU memory in all\n",
                   renderer.shadowMapSize(), renderer.shadowMapSize(), double(params.shadow.penumbra),
                   double(renderer.gpuBytes()) / (1024.0 * 1024.0));
  }
  return 0;
}

}  // namespace tg::app
