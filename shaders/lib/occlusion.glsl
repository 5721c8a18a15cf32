// Occlusion by the pre-pass of GlyphRenderer::render: the exact ellipsoids of
// the glyphs whose superquadric holds its ellipsoid (spheres, and definite
// tensors' Kindlmann shapes, both exponents <= 1). No visible surface lies
// behind their depth, so a superquadric whose nearest possible point is
// behind it can be skipped: a whole glyph in the vertex stage (the pyramid),
// one pixel's march in the fragment stage. Requires lib/camera.glsl.
#include "lib/bindings.h"

uniform int uOccluders;  // 0: no pre-pass ran
layout(binding = TG_UNIT_OCCLUDER_DEPTH) uniform sampler2D uOccluderDepth;    // window depth, reversed; 0: none
layout(binding = TG_UNIT_OCCLUDER_PYRAMID) uniform sampler2D uOccluderPyramid;  // mip k: the farthest over 2^(k+1) pixels

// True when depthVC lies behind the occluder at window depth occluderWin. The
// margin covers float rounding and the march's tolerance (toleranceVC) on the
// glyph that made the visible surface. Rounding grows with |depth|: an
// orthographic view also sees glyphs behind the eye, at negative depth.
bool behindOccluder(float depthVC, float occluderWin, float toleranceVC) {
  if (!(occluderWin > 0.0)) return false;  // no occluder there
  float occluderVC = viewDepthFromWindowDepth(occluderWin);
  return depthVC > occluderVC + 1e-5 * abs(occluderVC) + toleranceVC;
}

// The farthest occluder over the window pixels [pxMin, pxMax]: the finest
// level at which they span at most 4x4 texels, and those texels (a sprite a
// few pixels wide then reads texels little wider than itself).
float farthestOccluderWin(ivec2 pxMin, ivec2 pxMax) {
  const int kSpan = 4;
  int levels = textureQueryLevels(uOccluderPyramid);
  int k = 1;
  while (k < levels && any(greaterThan((pxMax >> k) - (pxMin >> k), ivec2(kSpan - 1)))) ++k;
  if (any(greaterThan((pxMax >> k) - (pxMin >> k), ivec2(kSpan - 1)))) return 0.0;
  // From level 0: llvmpipe's textureSize took one lane's lod for all when
  // the lod differed between vertices (a whole glyph vanished; tests).
  ivec2 last = max(textureSize(uOccluderPyramid, 0) >> (k - 1), ivec2(1)) - 1;
  ivec2 a = min(pxMin >> k, last), b = min(pxMax >> k, last);
  float f = 1.0;
  for (int y = a.y; y <= b.y; ++y)
    for (int x = a.x; x <= b.x; ++x) f = min(f, texelFetch(uOccluderPyramid, ivec2(x, y), k - 1).r);
  return f;
}

// Whole-glyph test for a sprite covering rectNDC whose nearest point is at nearestVC.
bool spriteOccluded(vec4 rectNDC, float nearestVC, float toleranceVC) {
  if (uOccluders == 0) return false;
  vec4 px = (rectNDC * 0.5 + 0.5) * uViewportDC.xyxy;
  ivec2 pxMin = ivec2(floor(px.xy)), pxMax = ivec2(ceil(px.zw)) - 1;
  pxMin = clamp(pxMin, ivec2(0), ivec2(uViewportDC) - 1);
  pxMax = clamp(pxMax, pxMin, ivec2(uViewportDC) - 1);
  return behindOccluder(nearestVC, farthestOccluderWin(pxMin, pxMax), toleranceVC);
}

// Per-pixel test at window pixel px, for a glyph whose nearest point on the
// pixel's ray is at entryVC.
bool pixelOccluded(ivec2 px, float entryVC, float toleranceVC) {
  if (uOccluders == 0) return false;
  return behindOccluder(entryVC, texelFetch(uOccluderDepth, px, 0).r, toleranceVC);
}
