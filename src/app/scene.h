#pragma once
// What a render or info command works on: a loaded (or built-in) field.
#include <optional>
#include <string>

#include "app/cli_values.h"
#include "app/look_flags.h"
#include "io/readers.h"
#include "io/selection.h"
#include "view/camera.h"

namespace tg::app {

struct Scene {
  io::TensorField field;
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
