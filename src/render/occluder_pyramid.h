#pragma once
// The occluder depth pyramid: mip k of GBuffer::occluderPyramid() holds, per
// texel, the farthest occluder depth over 2^(k+1) x 2^(k+1) pixels
// (shaders/occluder_pyramid.comp), so that the superquadric vertex stage can
// cull a glyph wholly behind the occluders with four fetches
// (shaders/lib/occlusion.glsl; Greene et al. 1993, hierarchical Z).
#include "gl/program.h"
#include "render/gbuffer.h"

namespace tg::render {

class OccluderPyramid {
 public:
  OccluderPyramid(const gl::Api& gl, const gl::ShaderLibrary& lib);
  // From target's occluder depth, every level; leaves the pyramid bound to
  // texture unit TG_UNIT_OCCLUDER_PYRAMID and the depth to TG_UNIT_OCCLUDER_DEPTH (shaders/lib/bindings.h).
  void build(const GBuffer& target) const;
  // The same for any occluder depth texture (`width` x `height`) and a
  // pyramid of `levels` levels at half its size (the shadow pass's own).
  void build(GLuint depth, GLuint pyramid, int width, int height, int levels) const;
  static int levelsFor(int width, int height);

  // Mirrored by shaders/lib/occlusion.glsl.

 private:
  const gl::Api& gl_;
  gl::Program fromDepth_, fromFiner_;  // level 0; the levels above it
};

}  // namespace tg::render
