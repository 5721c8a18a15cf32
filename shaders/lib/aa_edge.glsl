// Where anti-aliasing resolves its samples (render/antialias_pass.h): a
// pixel whose 3x3 neighbourhood in the frame's id channel holds another id
// (a silhouette against another glyph, context or the background).
layout(binding = TG_UNIT_AA_FRAME_ID) uniform usampler2D uFrameId;

bool aaEdge(ivec2 p) {
  uint id = texelFetch(uFrameId, p, 0).r;
  ivec2 hi = textureSize(uFrameId, 0) - 1;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      if (texelFetch(uFrameId, clamp(p + ivec2(dx, dy), ivec2(0), hi), 0).r != id) return true;
  return false;
}
