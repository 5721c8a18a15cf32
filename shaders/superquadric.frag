#version 450 core
// Ray-superquadric intersection per pixel into the same G-buffer as the
// ellipsoids: the ray in GC, seeded at the unit cube, Newton with a kept
// bracket (lib/superquadric_cast.glsl).
#include "lib/bindings.h"
#pragma tg option TG_ITERATION_STATS
#include "lib/camera.glsl"
#include "lib/ellipsoid.glsl"
#include "lib/superquadric.glsl"
#include "lib/superquadric_march.glsl"
#include "lib/superquadric_cast.glsl"
#include "lib/color.glsl"
#include "lib/occlusion.glsl"

uniform int uMaxIterations;
uniform float uEpsilon;
uniform int uColorMode;

in SuperquadricFS {
  flat vec3 centreVC;
  flat mat3 gcFromVC;
  flat vec3 shape;
  flat vec3 color;  // with uColorMode kColorSign, the sign weights in GC (lib/color.glsl)
  flat uint id;
} fin;

#ifdef TG_ITERATION_STATS
// Compiled in only when statistics are asked for: Newton iterations' [0]
// sum, [1] max and [2] pixels; [3] the march's gauge calls over all fragments.
layout(std430, binding = TG_SSBO_ITERATION_STATS) buffer IterationStats { uint iterStats[4]; };
#endif

layout(depth_less) out float gl_FragDepth;
layout(location = 0) out vec4 oAlbedo;
layout(location = 1) out vec4 oNormalWC;
layout(location = 2) out uint oId;

void main() {
  SuperquadricRay r = superquadricRay(gl_FragCoord.xy, fin.centreVC, fin.gcFromVC, fin.shape, uEpsilon);
  // The box's entry is the nearest this glyph can be on the ray: behind the
  // occluders it cannot win the depth test, so it skips the march.
  // Lanes out of reach leave the march's loop at once, whether masked by
  // this `if` or discarded: gallivm's loop end tests the kill mask too
  // (measured the same); the code before and after the loop runs for every
  // fragment either way (lib/superquadric_march.glsl).
  bool inReach = r.inReach && !pixelOccluded(ivec2(gl_FragCoord.xy), superquadricEntryVC(r), 4.0 * uEpsilon / r.dl);
  MarchResult m = MarchResult(false, 0.0, vec3(0.0), 0, 0);
  if (inReach) m = marchSuperquadricRay(r, fin.shape, uMaxIterations, uEpsilon);
#ifdef TG_ITERATION_STATS
  if (m.iterations > 0) {
    atomicAdd(iterStats[0], uint(m.iterations));
    atomicMax(iterStats[1], uint(m.iterations));
    atomicAdd(iterStats[2], 1u);
  }
  if (m.gaugeCalls > 0) atomicAdd(iterStats[3], uint(m.gaugeCalls));
#endif
  float depth;
  if (!superquadricHitDepth(r, m, depth)) discard;
  gl_FragDepth = windowDepthFromViewDepth(depth);
  oAlbedo = vec4(uColorMode == kColorSign ? signColor(fin.color, superquadricHitGC(r, m), fin.gcFromVC) : fin.color, 1.0);
  oNormalWC = vec4(superquadricNormalWC(fin.gcFromVC, m.gradGC), 0.0);
  oId = fin.id;
}
