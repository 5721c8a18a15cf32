#version 450 core
// An occluder of the superquadric pass's pre-pass (GlyphRenderer::render):
// the pixels whose centre lies inside the glyph's projected outline, at the
// constant depth that ellipsoid.vert's TG_OCCLUDER_DISC variant gives the
// sprite. It reads five inputs and casts no ray, where the exact ellipsoid
// read nineteen; and as it writes no gl_FragDepth, llvmpipe tests depth
// before running it (lp_state_fs.c: early test, late write for a shader that
// discards). On the helix, drawing the occluders in reverse order (front to
// back there) changed nothing measurable: setup, not shading, is the cost.

in OccluderFS {
  flat vec2 centreDC;
  flat vec3 conicDC;  // the outline (p - centre)^T C (p - centre) <= 1: C's xx, xy, yy
} fin;

void main() {
  vec2 d = gl_FragCoord.xy - fin.centreDC;
  // Shrunk by 1% so that float rounding of the conic never puts a pixel whose
  // ray misses the glyph inside: such a pixel would claim an occluder.
  if (!(d.x * d.x * fin.conicDC.x + 2.0 * d.x * d.y * fin.conicDC.y + d.y * d.y * fin.conicDC.z < 0.98)) discard;
}
