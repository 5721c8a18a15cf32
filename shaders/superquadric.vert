#version 450 core
// Four vertices per glyph (lib/sprite.glsl), for glyphs that are not
// ellipsoids at the current gamma: the shape from the record and gamma, and
// this vertex's corner of the exact screen rectangle of the glyph's box (the
// gamma -> infinity limit that holds every shape; Hlawitschka et al. §3.2).
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
  if (!glyphSelected(g.posWC_fa)) return;
  vec3 axes = glyphAxes(g.eigenvalues_id.xyz);
  if (!(max(axes.x, max(axes.y, axes.z)) > 0.0)) return;
  vec3 centreVC = (uViewWCVC * vec4(g.posWC_fa.xyz, 1.0)).xyz;
  // The box's half-diagonal bounds every shape.
  if (spriteMissesEveryPixelCentre(centreVC, length(axes))) return;
  vec4 shape = superquadricShape(g.eigenvalues_id.xyz, uGamma);

  mat3 rotWC = quatToMat3(g.frameWC);
  mat3 rotVC = mat3(uViewWCVC) * rotWC;
  // GC axes: a cyclic permutation of the eigenvectors that puts the symmetry axis on z.
  int ax = int(shape.w);
  ivec3 src = ivec3((ax + 1) % 3, (ax + 2) % 3, ax);
  vec3 e0 = rotVC[src.x] * axes[src.x], e1 = rotVC[src.y] * axes[src.y], e2 = rotVC[src.z] * axes[src.z];

  // The box's corners: nearest depth, and their projected rectangle.
  float nearest = 1e38;
  vec4 rect = vec4(1e38, 1e38, -1e38, -1e38);
  bool crossesEyePlane = false;
  vec2 boxNDC[8];
  for (int k = 0; k < 8; ++k) {
    vec3 c = centreVC + ((k & 1) == 0 ? -e0 : e0) + ((k & 2) == 0 ? -e1 : e1) + ((k & 4) == 0 ? -e2 : e2);
    nearest = min(nearest, -c.z);
    vec4 cc = uProjVCCC * vec4(c, 1.0);
    if (cc.w <= 0.0) crossesEyePlane = true;
    boxNDC[k] = cc.xy / cc.w;
    rect = vec4(min(rect.xy, boxNDC[k]), max(rect.zw, boxNDC[k]));
  }
  // Mixed-sign shapes (b, c >= 2) also lie in the double pyramid
  // max(|x|, |y|) + |z| <= 1 in GC (lib/superquadric_march.glsl), grown as
  // the fragment stage grows it for shape exponents just below 2 and the
  // march's tolerance (float rounding in window pixels is left to the
  // sprites' margins): its six corners bound a thin glyph's outline tighter
  // than the box's eight.
#ifdef TG_MARCH_MIXED
  bool pyramid = min(shape.y, shape.z) >= 1.9999;
#else
  bool pyramid = false;  // a constant: the compiler drops every use
#endif
  float rP = 1.0 + 1e-3 + 4.0 * uEpsilon;
  vec2 pyramidNDC[6];
  vec4 rectP = vec4(1e38, 1e38, -1e38, -1e38);
  for (int k = 0; k < 6; ++k) {
    vec3 c = centreVC + rP * (k < 4 ? ((k & 1) == 0 ? -e0 : e0) + ((k & 2) == 0 ? -e1 : e1) : (k == 4 ? -e2 : e2));
    vec4 cc = uProjVCCC * vec4(c, 1.0);
    if (cc.w <= 0.0) pyramid = false;
    pyramidNDC[k] = cc.xy / cc.w;
    rectP = vec4(min(rectP.xy, pyramidNDC[k]), max(rectP.zw, pyramidNDC[k]));
  }
  if (pyramid) rect = vec4(max(rect.xy, rectP.xy), min(rect.zw, rectP.zw));
  float farthest = -centreVC.z + length(axes);
  if (farthest < uNearVC || (uOrtho == 1 && nearest > uFarVC)) return;
  if (crossesEyePlane) rect = vec4(-1.0, -1.0, 1.0, 1.0);
  // The shape also lies within its ellipsoid grown by its reach: where that
  // ellipsoid's rectangle is tighter than the box's (a rotated box's corners
  // reach far out), only pixels that cannot hit are left out.
  float reach = superquadricReach(shape.xyz);
  nearest = max(nearest, -centreVC.z - reach * max(axes.x, max(axes.y, axes.z)));
  mat4 reachCC = uProjVCCC * mat4(vec4(reach * e0, 0.0), vec4(reach * e1, 0.0), vec4(reach * e2, 0.0),
                                  vec4(centreVC, 1.0));
  vec4 rectR;
  if (!crossesEyePlane && ellipsoidRectNDC(reachCC, rectR))
    rect = vec4(max(rect.xy, rectR.xy), min(rect.zw, rectR.zw));
  // No pixel centre in it (a glyph near a pixel's size, or thin): nothing to
  // set up. The march accepts hits within its tolerance, a glyph grown by at
  // most that fraction, so the margin grows with the rectangle.
  vec2 sizeDC = (rect.zw - rect.xy) * 0.5 * uViewportDC;
  float marginDC = kPixelCentreMarginDC + (2e-3 + 4.0 * uEpsilon) * max(sizeDC.x, sizeDC.y);
  if (!crossesEyePlane && rectMissesEveryPixelCentre(rect, marginDC)) return;
  // A quarter pixel of margin so that pixel centres on the exact edge are kept.
  vec2 px = 0.5 / uViewportDC;
  rect = clamp(rect + vec4(-px, px), -1.0, 1.0);
  if (rect.x >= rect.z || rect.y >= rect.w) return;
  // Wholly behind the occluders: no fragment of it could win the depth test.
  if (spriteOccluded(rect, nearest, 4.0 * uEpsilon * max(axes.x, max(axes.y, axes.z)))) return;

  // The march accepts hits up to its tolerance in front of the shape, so the
  // sprite lies that much nearer: superquadric.frag promises depth_less.
  float depthWin = windowDepthFromViewDepth(max(nearest - 4.0 * uEpsilon * max(axes.x, max(axes.y, axes.z)), uNearVC));
  gl_Position = spriteCornerCC(rect, depthWin);
  vec2 outlineDC;
  mat2 supportDC;
  if (uPointSprites == 0 && uOrientedSprites != 0 && !crossesEyePlane &&
      ellipseSupportDC(reachCC, outlineDC, supportDC)) {
    // Along the reach ellipsoid's projected axes, its quad clipped to the
    // box's corners, as the rectangle is.
    SpriteQuadDC quad = ellipseQuadDC(outlineDC, supportDC);
    vec2 f = vec2(-quad.axis.y, quad.axis.x);
    vec4 span = vec4(1e38, 1e38, -1e38, -1e38);
    for (int k = 0; k < 8; ++k) {
      vec2 d = (boxNDC[k] + 1.0) * 0.5 * uViewportDC - quad.centre;
      vec2 st = vec2(dot(d, quad.axis), dot(d, f));
      span = vec4(min(span.xy, st), max(span.zw, st));
    }
    if (pyramid) {
      vec4 spanP = vec4(1e38, 1e38, -1e38, -1e38);
      for (int k = 0; k < 6; ++k) {
        vec2 d = (pyramidNDC[k] + 1.0) * 0.5 * uViewportDC - quad.centre;
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
    if (pyramid && pyramidOutlineDC(pyramidNDC, 0.0625, outline) &&
        spriteCornersArea(outline) < min(4.0 * quad.halfSize.x * quad.halfSize.y, sizeDC.x * sizeDC.y))
      gl_Position = spriteCornersCC(outline, depthWin);
  }
  vs.centreVC = centreVC;
  vs.gcFromVC = transpose(mat3(e0 / dot(e0, e0), e1 / dot(e1, e1), e2 / dot(e2, e2)));
  vs.shape = shape.xyz;
  // One input fewer per fragment, as for ellipsoids: only one of the two is read.
  vs.color = glyphVertexColor(index, rotWC[0], g.posWC_fa.w, g.eigenvalues_id.xyz,
                              vec3(g.eigenvalues_id[src.x], g.eigenvalues_id[src.y], g.eigenvalues_id[src.z]));
  vs.id = floatBitsToUint(g.eigenvalues_id.w);
}
