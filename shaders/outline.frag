#version 450 core
// Silhouette and crease lines (render/outline_pass.h): the coverage of the
// line at this pixel, blended over the lit colour.
#include "lib/bindings.h"
#include "lib/camera.glsl"
#include "lib/view_position.glsl"

layout(binding = TG_UNIT_EFFECT_DEPTH) uniform sampler2D uDepth;  // reversed window depth
layout(binding = TG_UNIT_NORMAL) uniform sampler2D uNormalWC;
layout(binding = TG_UNIT_ID) uniform usampler2D uId;

uniform float uWidth;      // pixels
uniform vec4 uColor;
uniform float uCosCrease;  // cosine of the crease angle
// 0 where an id is no surface's own (a blob's dominant bump): ids then meet
// on smooth seams, and only the depth jump and the crease find edges there.
uniform int uIdEdges;

out vec4 oColor;

const uint kNoGlyph = 0xFFFFFFFFu;
// A pixel of the same id further behind p's tangent plane than this
// fraction of p's depth is a fold, not the same sheet of surface.
const float kDepthJump = 0.02;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  uint id = texelFetch(uId, p, 0).r;
  if (id == kNoGlyph) discard;  // lines lie on the glyph in front
  float zp = texelFetch(uDepth, p, 0).r;
  vec3 posVC = positionVC(gl_FragCoord.xy, zp);
  vec3 n = normalize(texelFetch(uNormalWC, p, 0).xyz);
  vec3 nVC = normalize(mat3(uViewWCVC) * n);
  ivec2 size = ivec2(uViewportDC);
  int reach = int(ceil(uWidth));
  float coverage = 0.0;
  for (int y = -reach; y <= reach; ++y)
    for (int x = -reach; x <= reach; ++x) {
      ivec2 q = p + ivec2(x, y);
      if ((x == 0 && y == 0) || any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
      float reachHere = clamp(uWidth + 1.0 - length(vec2(x, y)), 0.0, 1.0);
      if (reachHere <= coverage) continue;
      uint idq = texelFetch(uId, q, 0).r;
      bool edge;
      if (idq == kNoGlyph) {
        edge = true;
      } else {
        float zq = texelFetch(uDepth, q, 0).r;
        if (zq > zp) continue;  // q is in front: the line is on its side
        if (idq != id && uIdEdges == 1) {
          edge = true;
        } else {
          vec3 nq = normalize(texelFetch(uNormalWC, q, 0).xyz);
          vec3 o, d;
          rayThroughFragment(vec2(q) + 0.5, o, d);
          float facing = dot(nVC, d);
          // Depth of the ray through q at p's tangent plane.
          float planeDepth = abs(facing) > 1e-3 ? dot(nVC, posVC - o) / facing : 1e30;
          edge = dot(n, nq) < uCosCrease ||
                 viewDepthFromWindowDepth(zq) - planeDepth > kDepthJump * (-posVC.z);
        }
      }
      if (edge) coverage = reachHere;
    }
  if (coverage <= 0.0) discard;
  oColor = vec4(uColor.rgb, uColor.a * coverage);
}
