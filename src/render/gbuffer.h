#pragma once
// Offscreen targets: the geometry pass's G-buffer and the lit colour.
#include "gl/loader.h"

namespace tg::render {

class GBuffer {
 public:
  GBuffer(const gl::Api& gl, int width, int height);
  ~GBuffer();
  GBuffer(const GBuffer&) = delete;
  GBuffer& operator=(const GBuffer&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  // Clears every channel to "empty" and binds the geometry framebuffer.
  void beginGeometry() const;
  // Binds the G-buffer textures to units 0..2 and the colour framebuffer.
  void beginLighting() const;

  GLuint albedo() const { return tex_[0]; }    // RGBA8
  GLuint normalWC() const { return tex_[1]; }  // RGBA16F: 11-bit mantissa, < 0.03 deg
  GLuint id() const { return tex_[2]; }        // R32UI
  GLuint depth() const { return tex_[3]; }     // DEPTH32F, reversed
  GLuint color() const { return tex_[4]; }     // RGBA32F, lit
  GLuint colorFramebuffer() const { return fbo_[1]; }

 private:
  const gl::Api& gl_;
  int width_, height_;
  GLuint tex_[5] = {};
  GLuint fbo_[2] = {};
};

}  // namespace tg::render
