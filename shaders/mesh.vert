#version 450 core
// Context meshes (render/mesh_item.h): triangles or edges in WC, depth from
// the rasteriser through the same reversed-Z projection as the glyphs.
#include "lib/bindings.h"
#include "lib/camera.glsl"

// Vertices by index (gl_VertexID of an indexed draw): no vertex format to set up.
layout(std430, binding = TG_SSBO_MESH_VERTICES) readonly buffer MeshVertices { float meshPosWC[]; };

out MeshFS {
  vec3 posVC;
} vs;

// The see-through pass draws the mesh twice and keeps the fragments whose
// depth equals the first pass's: both must compute the very same positions.
invariant gl_Position;

void main() {
  int k = 3 * gl_VertexID;
  vec4 pVC = uViewWCVC * vec4(meshPosWC[k], meshPosWC[k + 1], meshPosWC[k + 2], 1.0);
  vs.posVC = pVC.xyz;
  gl_Position = uProjVCCC * pVC;
}
