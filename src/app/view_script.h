#pragma once
// The viewer's state and its script language (`tensorglyph view --script`):
// one command per line, '#' starts a comment. A script is parsed and checked
// whole before the window opens, so a mistake on line 40 costs no run.
//
//   orbit YAW PITCH        degrees (turntable about the world up axis)
//   pan DX DY              move the scene by view heights, right and up
//   zoom F                 F times closer
//   reset                  the initial view
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
//   mesh N on|off|opaque|see-through|edges   the N-th mesh (--mesh-from-input first, then
//                          each --mesh; from 1): shown, hidden, or drawn so (render's --mesh-mode)
//   mesh-opacity N A       the N-th mesh's see-through opacity, 0..1
//   frames N               render N frames unchanged (for timing)
//   screenshot FILE        save the rendered view (without the panel)
#include <string>
#include <vector>

#include "app/orbit_camera.h"
#include "render/mesh_item.h"
#include "render/renderer.h"

namespace tg::app {

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
  std::vector<MeshView> meshes{};
};

// Resolves v.sizing over v.magnitudes into baseScale, params.scale and
// params.sizing: uniforms only.
void resize(ViewState& v);

struct ScriptStep {
  int line = 0;
  std::string verb;
  std::vector<std::string> args;
};

// Throws io::InputError "PATH:LINE: ..." for an unreadable file, an unknown
// command, a wrong argument count or a value out of range.
std::vector<ScriptStep> parseScript(const std::string& path);

// io::InputError "PATH:LINE: mesh: ..." for a mesh step naming a mesh beyond
// the `meshes` loaded; run once they are, before the window opens.
void checkScriptMeshes(const std::vector<ScriptStep>& steps, std::size_t meshes, const std::string& path);

// Applies a parsed step to the state. `frames` and `screenshot` change
// nothing here; the viewer acts on them.
void applyStep(const ScriptStep& s, ViewState& v);

}  // namespace tg::app
