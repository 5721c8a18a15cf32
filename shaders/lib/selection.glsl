// The user's selection, tested on a glyph's centre before any shape work:
// the FA threshold and an optional slab of centres along a WC axis. Shared
// by the sprite stages and the tessellated baseline.
uniform float uFaMin;
uniform int uSlabAxis;  // -1: no slab
uniform vec2 uSlabWC;   // kept: uSlabWC.x <= centre[uSlabAxis] <= uSlabWC.y

bool glyphSelected(vec4 posWC_fa) {
  if (!(posWC_fa.w >= uFaMin)) return false;
  return uSlabAxis < 0 || (posWC_fa[uSlabAxis] >= uSlabWC.x && posWC_fa[uSlabAxis] <= uSlabWC.y);
}
