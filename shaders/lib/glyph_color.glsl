// What every glyph vertex stage colours by (lib/color.glsl): the mode, the
// colormap and the window as uniforms, and the per-glyph scalars of
// kColorArray in their own buffer, indexed like the records, so that a new
// colour source or window never touches the records.
#include "lib/bindings.h"
#include "lib/color.glsl"

uniform int uColorMode;
uniform int uColormap;
uniform vec2 uColorWindow;  // values at the map's ends; kColorSign: -M..M
uniform int uColorTable;    // 1: kColorArray maps through colorTable instead of uColormap

layout(std430, binding = TG_SSBO_COLOR_SCALARS) readonly buffer ColorScalars { float colorScalars[]; };
// A host's own map (ParaView's lookup table), GlyphRenderer::setColorTable's
// layout: n colours for n equal parts of the window, then the colours of
// NaN, of values below and of values above the window.
layout(std430, binding = TG_SSBO_COLOR_TABLE) readonly buffer ColorTable { vec4 colorTable[]; };

vec3 tableColor(vec2 window, float v) {
  int n = colorTable.length() - 3;
  if (isnan(v)) return colorTable[n].rgb;
  if (v < window.x) return colorTable[n + 1].rgb;
  if (v > window.y) return colorTable[n + 2].rgb;
  float span = 0.5 * window.y - 0.5 * window.x;
  float t = span > 0.0 ? (0.5 * v - 0.5 * window.x) / span : 0.5;
  return colorTable[clamp(int(t * float(n)), 0, n - 1)].rgb;
}

// Record `index`'s flat colour, or with kColorSign the weights signColor
// takes, for eigenvalues `lGC` in the glyph's GC order.
vec3 glyphVertexColor(uint index, vec3 e1WC, float fa, vec3 eigenvalues, vec3 lGC) {
  if (uColorMode == kColorSign) return signWeights(lGC, uColorWindow);
  float arrayValue = uColorMode == kColorArray ? colorScalars[index] : 0.0;
  if (uColorMode == kColorArray && uColorTable == 1) return tableColor(uColorWindow, arrayValue);
  return glyphColor(uColorMode, uColormap, uColorWindow, e1WC, fa, eigenvalues, arrayValue);
}
