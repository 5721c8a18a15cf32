#include "app/render_options.h"

#include <span>
#include <vector>

#include "app/cli_common.h"
#include "app/field_flags.h"
#include "app/frame_size.h"
#include "app/names.h"
#include "app/output_check.h"
#include "io/image_writer.h"
#include "io/readers.h"
#include "render/tessellated.h"

namespace tg::app {

void addRenderOptions(OptionTable& ap, RenderOptions& o) {
  using Args = OptionArgs;
  ap.arg("-o OUT").commandLineOnly().help("output image: .png (8-bit RGBA), .exr (float RGBA Z N id), other OIIO formats")
      .action([&](Args a) { o.output = a[1]; });
  addViewOptions(ap, o);
  ap.arg("--tessellate R").help("draw the tessellated baseline instead: an R x R superquadric mesh per glyph, "
                                 "as VTK's vtkTensorGlyph (4..64; needs --glyph superquadric)")
      .action([&](Args a) { o.tessellate = parseIntIn("--tessellate", a[1], 0, render::TessellatedGlyphs::kMaxResolution); });
  ap.arg("--backend NAME").reloads().help("osmesa (default), egl, glfw or auto").action([&](Args a) { o.backend = a[1]; });
  o.pick.addTo(ap);
  ap.arg("--repeat N").commandLineOnly().help("render N more frames and report the median frame time").action([&](Args a) {
    o.repeat = parseIntIn("--repeat", a[1], 0, 10000);
  });
  ap.arg("--quiet").commandLineOnly().help("no progress line on a terminal's stderr").action([&](Args) { o.quiet = true; });
  ap.arg("--verbose").commandLineOnly().help("report timings and memory on stderr").action([&](Args) { o.verbose = true; });
}

void addViewOptions(OptionTable& ap, RenderOptions& o) {
  using Args = OptionArgs;
  auto rest = [](Args a) { return std::span<const char* const>(a.data() + 1, a.size() - 1); };
  addInputArg(ap, o.input);
  const std::string size = "image size in pixels (default " + std::to_string(o.width) + " " + std::to_string(o.height) + ")";
  ap.arg("--size W H").reloads().help(size).action([&](Args a) {
    o.width = parseIntIn("--size", a[1], 1, kMaxFrameSide);
    o.height = parseIntIn("--size", a[2], 1, kMaxFrameSide);
  });
  ap.arg("--glyph KIND").help("ellipsoid (default; the built-in scene: superquadric), superquadric, "
                                  "or Teem's cylinder or box").action([&](Args a) {
    o.glyph = a[1];
    o.look.glyphGiven = true;
  });
  ap.arg("--iterations N").help("superquadric Newton iterations at most (default 10)").action([&](Args a) {
    o.maxIterations = parseIntIn("--iterations", a[1], 1, 1000);
    if (o.marchFlag.empty()) o.marchFlag = "--iterations";
  });
  ap.arg("--epsilon E").help("superquadric hit tolerance, relative to glyph size (default 1e-4)")
      .action([&](Args a) {
        o.epsilon = parseDouble("--epsilon", a[1]);
        if (o.marchFlag.empty()) o.marchFlag = "--epsilon";
      });
  ap.arg("--stats").help("report Newton iteration statistics on stderr").action([&](Args) { o.stats = true; });
  ap.arg("--gamma G").help("superquadric sharpness (Kindlmann 2004), 0..10000 (default " + formatNumber(o.gamma) + ")").action([&](Args a) {
    o.gamma = parseDouble("--gamma", a[1]);
    if (o.marchFlag.empty()) o.marchFlag = "--gamma";
  });
  ap.arg("--fa-min F").help("hide glyphs with FA below F").action([&](Args a) { o.faMin = parseDoubleIn("--fa-min", a[1], 0.0, 1.0); });
  ap.arg("--eye X Y Z").help("camera position (WC)").action([&](Args a) { o.eye = parseVec3("--eye", rest(a)); });
  ap.arg("--look-at X Y Z").help("point the camera looks at (WC)").action([&](Args a) {
    o.lookAt = parseVec3("--look-at", rest(a));
  });
  ap.arg("--up X Y Z").help("camera up vector (WC)").action([&](Args a) { o.up = parseVec3("--up", rest(a)); });
  ap.arg("--fov DEG").help("perspective, vertical field of view (default 30)").action([&](Args a) {
    o.fov = parseDouble("--fov", a[1]);
  });
  ap.arg("--ortho HEIGHT").help("orthographic, view height in world units").action([&](Args a) {
    o.ortho = parseDouble("--ortho", a[1]);
  });
  ap.arg("--color MODE").help("dec, fa, md, cl, cp or sign (normal stress: orange tension, blue compression)").action([&](Args a) { o.color = a[1]; });
  ap.arg("--background R G B A").help("background colour, 0..1 (default 0.08 0.08 0.1 1)").action([&](Args a) {
    for (int k = 0; k < 4; ++k) o.background[k] = float(parseDoubleIn("--background", a[1 + k], 0.0, 1.0));
  });
  o.addSceneFlags(ap);
}

// Every parameter is checked before anything is loaded or created.
void validateRenderOptions(const RenderOptions& o, bool toFile) {
  if (toFile && o.output.empty()) throw UsageError("-o OUT is required");
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
  // The kind table says which kinds the march's options (gamma among them) apply to.
  const bool marches = render::glyphKind(o.look.glyphGiven || !o.input.empty() ? *glyphKindNamed(o.glyph)
                                                                               : SceneLook{}.glyph).gamma;
  if (toFile && !o.marchFlag.empty() && !marches)
    throw UsageError(o.marchFlag + " applies to --glyph superquadric only; this render draws " + o.glyph + " glyphs");
  if (o.maxIterations < 1 || o.maxIterations > 1000) throw UsageError("--iterations must be within 1..1000");
  if (!(o.epsilon >= 1e-9 && o.epsilon <= 0.5)) throw UsageError("--epsilon must be within 1e-9..0.5");
  o.validateSceneFlags(o.input);
  if (o.fov && o.ortho) throw UsageError("--fov and --ortho exclude each other");
  // Checked here, not only by validateCamera: a framed camera's distance
  // divides by tan(fov / 2), so --fov 0 failed as "camera vectors must be finite".
  if (o.fov && !(*o.fov > 0.0 && *o.fov < 180.0)) throw UsageError("--fov must be in (0, 180) degrees");
  if ((o.lookAt || o.up) && !o.eye) throw UsageError("--look-at and --up need --eye");
  if (!colorModeNamed(o.color))
    throw UsageError("--color: unknown mode \"" + o.color + "\"; choose " + kColorModeNames);
  if (o.repeat < 0 || o.repeat > 10000) throw UsageError("--repeat must be within 0..10000");
  checkBackend(o.backend);
  if (toFile && !io::canWriteImage(o.output))
    throw UsageError("-o: no image format for \"" + o.output + "\"");
  std::vector<NamedPath> inputs = {{"INPUT", o.input}, {"--mask", o.field.read.selection.maskPath},
                                   {"--underlay", o.slices.fromField() ? "" : o.slices.underlay}};
  for (const NamedPath& m : o.mesh.inputs()) inputs.push_back(m);
  if (toFile) refuseOutputsOverInputs({{"-o", o.output}}, inputs);
}

render::FrameParams frameParams(const RenderOptions& o, const Scene& s, const tensor::ResolvedScale& sized) {
  render::FrameParams p;
  p.scale = sized.scale;
  p.sizing = sized.mapping;
  p.faMin = o.faMin.value_or(s.preferredFaMin.value_or(0.0));
  p.color = *colorModeNamed(o.color);
  p.glyph = *glyphKindNamed(o.glyph);
  p.gamma = o.gamma;
  p.march = {o.maxIterations, o.epsilon};
  p.iterationStats = o.stats;
  p.tessellation = o.tessellate;
  p.background = o.background;
  p.legend = o.legend.params;
  p.ao = o.effects.ao;
  p.outline = o.effects.outline;
  p.shadow = o.shadow.params;
  if (s.preferredLook) o.look.apply(*s.preferredLook, p, o.height);
  return p;
}

// One singular glyph must not shrink the view: hence the samples' box.
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

}  // namespace tg::app
