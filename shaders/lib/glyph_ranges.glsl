// Culling's data (tg::render::GlyphCulling). Binding points mirror
// src/render/glyph_culling.h.
#include "lib/bindings.h"

// One tile's glyphs of one dispatch group (tg::render::GlyphRange, std430).
struct GlyphRange {
  vec4 loWC_maxAbsEigenvalue;  // box of the centres; w: largest |eigenvalue|
  vec4 hiWC;
  uvec4 firstCount;            // x: first glyph, y: glyph count
};
layout(std430, binding = TG_SSBO_RANGES) readonly buffer Ranges { GlyphRange ranges[]; };

// Glyphs of range k that pass the FA threshold, written by compact_fa.comp.
layout(std430, binding = TG_SSBO_KEPT_COUNT) buffer KeptCount { uint keptCount[]; };

// Ranges are more than a dispatch's 65535 workgroups along x at 10^8 glyphs.
uint linearWorkGroup() { return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x; }
