#version 450 core
// The tessellated baseline into the same G-buffer as the ray-cast glyphs:
// interpolated normals, depth from the rasteriser.
in TessellatedFS {
  vec3 normalWC;
  flat vec3 color;
  flat uint id;
} fin;

layout(location = 0) out vec4 oAlbedo;
layout(location = 1) out vec4 oNormalWC;
layout(location = 2) out uint oId;

void main() {
  oAlbedo = vec4(fin.color, 1.0);
  oNormalWC = vec4(normalize(fin.normalWC), 0.0);
  oId = fin.id;
}
