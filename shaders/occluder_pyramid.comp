#version 450 core
// One level of the occluder depth pyramid (render/occluder_pyramid.h): each
// texel holds the farthest occluder depth (the smallest window depth, as Z is
// reversed) of the 2x2 texels under it. Mip sizes round down, so the last
// texel of a row or column also takes the odd source texel beyond it, and
// every pixel of the image lies under exactly one texel of each level.
// TG_FROM_DEPTH: level 0, from the occluder depth texture; otherwise from the
// level below. Two programs rather than a uniform: llvmpipe would run both
// fetches for every texel.
#include "lib/bindings.h"
#pragma tg option TG_FROM_DEPTH
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = TG_UNIT_OCCLUDER_DEPTH) uniform sampler2D uOccluderDepth;  // the source of level 1
layout(r32f, binding = TG_IMAGE_PYRAMID_FINER) uniform readonly image2D uFiner;
layout(r32f, binding = TG_IMAGE_PYRAMID_COARSER) uniform writeonly image2D uCoarser;

float finer(ivec2 q) {
#ifdef TG_FROM_DEPTH
  return texelFetch(uOccluderDepth, q, 0).r;
#else
  return imageLoad(uFiner, q).r;
#endif
}

void main() {
  ivec2 size = imageSize(uCoarser);
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, size))) return;
#ifdef TG_FROM_DEPTH
  ivec2 finerSize = textureSize(uOccluderDepth, 0);
#else
  ivec2 finerSize = imageSize(uFiner);
#endif
  ivec2 lo = 2 * p;
  ivec2 hi = mix(2 * p + 1, finerSize - 1, equal(p, size - 1));
  float farthest = 1.0;
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) farthest = min(farthest, finer(ivec2(x, y)));
  imageStore(uCoarser, p, vec4(farthest));
}
