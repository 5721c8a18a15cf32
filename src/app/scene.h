#pragma once
// What a render or info command works on: a loaded (or built-in) field.
#include <functional>
#include <optional>
#include <string>

#include "app/scale/cli_values.h"
#include "app/look_flags.h"
#include "app/stress_defaults.h"
#include "io/core/readers.h"
#include "io/core/selection.h"
#include "render/color_scalar.h"
#include "tensor/field_stats.h"
#include "tensor/glyph_scale.h"
#include "view/camera.h"

namespace tg::app {

struct FieldFlags;

// The ranges sizes and colours are worked out from when they are not those
// of the loaded glyphs: the whole field's, before the selection that left
// some of it out (slice, stride, ROI, mask, --cl-min/--cp-min; an FA
// threshold is a frame parameter and never leaves glyphs out). A selection
// chooses which glyphs are drawn, not their sizes or what their colours
// mean, so two slices of a field, or a slice beside the whole, share one
// scale and one window. Both come from one pass over the same glyphs
// (attachWholeField), so they cannot disagree on what the field is.
struct WholeField {
  tensor::FieldStats stats;
  double sampleSpacing = 0;
  render::ColorRanges colors;  // every colour source's range, --color-array's included
};

struct Scene {
  io::TensorField field;
  std::optional<WholeField> wholeField;  // none: the loaded glyphs are what the ranges come from
  // --color-array's scalar volume, once read for the whole field's range:
  // the session colours the glyphs from it instead of reading it again.
  std::optional<io::ScalarVolume> colorVolume;
  std::string sizesFrom;                 // where they come from, for info and --verbose
  std::optional<StressDefaults> stress;  // set by decideStressDefaults
  std::optional<render::CameraDesc> preferredCamera;  // used when no camera flag is given
  std::optional<double> preferredFaMin;
  std::optional<SceneLook> preferredLook;  // applied where the flags are silent
};

// The built-in default scene: the helix phantom, seen obliquely, with the
// isotropic background hidden by an FA threshold, drawn as superquadrics with
// every depth cue and a legend.
Scene defaultScene();

// The built-in scene when `input` is empty, else the file; the selection in
// `opt` applies to both. Refuses options that do not apply and an empty
// result (checkOptionsApply, checkLoaded); a --slice index beyond the grid
// is a UsageError naming the valid range.
Scene loadScene(const std::string& input, const io::ReadOptions& opt);

// Field-wide ranges (WholeField): unless `flags` asks --sizes-from
// selection, and when the selection (slice, stride, ROI, mask) or
// --cl-min/--cp-min left tensors out of s, the sizes' statistics and the
// colour ranges of the whole field are attached, from one build of its
// glyphs: of `whole()` (the field read again without the selection) when
// the load left tensors out, else of s.field itself, whose tensors a shape
// filter leaves all loaded. Sets s.sizesFrom either way.
void attachWholeField(Scene& s, const FieldFlags& flags, const std::function<io::TensorField()>& whole);
// The same for `input` (a file, or "" for the built-in scene), read again with `read` less its selection.
void attachWholeField(Scene& s, const FieldFlags& flags, const std::string& input, io::ReadOptions read);
// The statistics sizes come from: the whole field's, or those of `glyphs`
// (the loaded ones) when s has none; and resolveScale's sample of them.
tensor::FieldStats sizingStats(const Scene& s, const tensor::GlyphSet& glyphs);
tensor::MagnitudeSample sizingSample(const Scene& s, const tensor::FieldStats& stats);
// A scene with no look of its own gets the stress look when `stats` (the
// sizing statistics) or its array's name say stress (app/stress_defaults.h).
void decideStressDefaults(Scene& s, const tensor::FieldStats& stats);
// flags.scaleParams() with the scene's defaults where the flags are silent
// (a stress field's --magnitude).
tensor::ScaleParams sizingParams(const FieldFlags& flags, const Scene& s);

// The UsageError for a --slice index beyond the grid of `input` (empty: the
// built-in scene): the option, its value as `asked`, and the valid range.
UsageError sliceUsageError(const io::SliceOutOfRange& e, const io::SliceSpec& asked, const std::string& input);

// The view used when no camera flag is given: the scene's preferred view if
// it has one, else fitBox's default over the box (tensor::framingBox).
render::CameraDesc sceneCamera(const Scene& s, const glm::dvec3& loWC, const glm::dvec3& hiWC, render::Projection p,
                               double fovYDeg, double aspect);

// Grows the camera's depth range [lo, hi], the glyphs' box, to hold a
// context item's box (a slice plane's volume, a mesh), by at most
// kContextReach of the glyphs' diagonals each way: an item far larger than
// the field (an underlay with 1e30-wide voxels) would otherwise move the
// near plane past every glyph. Beyond that reach the item is clipped.
inline constexpr double kContextReach = 10.0;
void growDepthRange(glm::dvec3& lo, glm::dvec3& hi, const glm::dvec3& itemLo, const glm::dvec3& itemHi);

}  // namespace tg::app
