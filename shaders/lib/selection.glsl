// The user's selection, tested on a glyph's centre before any shape work:
// the FA threshold and an optional slab of centres across a WC direction
// (a world axis, or a grid's slice on an oblique grid). Shared by the
// sprite stages and the tessellated baseline.
uniform float uFaMin;
uniform int uSlabAxis;     // -1: no slab
uniform vec3 uSlabNormal;  // unit; a world axis's exactly, so that its dot is that coordinate
uniform vec2 uSlabWC;      // kept: uSlabWC.x <= dot(centre, uSlabNormal) <= uSlabWC.y

bool glyphSelected(vec4 posWC_fa) {
  if (!(posWC_fa.w >= uFaMin)) return false;
  float d = dot(vec3(posWC_fa), uSlabNormal);
  return uSlabAxis < 0 || (d >= uSlabWC.x && d <= uSlabWC.y);
}
