#version 450 core
// A slice plane's quad (render/slice_plane.h): two triangles from the four
// corners, no vertex buffer.
#include "lib/camera.glsl"

uniform vec4 uCornersWC[4];

out vec3 vPointWC;

void main() {
  const int corner[6] = int[6](0, 1, 2, 0, 2, 3);
  vec3 p = uCornersWC[corner[gl_VertexID]].xyz;
  vPointWC = p;
  gl_Position = uProjVCCC * (uViewWCVC * vec4(p, 1.0));
}
