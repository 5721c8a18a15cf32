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
  if (!glyphSelected(g.posWC_fa)) return;
  vec3 axes = glyphAxes(g.eigenvalues_id.xyz);
  float radius = max(axes.x, max(axes.y, axes.z));
  if (!(radius > 0.0)) return;

  vec3 centreVC = (uViewWCVC * vec4(g.posWC_fa.xyz, 1.0)).xyz;
  float dist = -centreVC.z;
  if (dist + radius < uNearVC || (uOrtho == 1 && dist - radius > uFarVC)) return;
  // The sphere of the longest axis holds the ellipsoid.
  if (spriteMissesEveryPixelCentre(centreVC, radius)) return;
  mat3 rotWC = quatToMat3(g.frameWC);
  mat3 rotVC = mat3(uViewWCVC) * rotWC;

  // T of eq. (2), in VC: parameter space -> view coordinates.
  mat4 tVC = mat4(vec4(rotVC[0] * axes.x, 0.0), vec4(rotVC[1] * axes.y, 0.0),
                  vec4(rotVC[2] * axes.z, 0.0), vec4(centreVC, 1.0));
  vec4 rect;
  if (!ellipsoidRectNDC(uProjVCCC * tVC, rect)) rect = vec4(-1.0, -1.0, 1.0, 1.0);
  else if (rectMissesEveryPixelCentre(rect, kPixelCentreMarginDC)) return;
  // A quarter pixel of margin so that pixel centres on the exact edge are kept.
  vec2 px = 0.5 / uViewportDC;
  rect = clamp(rect + vec4(-px, px), -1.0, 1.0);
  if (rect.x >= rect.z || rect.y >= rect.w) return;
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
  mat3 gcFromVC = transpose(mat3(rotVC[0] / axes.x, rotVC[1] / axes.y, rotVC[2] / axes.z));
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
  vs.gcFromVC = transpose(mat3(rotVC[0] / axes.x, rotVC[1] / axes.y, rotVC[2] / axes.z));
  // One input fewer per fragment: llvmpipe's ellipsoid fragments cost by the inputs they read.
  vs.color = glyphVertexColor(index, rotWC[0], g.posWC_fa.w, g.eigenvalues_id.xyz, g.eigenvalues_id.xyz);
  vs.id = floatBitsToUint(g.eigenvalues_id.w);
#endif
}
