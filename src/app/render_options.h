#pragma once
// The options of `render`, defined once: the command line (cmd_render.cpp)
// and the Python module (python/) register the same table, so that names,
// defaults and checks cannot drift.
#include <optional>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "app/scale/option_table.h"
#include "app/pick_flags.h"
#include "app/scene.h"
#include "app/scene_flags.h"
#include "view/anatomy.h"
#include "view/camera.h"
#include "render/frame_params.h"
#include "tensor/glyph_scale.h"

namespace tg::app {

struct RenderOptions : SceneFlags {
  std::string input, output, backend = "osmesa", glyph = "ellipsoid", color = "dec";
  std::string colormap;                  // --colormap; empty: the quantity's own
  std::optional<glm::dvec2> colorRange;  // --color-range LO HI
  bool colorGiven = false;               // --color itself; --color-array alone colours by the array
  bool colorValuesGiven = false;         // Python's color=array (RenderSession::setColorValues)
  PickFlags pick;
  int width = 1024, height = 768;
  double gamma = 3.0;
  std::optional<double> faMin, fov, ortho;
  std::optional<glm::dvec3> eye, lookAt, up;
  std::string view;                   // --view: a name of render::namedView
  std::optional<bool> radiological;   // --radiological, --neurological (the default)
  std::string orientationLetters = "auto";  // --orientation-letters auto|on|off
  glm::vec4 background{0.08f, 0.08f, 0.10f, 1.0f};
  int repeat = 0, tessellate = 0, maxIterations = render::MarchParams{}.maxIterations;
  double epsilon = render::MarchParams{}.epsilon;
  bool verbose = false, stats = false, quiet = false;
  // The first of --gamma, --iterations and --epsilon given: `render` refuses
  // it for glyphs that do not march (a Teem user's --gamma on a file's
  // default ellipsoids); view and Python may switch to superquadrics later.
  std::string marchFlag;
  std::string pipeline = "raster";  // the glyph path (render::makeGlyphPath)
  bool pipelineGiven = false;       // else a kind the raster path cannot draw (blob) takes the cpu path
  render::BlobParams blob;
  int samples = 1;  // --samples
  std::string blobFlag;  // the first --blob-* option given: refused for other kinds, as marchFlag
};

// --pipeline auto: the session picks the path (app/scale/pipeline_choice.h)
// once its context exists.
inline constexpr std::string_view kAutoPipeline = "auto";
// "raster, cpu, compute or auto": what --pipeline takes.
std::string pipelineNames();
// Whether --pipeline `path` can draw kind: auto where some path does.
bool pipelineDraws(std::string_view path, render::GlyphKind kind);

// The glyph path a session with options `o` draws `kind` by: --pipeline,
// or where it was not given the first path of the kind's row that draws it.
std::string glyphPathFor(const RenderOptions& o, render::GlyphKind kind);
// The path a session starts on: glyphPathFor the kind --glyph gives (a
// file's look never asks for a kind the raster path cannot draw).
std::string sessionGlyphPath(const RenderOptions& o);
// "" or why a blob frame may show nothing: a threshold at or above a lone
// bump's peak exp(-B), which only overlapping bumps can reach.
std::string blobThresholdHint(const render::BlobParams& b, const char* threshold, const char* blobbiness);


inline constexpr const char* kRenderUsage = "tensorglyph render [INPUT] -o OUT [options]";

// Registers every option of `render` on `table`, each writing into `o`.
void addRenderOptions(OptionTable& table, RenderOptions& o);
// The part `view` shares: the input, the size, the glyph and its march, the
// look, the camera, the field's selection and sizing, and the scene's
// context items. The defaults the help text gives are o's when called.
void addViewOptions(OptionTable& table, RenderOptions& o);
// --color, --colormap and --color-range: names known, LO < HI, a map only
// for a scalar (UsageError). The view script checks its colour commands so too.
void validateColorOptions(const RenderOptions& o);
// Every parameter checked before anything is loaded or created (UsageError).
// `toFile`: -o is required and checked (the command line); the Python module
// returns images instead.
void validateRenderOptions(const RenderOptions& o, bool toFile);
// The camera: the flags', else the scene's preferred view, else one that
// frames `frame` (the sample positions, not the glyphs' whole box): --view's,
// or a --slice seen face-on, or else axial (for a scene without a preferred
// view), in the convention --radiological or --neurological names.
render::CameraDesc chooseCamera(const RenderOptions& o, const Scene& s, const tensor::FramingBox& frame);
// The view chooseCamera frames when no --eye is given; none: the scene's own.
std::optional<render::ViewAxes> defaultViewAxes(const RenderOptions& o, const Scene& s);
// The frame's parameters from the options, the scene's preferred look and
// the resolved glyph size: what `render`, `view` and Python draw with.
render::FrameParams frameParams(const RenderOptions& o, const Scene& s, const tensor::ResolvedScale& sized);

}  // namespace tg::app
