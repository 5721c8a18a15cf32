#pragma once
// The viewer's state and its script language (`tensorglyph view --script`):
// one command per line, '#' starts a comment. A script is parsed and checked
// whole before the window opens, so a mistake on line 40 costs no run.
//
//   orbit YAW PITCH        degrees (turntable about the world up axis)
//   pan DX DY              move the scene by view heights, right and up
//   zoom F                 F times closer
//   reset                  the initial view
//   view NAME              look from an anatomical side, look-at and distance kept: axial,
//                          coronal, sagittal, superior, inferior, anterior, posterior, left,
//                          right (render --view; keys 1, 2, 3: axial, coronal, sagittal)
//   convention radiological|neurological   which side axial and coronal look from
//                          (render --radiological, --neurological; key V swaps them)
//   letters on|off         R/L, A/P, S/I on the image's edges (render --orientation-letters; key L)
//   glyph ellipsoid|superquadric
//   gamma G                superquadric sharpness, >= 0
//   fa-min F               hide glyphs with FA below F
//   scale F                glyph size, F times the initial scale
//   magnitude linear|log|shape [LAMBDA0]   size mapping (tensor/glyph_scale.h); LAMBDA0 default: the median
//   clamp N                no glyph wider than N sample spacings; 0: off
//   color dec|fa|md|cl|cp|sign
//   slab x|y|z LO HI       only glyphs with centres in [LO, HI] along the axis (WC)
//   slab off
//   light ambient|head|key|specular|shininess V
//   iterations N           superquadric Newton iterations at most
//   epsilon E              superquadric hit tolerance
//   stats on|off           count Newton iterations (status line)
//   legend on|off          the colour key and scale bar (render --legend)
//   legend-corner top-left|top-right|bottom-left|bottom-right
//   units TEXT             units of the tensor values in the legend (one word)
//   length-units TEXT      units of positions for the scale bar (one word)
//   ao on|off              screen-space ambient occlusion
//   ao-radius R            its radius in world units (> 0)
//   ao-strength S          its weight, 0..4
//   outlines on|off        silhouette and crease lines
//   outline-width W        their width in pixels, 0.25..8
//   shadows on|off         soft shadows from the key light
//   shadow penumbra|strength|bias|map-size V   (render's --shadow-* flags and ranges)
//   plane N on|off         show or hide slice plane N (1: the first --plane or --plane-at)
//   plane N index I        move index plane N to slice I of its axis (0-based, as --plane)
//   mesh N on|off|opaque|see-through|edges   the N-th mesh (--mesh-from-input first, then
//                          each --mesh; from 1): shown, hidden, or drawn so (render's --mesh-mode)
//   mesh-opacity N A       the N-th mesh's see-through opacity, 0..1
//   frames N               render N frames unchanged (for timing)
//   screenshot FILE        save the rendered view (without the panel)
//   pick I J               print what pixel (I, J) shows as one line of JSON on
//                          stdout, as render --pick (column I, row J from the top)
#include <string>
#include <vector>

#include "app/orbit_camera.h"
#include "render/mesh_item.h"
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
  bool radiological = false;  // the convention `view axial` and `view coronal` follow
  std::string view{};         // the last view named, which a change of convention turns again
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
// for a plane that does not exist, an index outside its axis or an index for
// an oblique plane.
void checkPlaneSteps(const std::vector<ScriptStep>& steps, const std::vector<PlaneView>& planes,
                     const std::string& path);
// io::InputError "PATH:LINE: mesh: ..." for a mesh step naming a mesh beyond
// the `meshes` loaded; run once they are, before the window opens.
void checkScriptMeshes(const std::vector<ScriptStep>& steps, std::size_t meshes, const std::string& path);

// Applies a parsed step to the state. `frames` and `screenshot` change
// nothing here; the viewer acts on them.
void applyStep(const ScriptStep& s, ViewState& v);

}  // namespace tg::app
