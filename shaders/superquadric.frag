#version 450 core
// Ray-superquadric intersection per pixel into the same G-buffer as the
// ellipsoids: the ray in GC, seeded at the unit cube, Newton with a kept
// bracket (lib/superquadric.glsl).
#include "lib/bindings.h"
#pragma tg option TG_ITERATION_STATS
#include "lib/camera.glsl"
#include "lib/ellipsoid.glsl"
#include "lib/superquadric.glsl"
#include "lib/superquadric_march.glsl"
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
  vec3 originVC, dirVC;
  rayThroughFragment(gl_FragCoord.xy, originVC, dirVC);
  // Restart at the closest approach to the centre, as for ellipsoids, and
  // march in GC arc length so that eps is relative to the glyph's size.
  float tc = dot(fin.centreVC - originVC, dirVC) / dot(dirVC, dirVC);
  vec3 o = fin.gcFromVC * (originVC + tc * dirVC - fin.centreVC);
  vec3 d = fin.gcFromVC * dirVC;
  float dl = length(d);
  // The shape lies within the sphere of radius superquadricReach in GC: a
  // ray that passes it by (with room for the march's tolerance) cannot hit,
  // and most of a thin glyph's rectangle is such rays.
  // q rounds with |o|, which reaches 1e7 for thin glyphs seen at a slant:
  // the same rounding margin as marchSearchSpan's, so a ray the march would hit
  // is never dropped here.
  vec3 q = o - dot(o, d) / (dl * dl) * d;
  float on = max(max(abs(o.x), abs(o.y)), abs(o.z));
  float reach = superquadricReach(fin.shape) * (1.0 + 1e-3) + 4.0 * uEpsilon + exp2(-19.0) * (on + 2.0);
  vec2 search = marchSearchSpan(fin.shape, o, d / dl, uEpsilon, on);
  // The box's entry is the nearest this glyph can be on the ray: behind the
  // occluders it cannot win the depth test, so it skips the march.
  // Lanes out of reach leave the march's loop at once, whether masked by
  // this `if` or discarded: gallivm's loop end tests the kill mask too
  // (measured the same); the code before and after the loop runs for every
  // fragment either way (lib/superquadric_march.glsl).
  bool inReach = !(dot(q, q) > reach * reach) && search.x <= search.y &&
      !pixelOccluded(ivec2(gl_FragCoord.xy), tc + unitCubeSpan(o, d / dl).x / dl, 4.0 * uEpsilon / dl);
  MarchResult m = MarchResult(false, 0.0, vec3(0.0), 0, 0);
  if (inReach) m = superquadricMarch(fin.shape, o, d / dl, (uNearVC - tc) * dl, search, uMaxIterations, uEpsilon);
#ifdef TG_ITERATION_STATS
  if (m.iterations > 0) {
    atomicAdd(iterStats[0], uint(m.iterations));
    atomicMax(iterStats[1], uint(m.iterations));
    atomicAdd(iterStats[2], 1u);
  }
  if (m.gaugeCalls > 0) atomicAdd(iterStats[3], uint(m.gaugeCalls));
#endif
  if (!m.hit) discard;
  float depth = tc + m.s / dl;
  if (!(depth >= uNearVC) || (uOrtho == 1 && depth > uFarVC)) discard;

  vec3 nVC = transpose(fin.gcFromVC) * m.gradGC;  // inverse transpose of GC -> VC
  vec3 nWC = normalize(transpose(mat3(uViewWCVC)) * nVC);
  gl_FragDepth = windowDepthFromViewDepth(depth);
  oAlbedo = vec4(uColorMode == kColorSign ? signColor(fin.color, o + m.s * d / dl, fin.gcFromVC) : fin.color, 1.0);
  oNormalWC = vec4(nWC, 0.0);
  oId = fin.id;
}
