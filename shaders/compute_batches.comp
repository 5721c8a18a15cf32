#version 450 core
// The compute glyph path's batch cull (render/compute_glyphs.h), one
// invocation per batch of the bound chunk's records: a batch none of whose
// glyphs can be selected or seen is left out of compute_setup.comp's
// dispatch, so that a zoomed view or a high FA threshold costs only the
// batches it keeps. Conservative: whatever the sprites would keep is kept.
#include "lib/compute_vis.glsl"

layout(local_size_x = 64) in;

uniform int uBatchCount;  // the chunk's

// Whether the box (cWC +- halfWC) grown by r lies wholly outside the
// half-space plane . (x, y, z, 1) >= 0 (a clip-space side plane in WC, after
// Gribb and Hartmann: a sum of rows of the projection times the view).
bool outside(vec4 plane, vec3 cWC, vec3 halfWC, float r) {
  return dot(plane.xyz, cWC) + plane.w + dot(abs(plane.xyz), halfWC) < -r * length(plane.xyz);
}

void main() {
  uint b = gl_GlobalInvocationID.x;
  if (b >= uint(uBatchCount)) return;
  BatchBounds bb = batches[b];
  // lib/selection.glsl's glyphSelected, for the batch's most anisotropic glyph.
  if (!(bb.hiWC_maxFA.w >= uFaMin)) return;
  vec3 lo = bb.loWC_maxAbs.xyz, hi = bb.hiWC_maxFA.xyz;
  vec3 cWC = 0.5 * (lo + hi), halfWC = 0.5 * (hi - lo);
  if (uSlabAxis >= 0) {
    // The slab selects centres: the centres' box against it.
    float d = dot(cWC, uSlabNormal), e = dot(halfWC, abs(uSlabNormal));
    if (d + e < uSlabWC.x || d - e > uSlabWC.y) return;
  }
  // Every glyph lies within sqrt(3) of its largest semi-axis of its centre
  // (a box's corner); glyphRadiusWC is non-decreasing. A thousandth more
  // against rounding.
  float r = 1.001 * 1.7320508 * glyphRadiusWC(bb.loWC_maxAbs.w);
  // The four side planes (perspective has no far plane), widened by a few
  // pixels for anti-aliasing's sub-pixel jitter (uPixelOffsetDC) and the
  // sprites' pixel rounding.
  mat4 M = uProjVCCC * uViewWCVC;
  vec4 rx = vec4(M[0][0], M[1][0], M[2][0], M[3][0]);
  vec4 ry = vec4(M[0][1], M[1][1], M[2][1], M[3][1]);
  vec4 rw = vec4(M[0][3], M[1][3], M[2][3], M[3][3]);
  vec2 m = 1.0 + 8.0 / uViewportDC;
  if (outside(rw * m.x + rx, cWC, halfWC, r) || outside(rw * m.x - rx, cWC, halfWC, r) ||
      outside(rw * m.y + ry, cWC, halfWC, r) || outside(rw * m.y - ry, cWC, halfWC, r))
    return;
  keptBatches[atomicAdd(setupDispatch.y, 1u)] = b;
  atomicAdd(batchesKept, 1u);
}
