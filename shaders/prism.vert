#version 450 core
// Four vertices per glyph (lib/sprite.glsl) for Teem's box glyphs, or with
// TG_CYLINDER its cylinder glyphs (lib/prism.glsl): this vertex's corner of
// the glyph's tight screen rectangle. A box's is that of its 8 corners; a
// cylinder's, the union of its two cap discs' (each Sigg et al. 2006 eq. 5
// with a flat parameter axis, their per-cap bounding boxes, §3.2): the
// projection of a convex hull is the hull of the projections.
#pragma tg option TG_CYLINDER
#include "lib/camera.glsl"
#include "lib/glyph_record.glsl"
#include "lib/ellipsoid.glsl"
#include "lib/glyph_size.glsl"
#include "lib/prism.glsl"
#include "lib/glyph_color.glsl"
#include "lib/selection.glsl"
#include "lib/sprite.glsl"

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
  if (!glyphSelected(g.posWC_fa)) return;
  vec3 l = g.eigenvalues_id.xyz;
  vec3 axes = glyphAxes(l);
  if (!(max(axes.x, max(axes.y, axes.z)) > 0.0)) return;

  mat3 rotWC = quatToMat3(g.frameWC);
  mat3 rotVC = mat3(uViewWCVC) * rotWC;
  vec3 centreVC = (uViewWCVC * vec4(g.posWC_fa.xyz, 1.0)).xyz;
#ifdef TG_CYLINDER
  // GC z on the cylinder's axis; a cyclic permutation keeps GC right-handed.
  int ax = cylinderAxis(l);
  ivec3 src = ivec3((ax + 1) % 3, (ax + 2) % 3, ax);
#else
  ivec3 src = ivec3(0, 1, 2);
#endif
  vec3 e0 = rotVC[src.x] * axes[src.x], e1 = rotVC[src.y] * axes[src.y], e2 = rotVC[src.z] * axes[src.z];

  vec4 rect = vec4(1e38, 1e38, -1e38, -1e38);
  bool full = false;
  float nearest = 1e38, farthest = -1e38;
#ifdef TG_CYLINDER
  for (int k = 0; k < 2; ++k) {
    vec3 capVC = centreVC + (k == 0 ? -e2 : e2);
    // The disc's depth extent along the view axis is exact: |(e0.z, e1.z)|.
    float reach = length(vec2(e0.z, e1.z));
    nearest = min(nearest, -capVC.z - reach);
    farthest = max(farthest, -capVC.z + reach);
    mat4 pmt = uProjVCCC * mat4(vec4(e0, 0.0), vec4(e1, 0.0), vec4(0.0), vec4(capVC, 1.0));
    vec4 capRect;
    // A cap meeting or behind the eye plane (w <= 0 at its centre) has no finite rectangle.
    if (!ellipsoidRectNDC(pmt, capRect) || !(pmt[3][3] > 0.0)) full = true;
    else rect = vec4(min(rect.xy, capRect.xy), max(rect.zw, capRect.zw));
  }
#else
  for (int k = 0; k < 8; ++k) {
    vec3 c = centreVC + ((k & 1) == 0 ? -e0 : e0) + ((k & 2) == 0 ? -e1 : e1) + ((k & 4) == 0 ? -e2 : e2);
    nearest = min(nearest, -c.z);
    farthest = max(farthest, -c.z);
    vec4 cc = uProjVCCC * vec4(c, 1.0);
    if (cc.w <= 0.0) full = true;
    vec2 ndc = cc.xy / cc.w;
    rect = vec4(min(rect.xy, ndc), max(rect.zw, ndc));
  }
#endif
  if (farthest < uNearVC || (uOrtho == 1 && nearest > uFarVC)) return;
  if (full) rect = vec4(-1.0, -1.0, 1.0, 1.0);
  // One pixel of margin so that pixel centres on the exact edge are kept.
  vec2 px = 2.0 / uViewportDC;
  rect = clamp(rect + vec4(-px, px), -1.0, 1.0);
  if (rect.x >= rect.z || rect.y >= rect.w) return;

  // At the nearest depth the glyph can have: fragments only move away (depth_less).
  gl_Position = spriteCornerCC(rect, windowDepthFromViewDepth(max(nearest, uNearVC)));
  vs.centreVC = centreVC;
  vs.gcFromVC = transpose(mat3(e0 / dot(e0, e0), e1 / dot(e1, e1), e2 / dot(e2, e2)));
  vs.color = glyphVertexColor(index, rotWC[0], g.posWC_fa.w, l, vec3(l[src.x], l[src.y], l[src.z]));
  vs.id = floatBitsToUint(g.eigenvalues_id.w);
}
