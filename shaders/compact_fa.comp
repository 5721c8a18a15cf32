#version 450 core
// Order-preserving stream compaction for the FA threshold, run once per
// threshold change: one workgroup per range (at most 256 glyphs), a
// shared-memory prefix sum over "fa >= uFaMin", and the kept glyphs' indices
// written from the range's own first slot. No global scan is needed, and
// every range keeps its glyphs in input order, so draw order and the image
// are those of the unculled frame.
#include "lib/bindings.h"
#include "lib/glyph_record.glsl"
#include "lib/glyph_ranges.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = TG_SSBO_KEPT_INDEX) writeonly buffer KeptIndex { uint keptIndex[]; };

uniform float uFaMin;
uniform int uRangeCount;

shared uint sums[256];

void main() {
  uint k = linearWorkGroup();
  if (k >= uint(uRangeCount)) return;  // uniform per workgroup, so barrier() below is safe
  uint i = gl_LocalInvocationID.x;
  uvec4 fc = ranges[k].firstCount;
  // The FA half of lib/selection.glsl's test, so both agree on every glyph.
  bool keep = i < fc.y && glyphs[fc.x + i].posWC_fa.w >= uFaMin;
  sums[i] = keep ? 1u : 0u;
  barrier();
  // Hillis-Steele inclusive scan: 8 steps for 256 lanes.
  for (uint offset = 1u; offset < 256u; offset <<= 1u) {
    uint add = i >= offset ? sums[i - offset] : 0u;
    barrier();
    sums[i] += add;
    barrier();
  }
  if (keep) keptIndex[fc.x + sums[i] - 1u] = fc.x + i;
  if (i == 255u) keptCount[k] = sums[255];
}
