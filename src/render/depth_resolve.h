#pragma once
// The seam's depth (render/glyph_path.h): the deferred passes read the
// G-buffer's DEPTH32F attachment, which neither a compute shader (no image
// stores to depth formats) nor every CPU upload path can write. A glyph path
// that is no raster writes window depth (reversed, 0 where empty) into this
// R32F channel instead, by imageStore or upload(), and resolve() copies it
// into the depth attachment through gl_FragDepth.
//
//   READS  its own R32F channel, target's size
//   WRITES GBuffer::depth() (colour writes masked off)
//
// Held by the path that needs it: the raster path builds none.
#include <cstddef>
#include <span>

#include "gl/program.h"
#include "render/gbuffer.h"

namespace tg::render {

class DepthResolve {
 public:
  DepthResolve(const gl::Api& gl, const gl::ShaderLibrary& lib, int width, int height);
  ~DepthResolve();
  DepthResolve(const DepthResolve&) = delete;
  DepthResolve& operator=(const DepthResolve&) = delete;

  // The R32F channel, for a compute shader's imageStore (GL_R32F).
  GLuint windowDepth() const { return tex_; }
  // Window depths from the CPU, rows bottom first as GL's; width x height values.
  void upload(std::span<const float> windowDepth) const;
  // Into target's depth, which must be of this channel's size, with target's
  // geometry framebuffer bound (GBuffer::beginGeometry); leaves the reversed-Z
  // depth test (GL_GREATER) with depth writes on, as the raster path does.
  void resolve(const GBuffer& target) const;
  std::size_t gpuBytes() const { return std::size_t(width_) * std::size_t(height_) * 4; }

 private:
  const gl::Api& gl_;
  gl::Program program_;
  int width_, height_;
  GLuint tex_ = 0, vao_ = 0;
};

}  // namespace tg::render
