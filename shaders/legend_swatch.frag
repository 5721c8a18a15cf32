#version 450 core
// The legend's filled areas (render::SwatchKind): the panel, a colour bar
// through the glyphs' own colour functions, an underlay's colormap, and the
// DEC key sphere.
#include "lib/color.glsl"

uniform vec2 uViewportDC;
uniform vec4 uRectDC;   // x0, y0, x1, y1; y down from the top
uniform int uKind;      // 0 fill, 1 viridis bar, 2 sign bar, 3 DEC sphere, 4 gray bar
uniform vec2 uRange;    // bars: the colour function's argument at x0 and at x1
uniform vec4 uFill;
uniform mat3 uRotWCVC;  // the camera's rotation, for the sphere

out vec4 oColor;

void main() {
  // From the pixel centre, not an interpolated varying: column i of a bar
  // shows exactly the argument at x = i + 0.5.
  vec2 pDC = vec2(gl_FragCoord.x, uViewportDC.y - gl_FragCoord.y);
  vec2 uv = (pDC - uRectDC.xy) / (uRectDC.zw - uRectDC.xy);
  if (uKind == 0) {
    oColor = uFill;
  } else if (uKind == 1 || uKind == 2 || uKind == 4) {
    float t = mix(uRange.x, uRange.y, uv.x);
    // Gray as slice_plane.frag's: the value itself, clamped.
    oColor = vec4(uKind == 1 ? viridis(t) : uKind == 2 ? signRamp(t) : vec3(clamp(t, 0.0, 1.0)), 1.0);
  } else {
    // The eye-facing hemisphere of a unit sphere: each point shows the colour
    // of a glyph whose principal direction is the sphere's normal there.
    vec2 q = vec2(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0);
    float r = length(q);
    float alpha = clamp((1.0 - r) * 0.5 * (uRectDC.z - uRectDC.x) + 0.5, 0.0, 1.0);
    if (alpha <= 0.0) discard;
    vec3 nVC = vec3(q, sqrt(max(0.0, 1.0 - r * r)));
    oColor = vec4(decColor(transpose(uRotWCVC) * nVC, 1.0), alpha);
  }
}
