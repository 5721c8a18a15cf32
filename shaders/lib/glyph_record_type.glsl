// The one-glyph record, mirroring tg::tensor::GlyphRecord (std430, 48 bytes),
// and its frame. In the GLSL/C++ subset (lib/glsl_cpp.h); the storage buffer
// that holds the records is lib/glyph_record.glsl's.
struct GlyphRecord {
  vec4 posWC_fa;        // xyz: centre in WC, w: FA
  vec4 eigenvalues_id;  // xyz: signed eigenvalues, descending; w: input index (uint bits)
  vec4 frameWC;         // unit quaternion (x, y, z, w): GC axes -> eigenvectors in WC
};

mat3 quatToMat3(vec4 q) {
  float x = q.x, y = q.y, z = q.z, w = q.w;
  return mat3(1.0f - 2.0f * (y * y + z * z), 2.0f * (x * y + w * z), 2.0f * (x * z - w * y),
              2.0f * (x * y - w * z), 1.0f - 2.0f * (x * x + z * z), 2.0f * (y * z + w * x),
              2.0f * (x * z + w * y), 2.0f * (y * z - w * x), 1.0f - 2.0f * (x * x + y * y));
}
