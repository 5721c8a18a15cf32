#version 450 core
// An occluder of the superquadric pass's pre-pass (GlyphRenderer::render):
// the pixels whose centre lies inside the glyph's projected outline, at the
// constant depth that ellipsoid.vert's TG_OCCLUDER_DISC variant gives the
// sprite. Writing no depth, this shader lets llvmpipe test depth before it
// runs (lp_state_fs.c: early test, late write for a shader that discards),
// where the exact ellipsoid's gl_FragDepth made it shade every fragment.

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
