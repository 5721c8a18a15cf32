#version 450 core
// Four vertices per glyph (lib/sprite.glsl): fetch the record, cull it, and
// place this vertex at a corner of the glyph's exact screen rectangle (Sigg
// et al. 2006, eq. 5), passing what the fragment stage needs to intersect it.
// TG_OCCLUDER_DISC: the same sprite as an occluder of the superquadric pass's
// pre-pass, for occluder_disc.frag: its outline, at a depth no front hit lies
// behind.
#pragma tg option TG_OCCLUDER_DISC
#include "lib/camera.glsl"
#include "lib/glyph_record.glsl"
#include "lib/ellipsoid.glsl"
#include "lib/glyph_size.glsl"
#include "lib/glyph_color.glsl"
#include "lib/selection.glsl"
#include "lib/sprite.glsl"
#include "lib/occlusion.glsl"
#include "lib/ellipsoid_sprite.glsl"

#ifdef TG_OCCLUDER_DISC
out OccluderFS {
  flat vec2 centreDC;
  flat vec3 conicDC;
} vs;
#else
out SpriteFS {
  flat vec3 centreVC;
  flat mat3 gcFromVC;
  flat vec3 color;  // with uColorMode kColorSign, the sign weights (lib/color.glsl)
  flat uint id;
} vs;
#endif

void main() {
  gl_Position = kSpriteCulledCC;
  uint index = spriteGlyphIndex();
  GlyphRecord g = glyphs[index];
  EllipsoidSprite s;
  if (!ellipsoidSprite(g, s)) return;
  vec3 axes = s.axes, centreVC = s.centreVC;
  float radius = s.radius, dist = s.dist;
  mat3 rotWC = s.rotWC, rotVC = s.rotVC;
  mat4 tVC = s.tVC;
  vec4 rect = s.rectNDC;
  // Hidden behind the pre-pass's occluders, which hold this very ellipsoid
  // (so a glyph visible anywhere never is): no fragment of it could win.
  if (spriteOccluded(rect, dist - radius, 0.0)) return;

#ifdef TG_OCCLUDER_DISC
  // A glyph the near plane may cut, or the eye may be in, occludes nothing
  // (from inside, its far wall would bound no surface in front of it).
  vec2 outlineDC;
  mat2 supportDC;
  float farVC;
  if (dist - radius < uNearVC || !ellipseSupportDC(uProjVCCC * tVC, outlineDC, supportDC)) return;
  // Nor does a glyph whose pixels the frame's own ray cast may miss: one
  // thinner than 1e-5 of its length (its rays' GC coordinates reach length
  // over thickness, and their rounding moves the hit test by more than the
  // outline's 1%), or an outline thinner than a hundredth of its length,
  // whose conic rounds by more than that 1%.
  if (!(min(axes.x, min(axes.y, axes.z)) >= 1e-5 * radius)) return;
  mat3 gcFromVC = ellipsoidGcFromVC(rotVC, axes);
  vec3 depthGC = -vec3(rotVC[0].z * axes.x, rotVC[1].z * axes.y, rotVC[2].z * axes.z);
  if (!silhouetteFarVC(gcFromVC, depthGC, centreVC, farVC)) return;
  // det / trace^2 is about the squared ratio of the outline's axes.
  float det = determinant(supportDC), trace = supportDC[0][0] + supportDC[1][1];
  if (!(det > 1e-4 * trace * trace)) return;
  // Constant over the sprite, as a point sprite's depth is.
  float depthWin = windowDepthFromViewDepth(farVC);
  bool oriented = uPointSprites == 0 && uOrientedSprites != 0;
#else
  // The quad sits at the nearest depth the glyph can have, so the fragment
  // depth only ever moves away from it (layout(depth_less) with reversed Z).
  float depthWin = windowDepthFromViewDepth(max(dist - radius, uNearVC));
  vec2 outlineDC;
  mat2 supportDC;
  bool oriented = uPointSprites == 0 && uOrientedSprites != 0 && ellipseSupportDC(uProjVCCC * tVC, outlineDC, supportDC);
#endif
  gl_Position = spriteCornerCC(rect, depthWin);
  if (oriented) {
    SpriteQuadDC quad = ellipseQuadDC(outlineDC, supportDC);
    quad.halfSize += 0.25;  // the rectangle's margin
    if (spriteQuadSmaller(quad, rect)) gl_Position = spriteQuadCornerCC(quad, depthWin);
  }
#ifdef TG_OCCLUDER_DISC
  vs.centreDC = outlineDC;
  vs.conicDC = vec3(supportDC[1][1], -supportDC[0][1], supportDC[0][0]) / det;
#else
  vs.centreVC = centreVC;
  vs.gcFromVC = ellipsoidGcFromVC(rotVC, axes);
  // One input fewer per fragment: llvmpipe's ellipsoid fragments cost by the inputs they read.
  vs.color = glyphVertexColor(index, rotWC[0], g.posWC_fa.w, g.eigenvalues_id.xyz, g.eigenvalues_id.xyz);
  vs.id = floatBitsToUint(g.eigenvalues_id.w);
#endif
}
