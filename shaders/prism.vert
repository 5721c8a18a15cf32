#version 450 core
// Four vertices per glyph (lib/sprite.glsl) for Teem's box glyphs, or with
// TG_CYLINDER its cylinder glyphs: the glyph's set-up and tight screen
// rectangle (lib/prism.glsl's prismSprite, which the CPU glyph path runs
// too), and this vertex's corner of it.
#pragma tg option TG_CYLINDER
#include "lib/camera.glsl"
#include "lib/glyph_record.glsl"
#include "lib/ellipsoid.glsl"
#include "lib/glyph_size.glsl"
#include "lib/selection.glsl"
#include "lib/prism.glsl"
#include "lib/glyph_color.glsl"
#include "lib/sprite.glsl"

#ifdef TG_CYLINDER
const bool kCylinder = true;
#else
const bool kCylinder = false;
#endif

out PrismFS {
  flat vec3 centreVC;
  flat mat3 gcFromVC;  // rows: GC axes in VC over their lengths; a cylinder's axis is GC z
  flat vec3 color;
  flat uint id;
} vs;

void main() {
  gl_Position = kSpriteCulledCC;
  uint index = spriteGlyphIndex();
  GlyphRecord g = glyphs[index];
  PrismSprite s;
  if (!prismSprite(g, kCylinder, s)) return;
  // At the nearest depth the glyph can have: fragments only move away (depth_less).
  gl_Position = spriteCornerCC(s.rectNDC, windowDepthFromViewDepth(s.nearVC));
  vs.centreVC = s.centreVC;
  vs.gcFromVC = s.gcFromVC;
  vec3 l = g.eigenvalues_id.xyz;
  vs.color = glyphVertexColor(index, s.rotWC[0], g.posWC_fa.w, l, vec3(l[s.src.x], l[s.src.y], l[s.src.z]));
  vs.id = floatBitsToUint(g.eigenvalues_id.w);
}
