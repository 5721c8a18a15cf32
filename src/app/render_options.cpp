#include "app/render_options.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <span>

#include <glm/geometric.hpp>
#include <vector>

#include "app/cli_common.h"
#include "app/field_flags.h"
#include "app/scale/frame_size.h"
#include "app/names.h"
#include "app/scale/option_ranges.h"
#include "app/output_check.h"
#include "io/core/image_writer.h"
#include "io/core/readers.h"
#include "render/color_scalar.h"
#include "render/glyph_path.h"
#include "render/tessellated.h"
#include "view/anatomy.h"

namespace tg::app {

void addRenderOptions(OptionTable& ap, RenderOptions& o) {
  using Args = OptionArgs;
  ap.setGroup("output");
  ap.arg("-o OUT").commandLineOnly().help("output image: .png (8-bit RGBA), .exr (float RGBA Z N id), other OIIO formats")
      .action([&](Args a) { o.output = a[1]; });
  addViewOptions(ap, o);
  ap.setGroup("glyphs");
  ap.arg("--tessellate R").help("draw the tessellated baseline instead: an R x R superquadric mesh per glyph, "
                                 "as VTK's vtkTensorGlyph (needs --glyph superquadric)")
      .range(ranges::kTessellation).action([&](Args a) { o.tessellate = int(parseInt(a[0], a[1])); });
  ap.setGroup("output");
  ap.arg("--backend NAME").reloads().help("osmesa (default), egl, glfw or auto").oneOf(kBackendNames).action([&](Args a) { o.backend = a[1]; });
  o.pick.addTo(ap);
  ap.arg("--repeat N").commandLineOnly().help("render N more frames and report the median frame time")
      .range(ranges::kRepeat).action([&](Args a) { o.repeat = int(parseInt(a[0], a[1])); });
  ap.arg("-q,--quiet").commandLineOnly().help("no progress line on a terminal's stderr").action([&](Args) { o.quiet = true; });
  ap.arg("--verbose").commandLineOnly().help("report timings and memory on stderr").action([&](Args) { o.verbose = true; });
}

void addViewOptions(OptionTable& ap, RenderOptions& o) {
  using Args = OptionArgs;
  auto rest = [](Args a) { return std::span<const char* const>(a.data() + 1, a.size() - 1); };
  const std::string group = ap.groupDefault();
  addInputArg(ap, o.input);
  ap.setGroup("output");
  ap.arg("--size W H").reloads().help("image size in pixels").range({1, kMaxFrameSide, true})
      .byDefault(formatSize(o.width, o.height)).action([&](Args a) {
    o.width = int(parseInt(a[0], a[1]));
    o.height = int(parseInt(a[0], a[2]));
  });
  ap.arg("--samples N").help("anti-aliasing: samples per pixel where a silhouette crosses it (the id changes "
                              "in its 3x3 neighbourhood), each cast against the glyphs around it and coloured as "
                              "the nearest pixel showing its surface (blobs: a whole frame per sample); id, depth "
                              "and normal channels stay the pixel centre's")
      .range(ranges::kSamples).byDefault(std::to_string(o.samples))
      .action([&](Args a) { o.samples = int(parseInt(a[0], a[1])); });
  ap.setGroup("glyphs");
  ap.arg("--pipeline NAME").reloads().help("how glyphs are drawn: raster (default; a ray-cast sprite per glyph), "
                                            "cpu (tiles cast on every core; every kind, and the only path for blobs), "
                                            "compute (compute shaders cast per screen tile into a visibility buffer; "
                                            "for GPUs whose graphics stages are a small part of the chip) or "
                                            "auto (the path predicted fastest for this scene from a calibration "
                                            "measured once per renderer and kept in the cache; --verbose says why)")
      .oneOf(pipelineNames())
      .action([&](Args a) {
        o.pipeline = a[1];
        o.pipelineGiven = true;
      });
  ap.arg("--glyph KIND").help("ellipsoid (default; the built-in scene: superquadric), superquadric, "
                                  "Teem's cylinder or box, or blob (Blinn's blobby surface of all the glyphs' "
                                  "bumps; cast on the cpu path)").oneOf(kGlyphKindNames).action([&](Args a) {
    o.glyph = a[1];
    o.look.glyphGiven = true;
  });
  ap.arg("--iterations N").help("superquadric Newton iterations at most").range(ranges::kIterations)
      .byDefault(std::to_string(o.maxIterations))
      .action([&](Args a) {
    o.maxIterations = int(parseInt(a[0], a[1]));
    if (o.marchFlag.empty()) o.marchFlag = "--iterations";
  });
  ap.arg("--epsilon E").help("superquadric hit tolerance, relative to glyph size")
      .range(ranges::kEpsilon).byDefault(formatNumber(o.epsilon)).action([&](Args a) {
        o.epsilon = parseDouble("--epsilon", a[1]);
        if (o.marchFlag.empty()) o.marchFlag = "--epsilon";
      });
  ap.arg("--stats").help("report Newton iteration statistics on stderr").action([&](Args) {
    o.stats = true;
    if (o.marchFlag.empty()) o.marchFlag = "--stats";
  });
  ap.arg("--gamma G").help("superquadric sharpness (Kindlmann 2004)")
      .range(ranges::kGamma).byDefault(formatNumber(o.gamma)).action([&](Args a) {
    o.gamma = parseDouble("--gamma", a[1]);
    if (o.marchFlag.empty()) o.marchFlag = "--gamma";
  });
  const render::BlobParams blob;
  auto blobFlag = [&o](const char* flag) {
    if (o.blobFlag.empty()) o.blobFlag = flag;
  };
  ap.arg("--blob-threshold T").help("blob: the surface where the bumps' sum is T; at 1 a lone glyph's blob is the glyph")
      .range(ranges::kBlobThreshold).byDefault(formatNumber(blob.threshold)).action([&, blobFlag](Args a) {
        o.blob.threshold = parseDouble(a[0], a[1]);
        blobFlag("--blob-threshold");
      });
  ap.arg("--blobbiness B").help("blob: Blinn's blobbiness B < 0 of each bump exp(B (g^2 - 1)); nearer 0, "
                                "neighbours blend more")
      .range(ranges::kBlobbiness).byDefault(formatNumber(blob.blobbiness)).action([&, blobFlag](Args a) {
        o.blob.blobbiness = parseDouble(a[0], a[1]);
        blobFlag("--blobbiness");
      });
  ap.arg("--blob-cutoff C").help("blob: a bump ends where it falls to C times the threshold; the sum is then "
                                 "within K C T / (1 - C) of the untruncated one where K bumps overlap")
      .range(ranges::kBlobCutoff).byDefault(formatNumber(blob.cutoff)).action([&, blobFlag](Args a) {
        o.blob.cutoff = parseDouble(a[0], a[1]);
        blobFlag("--blob-cutoff");
      });
  ap.arg("--blob-steps N").help("blob: samples of the sum along a ray between a bump's entry, peak and exit")
      .range(ranges::kBlobSteps).byDefault(std::to_string(blob.steps)).action([&, blobFlag](Args a) {
        o.blob.steps = int(parseInt(a[0], a[1]));
        blobFlag("--blob-steps");
      });
  ap.setGroup("input and selection");
  ap.arg("--fa-min F").help("hide glyphs with FA below F").range(ranges::kUnit).action([&](Args a) {
    o.faMin = parseDouble(a[0], a[1]);
  });
  ap.setGroup("camera and views");
  ap.arg("--eye X Y Z").help("camera position (WC)").range(ranges::kAnyFloat).action([&](Args a) {
    o.eye = parseVec3("--eye", rest(a));
  });
  ap.arg("--look-at X Y Z").help("point the camera looks at (WC)").range(ranges::kAnyFloat).action([&](Args a) {
    o.lookAt = parseVec3("--look-at", rest(a));
  });
  ap.arg("--up X Y Z").help("camera up vector (WC)").range(ranges::kAnyFloat).action([&](Args a) {
    o.up = parseVec3("--up", rest(a));
  });
  ap.arg("--fov DEG").help("perspective, vertical field of view").range(ranges::kFovDeg)
      .byDefault(formatNumber(render::CameraDesc{}.fovYDeg)).action([&](Args a) {
    o.fov = parseDouble("--fov", a[1]);
  });
  ap.arg("--view NAME").help(std::string("look from an anatomical side, up anatomical, framing the field: ") +
                             render::kViewNames + " (in world terms: RAS+, as every reader converts; x, y, z for "
                             "fields without an anatomical space); default: a --slice seen face-on, else axial")
      .oneOf(render::kViewNames)
      .action([&](Args a) {
        if (!render::namedView(a[1], false))
          throw UsageError(std::string("--view: unknown view \"") + a[1] + "\"; choose " + render::kViewNames);
        o.view = a[1];
      });
  ap.arg("--radiological").help("axial and coronal views show the patient's right on the image's left, as if "
                                "seen from the feet or facing the patient (Slicer's and mrview's default)")
      .action([&](Args) {
        if (o.radiological == false) throw UsageError("--radiological and --neurological exclude each other");
        o.radiological = true;
      });
  ap.arg("--neurological").help("axial and coronal views show the patient's right on the image's right, as if "
                                "seen from above or from behind (the default; FSLeyes' default)")
      .action([&](Args) {
        if (o.radiological == true) throw UsageError("--radiological and --neurological exclude each other");
        o.radiological = false;
      });
  ap.arg("--orientation-letters MODE").help("R/L, A/P, S/I on the image's edges: auto (default: on where the field's "
                                            "space is anatomical, NIfTI, MRtrix and NRRD with a space; off for FEM "
                                            "meshes and unknown spaces), on or off")
      .oneOf("auto, on or off")
      .action([&](Args a) {
        const std::string m = a[1];
        if (m != "auto" && m != "on" && m != "off")
          throw UsageError("--orientation-letters: unknown mode \"" + m + "\"; choose auto, on or off");
        o.orientationLetters = m;
      });
  ap.arg("--ortho HEIGHT").help("orthographic, view height in world units").range(ranges::kPositiveFloat)
      .action([&](Args a) { o.ortho = parseDouble("--ortho", a[1]); });
  ap.setGroup("colour");
  ap.arg("--color MODE").help("dec (default), decfa (|e1| x FA, dark where isotropic), fa, md, cl, cp; stress: "
                               "sign (normal stress, saturated at the window's largest |value|: orange tension, blue "
                               "compression), vonmises, tresca (s1 - s3), pressure (-trace/3), s1, s2, s3 (principal "
                               "values, descending), trace; array (with --color-array)")
      .oneOf(kColorModeNames)
      .action([&](Args a) {
        o.color = a[1];
        o.colorGiven = true;
        o.look.colorGiven = true;
      });
  ap.arg("--color-array NAME").reloads().help("colour by a scalar given beside the tensors: a VTK input's point "
                                               "array NAME, or a volume input's scalar volume file NAME on its grid "
                                               "(implies --color array)")
      .action([&](Args a) {
        o.field.read.colorArray = a[1];
        if (!o.colorGiven) o.color = "array";
        o.look.colorGiven = true;  // a stress field's default sign colour must not replace it
      });
  ap.arg("--colormap NAME").help("the scalar's map: viridis, gray or diverging (blue, white at 0, orange); default "
                                 "diverging for pressure, s1, s2, s3 and trace, else viridis")
      .oneOf(render::kColormapNames)
      .action([&](Args a) { o.colormap = a[1]; });
  ap.arg("--color-range LO HI").help("the colour window: values at the map's ends, clamped beyond (sign: saturated at "
                                     "max(|LO|, |HI|)); default the whole field's range")
      .range(ranges::kAnyFloat).action([&](Args a) {
        o.colorRange = glm::dvec2(parseDouble(a[0], a[1]), parseDouble(a[0], a[2]));
      });
  ap.arg("--background R G B A").help("background colour").range(ranges::kUnit)
      .byDefault(formatNumber(o.background.r) + " " + formatNumber(o.background.g) + " " +
                 formatNumber(o.background.b) + " " + formatNumber(o.background.a))
      .action([&](Args a) {
        for (int k = 0; k < 4; ++k) o.background[k] = float(parseDouble(a[0], a[1 + k]));
      });
  o.addSceneFlags(ap);
  ap.setGroup(group);
}

void validateColorOptions(const RenderOptions& o) {
  const auto mode = colorModeNamed(o.color);
  if (!mode) throw UsageError("--color: unknown mode \"" + o.color + "\"; choose " + kColorModeNames);
  if (*mode == render::ColorMode::Array && o.field.read.colorArray.empty() && !o.colorValuesGiven)
    throw UsageError("--color array needs --color-array NAME, the values to colour by");
  if (!o.colormap.empty()) {
    if (!render::colormapNamed(o.colormap))
      throw UsageError("--colormap: unknown map \"" + o.colormap + "\"; choose " + render::kColormapNames);
    if (!render::colorIsScalar(*mode))
      throw UsageError("--colormap: --color " + o.color + " has colours of its own; a map applies to a scalar (" +
                       "fa, md, cl, cp, vonmises, tresca, pressure, s1, s2, s3, trace, array)");
  }
  if (o.colorRange) {
    if (!(o.colorRange->x < o.colorRange->y))
      throw UsageError("--color-range: LO " + formatNumber(o.colorRange->x) + " must be below HI " +
                       formatNumber(o.colorRange->y));
    // Without --color the scene's look may still choose a scalar (a stress
    // field's sign colour): frameParams refuses once the look is known.
    if (o.colorGiven && (*mode == render::ColorMode::DEC || *mode == render::ColorMode::DecFA))
      throw UsageError("--color-range: --color " + o.color + " maps directions, no scalar");
  }
}

namespace {

// The options that need a kind of glyph: the cpu path casts ellipsoids and
// superquadrics, the march's options (gamma among them) apply where the kind
// table says.
// "ellipsoid, superquadric and blob": the kinds a path draws, from the kind table.
std::string kindsDrawnBy(std::string_view path) {
  std::vector<std::string_view> names;
  for (const render::GlyphKindInfo& k : render::glyphKinds())
    if (render::pathDraws(path, k.kind)) names.push_back(k.name);
  std::string s;
  for (std::size_t k = 0; k < names.size(); ++k)
    s.append(k == 0 ? "" : k + 1 == names.size() ? " and " : ", ").append(names[k]);
  return s;
}

void checkKindOptions(const RenderOptions& o, render::GlyphKind kind, bool toFile) {
  const std::string path = glyphPathFor(o, kind), name(render::glyphKind(kind).name);
  if ((path == "cpu" || path == "compute") && o.tessellate != 0)
    throw UsageError("--pipeline " + path + " casts rays; --tessellate draws a mesh (use --pipeline raster)");
  if (!pipelineDraws(path, kind)) {
    std::string others;
    for (const std::string_view p : render::kGlyphPathNames)
      if (p != path && pipelineDraws(p, kind)) others += (others.empty() ? "" : " or ") + std::string(p);
    throw UsageError("--pipeline " + path + " draws " + kindsDrawnBy(path) + " glyphs only; this render draws " + name +
                     " glyphs" + (kind == render::GlyphKind::Blob ? " (each blob pixel needs every bump its ray meets)" : "") +
                     ": use --pipeline " + others + ", or leave --pipeline out");
  }
  const bool blob = kind == render::GlyphKind::Blob;
  if (toFile && !o.marchFlag.empty() && (!render::glyphKind(kind).gamma || (blob && o.marchFlag != "--gamma")))
    throw UsageError(o.marchFlag + " applies to --glyph superquadric" + (o.marchFlag == "--gamma" ? " and blob" : "") +
                     " only; this render draws " + name + " glyphs");
  if (toFile && !o.blobFlag.empty() && !blob)
    throw UsageError(o.blobFlag + " applies to --glyph blob only; this render draws " + name + " glyphs");
  if (blob) {
    // The bump's peak exp(-B) must rise above the cutoff, or nothing adds;
    // its reach sqrt(1 + ln(C T) / B) glyph radii sets what every pixel
    // pays, which grows with its cube.
    const render::BlobParams& b = o.blob;
    constexpr double kMaxReach = 8.0;
    const double reach = render::blobBoundGauge(b);
    if (reach > kMaxReach)
      throw UsageError("--blobbiness " + formatNumber(b.blobbiness) + " with --blob-cutoff " + formatNumber(b.cutoff) +
                       " and --blob-threshold " + formatNumber(b.threshold) + ": each bump would reach " +
                       formatNumber(reach) + " glyph radii (at most " + formatNumber(kMaxReach) +
                       "); give a larger --blob-cutoff or a --blobbiness further from 0");
    if (!(b.cutoff * b.threshold < std::exp(-b.blobbiness)))
      throw UsageError("--blob-cutoff " + formatNumber(b.cutoff) + " x --blob-threshold " + formatNumber(b.threshold) +
                       " lies above a bump's peak exp(-B) = " + formatNumber(std::exp(-b.blobbiness)) +
                       " (--blobbiness " + formatNumber(b.blobbiness) + "): no bump would add anything");
  }
}

}  // namespace

std::string pipelineNames() { return render::glyphPathNames() + " or " + std::string(kAutoPipeline); }

bool pipelineDraws(std::string_view path, render::GlyphKind kind) {
  if (path != kAutoPipeline) return render::pathDraws(path, kind);
  return std::any_of(std::begin(render::kGlyphPathNames), std::end(render::kGlyphPathNames),
                     [&](std::string_view p) { return render::pathDraws(p, kind); });
}

std::string glyphPathFor(const RenderOptions& o, render::GlyphKind kind) {
  if (o.pipelineGiven) return o.pipeline;
  for (const std::string_view path : render::kGlyphPathNames)
    if (render::pathDraws(path, kind)) return std::string(path);
  return o.pipeline;
}

std::string blobThresholdHint(const render::BlobParams& b, const char* threshold, const char* blobbiness) {
  const double peak = std::exp(-b.blobbiness);
  if (b.threshold < peak) return "";
  return std::string(threshold) + " " + formatNumber(b.threshold) + " is at or above a lone bump's peak exp(-B) = " +
         formatNumber(peak) + " (" + blobbiness + " " + formatNumber(b.blobbiness) +
         "): only where bumps overlap enough does a surface show, and the image may show none";
}

std::string sessionGlyphPath(const RenderOptions& o) {
  return glyphPathFor(o, o.look.glyphGiven ? *glyphKindNamed(o.glyph) : render::GlyphKind::Ellipsoid);
}

// Every parameter is checked before anything is loaded or created.
void validateRenderOptions(const RenderOptions& o, bool toFile) {
  if (toFile && o.output.empty()) throw UsageError("-o OUT is required");
  checkFrameSize("--size", o.width, o.height);
  o.pick.validate(o.width, o.height);
  if (!glyphKindNamed(o.glyph))
    throw UsageError("--glyph: unknown kind \"" + o.glyph + "\"; choose " + kGlyphKindNames);
  if (o.tessellate != 0 && o.glyph != "superquadric") throw UsageError("--tessellate needs --glyph superquadric");
  if (o.tessellate != 0 && o.stats) throw UsageError("--stats counts the ray march; --tessellate has none");
  if (o.pipeline != kAutoPipeline &&
      std::find(std::begin(render::kGlyphPathNames), std::end(render::kGlyphPathNames), o.pipeline) ==
          std::end(render::kGlyphPathNames))
    throw UsageError("--pipeline: unknown glyph path \"" + o.pipeline + "\"; choose " + pipelineNames());
  const render::GlyphKind kind = o.look.glyphGiven || !o.input.empty() ? *glyphKindNamed(o.glyph) : SceneLook{}.glyph;
  // A file's kind without --glyph may still change with its look (a stress
  // field's superquadrics): frameParams checks those once the look is known.
  const bool kindKnown = o.look.glyphGiven || o.input.empty();
  if (kindKnown) checkKindOptions(o, kind, toFile);
  o.validateSceneFlags(o.input);
  if (toFile) o.mesh.checkModeParameters();
  if (o.fov && o.ortho) throw UsageError("--fov and --ortho exclude each other");
  if ((o.lookAt || o.up) && !o.eye) throw UsageError("--look-at and --up need --eye");
  validateColorOptions(o);
  if (!o.view.empty() && o.eye) throw UsageError("--view and --eye exclude each other");
  if (o.radiological && o.eye)
    throw UsageError(std::string(*o.radiological ? "--radiological" : "--neurological") +
                     " chooses the anatomical views; with --eye the camera is as given");
  checkBackend(o.backend);
  if (toFile && !io::canWriteImage(o.output))
    throw UsageError("-o: no image format for \"" + o.output + "\"");
  if (toFile) refuseOutputsOverInputs({{"-o", o.output}}, sceneInputs(o.input, o));
}

render::FrameParams frameParams(const RenderOptions& o, const Scene& s, const tensor::ResolvedScale& sized) {
  // The glyphs vanished without a word beyond about 1e10 world units
  // (--scale 1e14 on a DTI field): the shaders' single-precision ray
  // casting. The bound keeps a margin below what was seen to draw (7e8).
  constexpr double kMaxRadiusWC = 1e9;
  if (o.field.scale && !(sized.typicalRadiusWC <= kMaxRadiusWC))
    throw UsageError("--scale " + formatNumber(*o.field.scale) + ": the typical glyph would be " +
                     formatNumber(2 * sized.typicalRadiusWC) + " world units across, beyond what single precision " +
                     "draws (" + formatNumber(2 * kMaxRadiusWC) + "); give a smaller --scale");
  // log: lambda0 ln(1 + m / lambda0) in single precision is 0 where m / lambda0
  // is below its step (about 1e-7); the typical glyph's m / lambda0 is about
  // its radius over scale x lambda0.
  const tensor::SizeMapping& m = sized.mapping;
  if (o.field.sizing.lambda0 && m.magnitude == tensor::Magnitude::Log &&
      !(sized.typicalRadiusWC >= 1e-6 * sized.scale * m.lambda0))
    throw UsageError("--lambda0 " + formatNumber(m.lambda0) + ": the typical glyph's |eigenvalue| is below a millionth " +
                     "of it, which the logarithm in single precision draws as 0; give --lambda0 " +
                     formatNumber(1e6 * sized.typicalRadiusWC / sized.scale) + " or less");
  render::FrameParams p;
  p.scale = sized.scale;
  p.sizing = sized.mapping;
  p.faMin = o.faMin.value_or(s.preferredFaMin.value_or(0.0));
  p.color = *colorModeNamed(o.color);
  if (!o.colormap.empty()) p.colormap = render::colormapNamed(o.colormap);
  p.colorWindow = o.colorRange;
  p.glyph = *glyphKindNamed(o.glyph);
  p.gamma = o.gamma;
  p.march = {o.maxIterations, o.epsilon};
  p.blob = o.blob;
  p.samples = o.samples;
  p.iterationStats = o.stats;
  p.tessellation = o.tessellate;
  p.background = o.background;
  p.legend = o.legend.params;
  // The scale bar in the file's units, where --length-units says none.
  if (p.legend.lengthUnits.empty()) p.legend.lengthUnits = s.field.lengthUnits;
  p.ao = o.effects.ao;
  p.outline = o.effects.outline;
  p.shadow = o.shadow.params;
  p.orientationLetters = o.orientationLetters == "on" ||
                         (o.orientationLetters == "auto" && render::isAnatomicalSpace(s.field.space));
  if (s.preferredLook) o.look.apply(*s.preferredLook, p, o.height);
  if (!o.look.glyphGiven && !o.input.empty()) checkKindOptions(o, p.glyph, !o.output.empty());
  if (o.colorRange && (p.color == render::ColorMode::DEC || p.color == render::ColorMode::DecFA))
    throw UsageError("--color-range: this field is coloured by " + std::string(kColorModeList[int(p.color)]) +
                     ", directions, no scalar; give --color with a scalar or sign");
  return p;
}

std::optional<render::ViewAxes> defaultViewAxes(const RenderOptions& o, const Scene& s) {
  const bool radiological = o.radiological.value_or(false);
  if (!o.view.empty()) return render::namedView(o.view, radiological);
  const std::optional<io::SliceSpec>& slice = o.field.read.selection.slice;
  if (slice && s.field.grid) {
    // Face-on: along the normal of the voxel plane the slice keeps.
    const io::GridInfo& g = *s.field.grid;
    io::GridPlacement placed;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) placed.axesWC[3 * r + c] = g.directions[3 * r + c] * g.spacing[c];
    const int a = io::resolveSlice(*slice, placed, g.dims).axis;
    auto column = [&](int c) { return glm::dvec3(g.directions[c], g.directions[3 + c], g.directions[6 + c]); };
    const glm::dvec3 normal = glm::cross(column((a + 1) % 3), column((a + 2) % 3));
    if (glm::length(normal) > 0) return render::faceOnView(normal, radiological);
  }
  if (s.preferredCamera && !o.radiological) return std::nullopt;
  return render::namedView("axial", radiological);
}

// One singular glyph must not shrink the view: hence the samples' box.
render::CameraDesc chooseCamera(const RenderOptions& o, const Scene& s, const tensor::FramingBox& frame) {
  const render::Projection proj = o.ortho ? render::Projection::Orthographic : render::Projection::Perspective;
  const double aspect = double(o.width) / o.height;
  const glm::dvec3 lo = frame.lo, hi = frame.hi;
  render::CameraDesc d = sceneCamera(s, lo, hi, proj, o.fov.value_or(30.0), aspect);
  if (const std::optional<render::ViewAxes> axes = defaultViewAxes(o, s); axes && !o.eye)
    d = render::fitBox(lo, hi, proj, o.fov.value_or(30.0), aspect, axes->towardEyeWC, axes->upWC);
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
  // Only a view the options chose is refused here; the range alone cannot
  // say it, as the bound depends on the image and the eye.
  const double smallest = render::smallestResolvedView(d, o.height);
  const bool tooSmall = o.ortho ? d.orthoHeight < smallest : o.fov && d.fovYDeg < smallest;
  if (tooSmall) {
    const std::string flag = o.ortho ? "--ortho" : "--fov";
    throw UsageError(flag + " " + formatNumber(o.ortho ? *o.ortho : *o.fov) + ": a pixel of this " +
                     std::to_string(o.height) + "-pixel-high image would be finer than single precision resolves " +
                     "at this camera; give " + flag + " " + formatNumber(smallest * 1.00001) + " or more");
  }
  return d;
}

}  // namespace tg::app
