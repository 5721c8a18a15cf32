// The glyph records' storage buffer (the record: lib/glyph_record_type.glsl).
#include "lib/bindings.h"
#include "lib/glyph_record_type.glsl"

layout(std430, binding = TG_SSBO_GLYPHS) readonly buffer Glyphs { GlyphRecord glyphs[]; };
