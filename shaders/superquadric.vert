#version 450 core
// Four vertices per glyph (lib/sprite.glsl), for glyphs that are not
// ellipsoids at the current gamma: the glyph's set-up and rectangle
// (lib/superquadric_sprite.glsl), and this vertex's corner of it or of a
// tighter quad along the glyph's projected axes.
// TG_MARCH_MIXED (the mixed-sign group's program): sprites also follow the
// double pyramid's outline; the other groups never pay for its corners.
#pragma tg option TG_MARCH_MIXED
#include "lib/camera.glsl"
#include "lib/glyph_record.glsl"
#include "lib/ellipsoid.glsl"
#include "lib/glyph_size.glsl"
#include "lib/superquadric.glsl"
#include "lib/glyph_color.glsl"
#include "lib/selection.glsl"
#include "lib/sprite.glsl"
#include "lib/superquadric_sprite.glsl"
#include "lib/occlusion.glsl"

uniform float uGamma;
uniform float uEpsilon;

out SuperquadricFS {
  flat vec3 centreVC;
  flat mat3 gcFromVC;  // rows: GC axes in VC over their lengths; GC z is the symmetry axis
  flat vec3 shape;
  flat vec3 color;  // with uColorMode kColorSign, the sign weights in GC (lib/color.glsl)
  flat uint id;
} vs;

void main() {
  gl_Position = kSpriteCulledCC;
  uint index = spriteGlyphIndex();
  GlyphRecord g = glyphs[index];
  SuperquadricSprite s;
  if (!superquadricSprite(g, uGamma, uEpsilon, s)) return;
  vec4 rect = s.rectNDC;
  // Wholly behind the occluders: no fragment of it could win the depth test.
  if (spriteOccluded(rect, s.nearest, 4.0 * uEpsilon * max(s.axes.x, max(s.axes.y, s.axes.z)))) return;

  float depthWin = windowDepthFromViewDepth(s.nearVC);
  gl_Position = spriteCornerCC(rect, depthWin);
  vec2 outlineDC;
  mat2 supportDC;
  if (uPointSprites == 0 && uOrientedSprites != 0 && !s.crossesEyePlane &&
      ellipseSupportDC(s.reachCC, outlineDC, supportDC)) {
    // Along the reach ellipsoid's projected axes, its quad clipped to the
    // box's corners, as the rectangle is.
    SpriteQuadDC quad = ellipseQuadDC(outlineDC, supportDC);
    vec2 f = vec2(-quad.axis.y, quad.axis.x);
    vec4 span = vec4(1e38, 1e38, -1e38, -1e38);
    for (int k = 0; k < 8; ++k) {
      vec2 d = (s.boxNDC[k] + 1.0) * 0.5 * uViewportDC - quad.centre;
      vec2 st = vec2(dot(d, quad.axis), dot(d, f));
      span = vec4(min(span.xy, st), max(span.zw, st));
    }
    if (s.pyramid) {
      vec4 spanP = vec4(1e38, 1e38, -1e38, -1e38);
      for (int k = 0; k < 6; ++k) {
        vec2 d = (s.pyramidNDC[k] + 1.0) * 0.5 * uViewportDC - quad.centre;
        vec2 st = vec2(dot(d, quad.axis), dot(d, f));
        spanP = vec4(min(spanP.xy, st), max(spanP.zw, st));
      }
      span = vec4(max(span.xy, spanP.xy), min(span.zw, spanP.zw));
    }
    span = vec4(max(span.xy, -quad.halfSize), min(span.zw, quad.halfSize));
    vec2 mid = 0.5 * (span.xy + span.zw);
    quad.centre += mid.x * quad.axis + mid.y * f;
    quad.halfSize = 0.5 * (span.zw - span.xy) + 0.25;  // the rectangle's margin
    if (all(greaterThan(quad.halfSize, vec2(0.0))) && spriteQuadSmaller(quad, rect))
      gl_Position = spriteQuadCornerCC(quad, depthWin);
    // Mixed-sign glyphs: the pyramid's outline where a quad holds it, half
    // the rectangle of a long diamond. A sixteenth of a pixel of margin
    // exceeds the rasteriser's snapping (1/256 px) and the corners' rounding.
    SpriteCornersDC outline;
    if (s.pyramid && pyramidOutlineDC(s.pyramidNDC, 0.0625, outline) &&
        spriteCornersArea(outline) < min(4.0 * quad.halfSize.x * quad.halfSize.y, s.sizeDC.x * s.sizeDC.y))
      gl_Position = spriteCornersCC(outline, depthWin);
  }
  vs.centreVC = s.centreVC;
  vs.gcFromVC = s.gcFromVC;
  vs.shape = s.shape.xyz;
  // One input fewer per fragment, as for ellipsoids: only one of the two is read.
  vs.color = glyphVertexColor(index, s.rotWC[0], g.posWC_fa.w, g.eigenvalues_id.xyz,
                              vec3(g.eigenvalues_id[s.src.x], g.eigenvalues_id[s.src.y], g.eigenvalues_id[s.src.z]));
  vs.id = floatBitsToUint(g.eigenvalues_id.w);
}
