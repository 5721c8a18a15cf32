#version 450 core
// Copies the lit glyphs into a host application's framebuffer (the ParaView
// plugin, plugins/paraview): the colour, and the depth re-projected into the
// host's convention, so that the host's own geometry and the glyphs hide each
// other correctly. Pixels without a glyph are discarded. Below an opacity of
// 1 the host blends the colour over what it drew (uOpacity).
//
// In the host's selection passes (VTK's hardware selector) the colour is what
// the pass reads back instead: a constant (the prop, composite or process id
// the selector chose), or the glyph's input point id, its low 24 bits as RGB
// bytes or bits 24..31 in red. VTK 9.2's selector reads the id as written:
// whether a pixel holds any id at all comes from its actor pass.
//
// For a composite (multiblock) input the glyph ids run on over the blocks:
// uBlocks maps an id to its block's flat index (ParaView's composite id, written
// in the composite pass) and the point id within the block.
#include "lib/camera.glsl"

layout(binding = 0) uniform sampler2D uColor;
layout(binding = 1) uniform sampler2D uDepth;  // reversed window depth
layout(binding = 2) uniform usampler2D uId;

uniform vec2 uOriginDC;   // the host viewport's lower-left corner, pixels
uniform vec4 uHostZRow;   // rows 2 and 3 of the host's view -> clip matrix
uniform vec4 uHostWRow;
uniform int uOutput;      // kOutput* below
uniform vec3 uSelectColor;  // kOutputConstant's colour
uniform int uBlockCount;    // 0: one dataset, the ids are its point ids
uniform float uOpacity;     // kOutputLit's alpha: below 1 the host blends it over its frame

layout(std430, binding = 0) readonly buffer BlockTable {
  uvec2 uBlocks[];  // (first glyph id, flat index), ascending ids
};

out vec4 oColor;

const uint kNoGlyph = 0xFFFFFFFFu;
const int kOutputLit = 0, kOutputConstant = 1, kOutputIdLow24 = 2, kOutputIdHigh8 = 3, kOutputComposite = 4;

vec3 bytes(uint v) { return vec3(v & 0xFFu, (v >> 8) & 0xFFu, (v >> 16) & 0xFFu) / 255.0; }

// The last block whose first id is at most `id`.
uvec2 blockOf(uint id) {
  int lo = 0, hi = uBlockCount - 1;
  while (lo < hi) {
    int mid = (lo + hi + 1) / 2;
    if (uBlocks[mid].x <= id) lo = mid; else hi = mid - 1;
  }
  return uBlocks[lo];
}

void main() {
  vec2 fragDC = gl_FragCoord.xy - uOriginDC;
  ivec2 p = ivec2(fragDC);
  uint id = texelFetch(uId, p, 0).r;
  if (id == kNoGlyph) discard;
  vec3 originVC, dirVC;
  rayThroughFragment(fragDC, originVC, dirVC);
  vec4 pVC = vec4(originVC + viewDepthFromWindowDepth(texelFetch(uDepth, p, 0).r) * dirVC, 1.0);
  // The host's clip depth; glDepthRange(0, 1) maps [-1, 1] to [0, 1].
  gl_FragDepth = clamp(0.5 * dot(uHostZRow, pVC) / dot(uHostWRow, pVC) + 0.5, 0.0, 1.0);
  uint pointId = id, flatIndex = 0u;
  if (uBlockCount > 0 && uOutput >= kOutputIdLow24) {  // selection passes only
    uvec2 block = blockOf(id);
    pointId = id - block.x;
    flatIndex = block.y;
  }
  if (uOutput == kOutputConstant) {
    oColor = vec4(uSelectColor, 1.0);
  } else if (uOutput == kOutputComposite) {
    oColor = vec4(bytes(flatIndex), 1.0);  // read as written, as the ids
  } else if (uOutput == kOutputIdLow24) {
    oColor = vec4(bytes(pointId), 1.0);
  } else if (uOutput == kOutputIdHigh8) {
    oColor = vec4(float(pointId >> 24) / 255.0, 0.0, 0.0, 1.0);
  } else {
    oColor = vec4(texelFetch(uColor, p, 0).rgb, uOpacity);
  }
}
