#version 450 core
// The tessellated baseline (`--tessellate R`, `bench scale`): what VTK's
// vtkTensorGlyph with a vtkSuperquadricSource draws, as one instanced mesh.
// Instance = glyph record; gl_VertexID indexes an (R + 1) x (R + 1) grid of
// (theta, phi), mapped to the superquadric surface of the glyph's shape:
//   x = c(theta)^a s(phi)^b, y = s(theta)^a s(phi)^b, z = c(phi)^c
// (signed powers), the parametric twin of lib/superquadric.glsl's gauge.
#include "lib/camera.glsl"
#include "lib/glyph_record.glsl"
#include "lib/ellipsoid.glsl"
#include "lib/glyph_size.glsl"
#include "lib/superquadric.glsl"
#include "lib/glyph_color.glsl"
#include "lib/selection.glsl"

uniform float uGamma;
uniform int uResolution;

out TessellatedFS {
  vec3 normalWC;
  flat vec3 color;
  flat uint id;
} vs;

float signedPow(float v, float e) { return sign(v) * pow(abs(v), e); }

void main() {
  gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // culled: outside the clip volume
  GlyphRecord g = glyphs[gl_InstanceID];
  vec4 pf = g.posWC_fa;
  if (!glyphSelected(pf)) return;
  vec3 axes = glyphAxes(g.eigenvalues_id.xyz);
  if (!(max(axes.x, max(axes.y, axes.z)) > 0.0)) return;
  vec4 shape = superquadricShape(g.eigenvalues_id.xyz, uGamma);
  int ax = int(shape.w);
  ivec3 src = ivec3((ax + 1) % 3, (ax + 2) % 3, ax);
  mat3 rotWC = quatToMat3(g.frameWC);
  vec3 e0 = rotWC[src.x] * axes[src.x], e1 = rotWC[src.y] * axes[src.y], e2 = rotWC[src.z] * axes[src.z];

  int i = gl_VertexID % (uResolution + 1), j = gl_VertexID / (uResolution + 1);
  float theta = 6.28318531 * float(i) / float(uResolution), phi = 3.14159265 * float(j) / float(uResolution);
  float sp = signedPow(sin(phi), shape.y);
  vec3 pGC = vec3(signedPow(cos(theta), shape.x) * sp, signedPow(sin(theta), shape.x) * sp,
                  signedPow(cos(phi), shape.z));
  vec3 gradGC;
  superquadricGauge(shape.xyz, pGC, gradGC);
  // Poles and the seam have no gradient direction: fall back to the position.
  if (!(dot(gradGC, gradGC) > 0.0)) gradGC = pGC;

  vec3 pWC = pf.xyz + e0 * pGC.x + e1 * pGC.y + e2 * pGC.z;
  gl_Position = uProjVCCC * (uViewWCVC * vec4(pWC, 1.0));
  vs.normalWC = normalize(e0 / dot(e0, e0) * gradGC.x + e1 / dot(e1, e1) * gradGC.y + e2 / dot(e2, e2) * gradGC.z);
  // No per-point sign colour on the mesh: its glyph colour is that of the other scalar modes.
  vs.color = uColorMode == kColorSign ? vec3(1.0)
                                      : glyphVertexColor(uint(gl_InstanceID), rotWC[0], pf.w, g.eigenvalues_id.xyz, vec3(0.0));
  vs.id = floatBitsToUint(g.eigenvalues_id.w);
}
