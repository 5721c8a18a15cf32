#version 450 core
// Tracts (render/tract_item.h): each segment a camera-facing quad, two
// triangles, widened about the streamline by the tube's radius (at least
// half a pixel), its sides along the point tangents so that neighbouring
// segments meet edge to edge. tract.frag shades and depths it as a tube.
#include "lib/bindings.h"
#include "lib/camera.glsl"

// x y z and w: 1 a point, 0 the separator between streamlines (and at both ends).
layout(std430, binding = TG_SSBO_TRACT_POINTS) readonly buffer TractPoints { vec4 tractPointWC[]; };

uniform float uRadiusWC;

out TractFS {
  vec3 posVC;      // on the quad, in the tube's axis plane
  vec3 tangentWC;  // for the direction colour
  float across;    // -1 .. 1 from one side of the tube to the other
  float radiusVC;
} vs;

const int kEnd[6] = int[](0, 0, 1, 1, 0, 1);
const float kSide[6] = float[](-1.0, 1.0, -1.0, -1.0, 1.0, 1.0);

void main() {
  int seg = gl_VertexID / 6, corner = gl_VertexID % 6;
  if (tractPointWC[seg].w == 0.0 || tractPointWC[seg + 1].w == 0.0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // across a separator: outside the clip volume, no area
    return;
  }
  int i = seg + kEnd[corner];
  vec3 p = tractPointWC[i].xyz;
  vec4 prev = tractPointWC[i - 1], next = tractPointWC[i + 1];
  vec3 t = (next.w != 0.0 ? next.xyz : p) - (prev.w != 0.0 ? prev.xyz : p);
  vec3 pVC = (uViewWCVC * vec4(p, 1.0)).xyz;
  vec3 tVC = mat3(uViewWCVC) * t;
  vec3 toEye = uOrtho == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-pVC);
  vec3 side = cross(tVC, toEye);
  float len = length(side);
  side = len > 1e-20 ? side / len : normalize(cross(toEye, abs(toEye.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
  // Half a pixel at this depth: thinner tubes would fall between pixel centres.
  float pixelVC = 2.0 * uRayScaleVC.y / uViewportDC.y * (uOrtho == 1 ? 1.0 : max(-pVC.z, uNearVC));
  float r = max(uRadiusWC, 0.5 * pixelVC);
  vec3 q = pVC + side * (r * kSide[corner]);
  vs.posVC = q;
  vs.tangentWC = t;
  vs.across = kSide[corner];
  vs.radiusVC = r;
  gl_Position = uProjVCCC * vec4(q, 1.0);
}
