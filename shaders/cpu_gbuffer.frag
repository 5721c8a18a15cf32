#version 450 core
// The CPU glyph path's G-buffer (render/cpu_glyphs.h): the caster wrote each
// pixel's window depth, record and normal; this pass writes them into the
// G-buffer's attachments and takes the albedo and id from the record with the
// raster path's own colour code (ellipsoid.vert, lib/color.glsl), so that
// the colour maths stays on one side. Empty pixels are discarded: they keep
// what GBuffer::beginGeometry cleared.
#include "lib/bindings.h"
#include "lib/camera.glsl"
#include "lib/glyph_record.glsl"
#include "lib/ellipsoid.glsl"
#include "lib/glyph_size.glsl"
#include "lib/glyph_color.glsl"

// Buffer textures, a texel per pixel, rows bottom first (render/cast_targets.h).
layout(binding = TG_UNIT_CPU_DEPTH) uniform samplerBuffer uWindowDepth;
layout(binding = TG_UNIT_CPU_RECORD) uniform usamplerBuffer uRecord;
layout(binding = TG_UNIT_CPU_NORMAL) uniform samplerBuffer uCastNormalWC;
layout(binding = TG_UNIT_CPU_HIT_GC) uniform samplerBuffer uHitGC;
uniform int uCastWidth;

layout(location = 0) out vec4 oAlbedo;
layout(location = 1) out vec4 oNormalWC;
layout(location = 2) out uint oId;

// The bound chunk of the records and colour scalars (render/cast_targets.h,
// RecordChunk): one draw per chunk, each writing the pixels of its records.
uniform int uRecordBase;
uniform int uRecordCount;

void main() {
  ivec2 xy = ivec2(gl_FragCoord.xy);
  int p = xy.y * uCastWidth + xy.x;
  uint r = texelFetch(uRecord, p).r;
  if (r == 0u) discard;
  uint index = r - 1u - uint(uRecordBase);  // wraps past the chunk for records before it
  if (index >= uint(uRecordCount)) discard;
  GlyphRecord g = glyphs[index];
  mat3 rotWC = quatToMat3(g.frameWC);
  vec3 color = glyphVertexColor(index, rotWC[0], g.posWC_fa.w, g.eigenvalues_id.xyz, g.eigenvalues_id.xyz);
  if (uColorMode == kColorSign) {
    mat3 gcFromVC = ellipsoidGcFromVC(mat3(uViewWCVC) * rotWC, glyphAxes(g.eigenvalues_id.xyz));
    color = signColor(color, texelFetch(uHitGC, p).xyz, gcFromVC);
  }
  gl_FragDepth = texelFetch(uWindowDepth, p).r;
  oAlbedo = vec4(color, 1.0);
  oNormalWC = vec4(texelFetch(uCastNormalWC, p).xyz, 0.0);
  oId = floatBitsToUint(g.eigenvalues_id.w);
}
