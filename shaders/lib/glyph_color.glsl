// What every glyph vertex stage colours by (lib/color.glsl): the mode, the
// colormap and the window as uniforms, and the per-glyph scalars of
// kColorArray in their own buffer, indexed like the records, so that a new
// colour source or window never touches the records.
#include "lib/bindings.h"
#include "lib/color.glsl"

uniform int uColorMode;
uniform int uColormap;
uniform vec2 uColorWindow;  // values at the map's ends; kColorSign: -M..M

layout(std430, binding = TG_SSBO_COLOR_SCALARS) readonly buffer ColorScalars { float colorScalars[]; };

// Record `index`'s flat colour, or with kColorSign the weights signColor
// takes, for eigenvalues `lGC` in the glyph's GC order.
vec3 glyphVertexColor(uint index, vec3 e1WC, float fa, vec3 eigenvalues, vec3 lGC) {
  if (uColorMode == kColorSign) return signWeights(lGC, uColorWindow);
  float arrayValue = uColorMode == kColorArray ? colorScalars[index] : 0.0;
  return glyphColor(uColorMode, uColormap, uColorWindow, e1WC, fa, eigenvalues, arrayValue);
}
