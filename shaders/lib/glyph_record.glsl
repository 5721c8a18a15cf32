// The one-glyph record, mirroring tg::tensor::GlyphRecord (std430, 48 bytes).
#include "lib/bindings.h"
struct GlyphRecord {
  vec4 posWC_fa;        // xyz: centre in WC, w: FA
  vec4 eigenvalues_id;  // xyz: signed eigenvalues, descending; w: input index (uint bits)
  vec4 frameWC;         // unit quaternion (x, y, z, w): GC axes -> eigenvectors in WC
};

layout(std430, binding = TG_SSBO_GLYPHS) readonly buffer Glyphs { GlyphRecord glyphs[]; };

mat3 quatToMat3(vec4 q) {
  float x = q.x, y = q.y, z = q.z, w = q.w;
  return mat3(1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y + w * z), 2.0 * (x * z - w * y),
              2.0 * (x * y - w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z + w * x),
              2.0 * (x * z + w * y), 2.0 * (y * z - w * x), 1.0 - 2.0 * (x * x + y * y));
}
