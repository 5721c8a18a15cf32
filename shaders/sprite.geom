#version 450 core
// Expands the glyph's point into its rectangle. Point sprites cannot do this:
// their size is capped (255 px on llvmpipe, GL_POINT_SIZE_RANGE), and a glyph
// near the camera, or one crossing the eye plane, needs up to the whole
// viewport. The rectangle itself is computed in the vertex stage.
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

in SpriteVS {
  flat int visible;
  flat vec4 rectNDC;
  flat float quadDepth;
  flat vec3 centreVC;
  flat mat3 gcFromVC;
  flat vec3 color;
  flat uint id;
} gin[];

out SpriteFS {
  flat vec3 centreVC;
  flat mat3 gcFromVC;
  flat vec3 color;
  flat uint id;
} gout;

void main() {
  if (gin[0].visible == 0) return;
  vec4 r = gin[0].rectNDC;
  vec2 corners[4] = vec2[4](r.xy, r.zy, r.xw, r.zw);
  for (int k = 0; k < 4; ++k) {
    gl_Position = vec4(corners[k], gin[0].quadDepth, 1.0);
    gout.centreVC = gin[0].centreVC;
    gout.gcFromVC = gin[0].gcFromVC;
    gout.color = gin[0].color;
    gout.id = gin[0].id;
    EmitVertex();
  }
  EndPrimitive();
}
