#pragma once
// The viewer's state and its script language (`tensorglyph view --script`):
// one command per line, '#' starts a comment, each a row of the command
// table (app/script_commands.h; `tensorglyph help script`, docs/script.md).
// A script is parsed and checked whole before the window opens, so that a
// mistake on line 40 costs no run. Slices (`slab`, `plane N SLICE`) are
// written as --slice takes them and parsed by the same code (io::parseSlice).
#include <optional>
#include <string>
#include <vector>

#include "app/orbit_camera.h"
#include "io/core/selection.h"
#include "render/mesh_item.h"
#include "render/tract_item.h"
#include "render/frame_params.h"
#include "view/underlay.h"

namespace tg::app {

// A slice plane as the panel and `plane N ...` set it; the viewer hands a
// change to its render::SlicePlane (the quad only: no upload).
struct PlaneView {
  render::PlaneSpec spec;
  bool visible = true;
  long long slices = 0;  // along spec.axis: the index runs over 0..slices-1 (0: oblique)
  bool operator==(const PlaneView&) const = default;
};

// A context mesh as the viewer shows it; the viewer hands changes to its MeshItem.
struct MeshView {
  std::string label;
  bool visible = true;
  render::MeshParams params;
};

// A tractography item as the viewer shows it (its TractItem takes changes).
struct TractView {
  std::string label;
  bool visible = true;
  render::TractParams params;
};

// A grid that a script's slice is resolved on (io::resolveSlice): the
// glyphs' field's for `slab`, the underlay's for `plane N SLICE`.
struct SliceGrid {
  io::GridPlacement placement;
  int dims[3] = {0, 0, 0};
};
SliceGrid sliceGridOf(const io::GridInfo& g);
SliceGrid sliceGridOf(const render::UnderlayVolume& v);

// `spec` on grid `g` (io::resolveSlice), held to it: throws UsageError
// "WHAT: ..." (the step as written, "slab axial:40") for an index outside
// the grid along its voxel axis.
io::SliceSpec resolveOn(const std::string& what, const io::SliceSpec& spec, const SliceGrid& g);
// The glyph centres of a resolved slice as render's slab: the voxels a
// --slice of it keeps, and no others, on any grid (across a world axis
// where the grid's axes are the world's; across the slice's own normal on
// an oblique grid).
render::Slab slabOf(const io::SliceSpec& resolved, const SliceGrid& g);

struct ViewState {
  render::FrameParams params;
  OrbitCamera camera;
  double baseScale = 1.0;  // params.scale = baseScale * scaleFactor
  double scaleFactor = 1.0;
  // The size choice and the field's magnitudes, kept so that a change of
  // mapping or clamp is resolved again without the records (resize()).
  tensor::ScaleParams sizing{};
  tensor::MagnitudeSample magnitudes{};
  std::vector<PlaneView> planes{};  // in the order of --plane and --plane-at
  std::vector<MeshView> meshes{};
  std::vector<TractView> tracts{};  // in the order of --tracts
  bool radiological = false;  // the convention `view axial` and `view coronal` follow
  std::string view{};         // the last view named, which a change of convention turns again
  std::optional<SliceGrid> fieldGrid{}, underlayGrid{};  // none: a point set, no underlay
  // The slice params.slab shows, resolved on fieldGrid (the panel's slab
  // controls start from it); none: no slab, or a point set's world range.
  std::optional<io::SliceSpec> slabSlice{};
};

// Turns the camera to the named view (render::namedView) in v's convention.
void turnToView(ViewState& v, const std::string& name);

// Resolves v.sizing over v.magnitudes into baseScale, params.scale and
// params.sizing: uniforms only.
void resize(ViewState& v);

struct ScriptStep {
  int line = 0;
  std::string verb;
  std::vector<std::string> args;
  // Argument k as an integer, once parseScript has held it to its range
  // (frames, pick: app/scale/option_ranges.h), so the viewer reads it without a
  // second range of its own.
  int integer(std::size_t k) const;
};

// Throws io::InputError "PATH:LINE: ..." for an unreadable file, an unknown
// command, a wrong argument count or a value out of range.
std::vector<ScriptStep> parseScript(const std::string& path);

// The `plane` steps against the planes the view has, once the underlay is
// known and before the window opens: throws io::InputError "PATH:LINE: ..."
// for a plane that does not exist, an index or SLICE outside its grid (the
// underlay's, `underlay`) or either for an oblique plane.
void checkPlaneSteps(const std::vector<ScriptStep>& steps, const std::vector<PlaneView>& planes,
                     const std::string& path, const std::optional<SliceGrid>& underlay = std::nullopt);
// The `slab` steps against the glyphs' grid (none: a point set), once the
// field is loaded: io::InputError "PATH:LINE: slab ..." for a slice outside
// it, or any slice of a point set.
void checkSlabSteps(const std::vector<ScriptStep>& steps, const std::optional<SliceGrid>& field,
                    const std::string& path);
// io::InputError "PATH:LINE: mesh: ..." for a mesh step naming a mesh beyond
// the `meshes` loaded; run once they are, before the window opens.
void checkScriptMeshes(const std::vector<ScriptStep>& steps, std::size_t meshes, const std::string& path);

// Applies a parsed step to the state. `frames` and `screenshot` change
// nothing here; the viewer acts on them.
void applyStep(const ScriptStep& s, ViewState& v);

}  // namespace tg::app
