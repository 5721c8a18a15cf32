#pragma once
// Offscreen targets: the geometry pass's G-buffer and the lit colour.
#include <cstdint>

#include "gl/loader.h"

namespace tg::render {

// The G-buffer's channels as named attachments: what passes declare they
// read and write (render/frame_pass.h), and what a glyph path fills
// (render/glyph_path.h). Albedo, NormalWC, Id and Depth are the geometry
// pass's; Color the lit image; the occluder channels the pre-pass's.
enum class Attachment { Albedo, NormalWC, Id, Depth, Color, OccluderDepth, OccluderPyramid };
inline constexpr int kAttachmentCount = 7;

class GBuffer {
 public:
  GBuffer(const gl::Api& gl, int width, int height);
  ~GBuffer();
  GBuffer(const GBuffer&) = delete;
  GBuffer& operator=(const GBuffer&) = delete;

  // What a width x height G-buffer holds in its textures, from the same
  // format table the constructor allocates: 40 bytes per pixel and the
  // occluder pyramid. Needs no context, so sizes can be checked up front.
  static std::uint64_t bytesFor(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  // Clears id and depth to "empty" and binds the geometry framebuffer;
  // albedo and normal hold what they held where the id says empty.
  void beginGeometry() const;
  // Clears and binds the occluder depth framebuffer (depth only): the
  // superquadric pass's occlusion pre-pass (GlyphRenderer::render).
  void beginOccluders() const;
  // Binds the G-buffer textures to units 0..2 and the colour framebuffer.
  void beginLighting() const;
  // As beginLighting, but fills the lit colour with `background` and binds a
  // framebuffer that also holds the G-buffer depth, read only, under a test
  // that only covered pixels pass (any depth nearer than far). llvmpipe then
  // rejects background pixels before shading them: they keep the fill, as
  // the lighting shader would have written it. Not while the lighting shader
  // samples depth() (shadows): that would read a bound attachment.
  void beginLightingCovered(const float background[4]) const;
  // Restores what beginLightingCovered changed: no depth test, depth writes on.
  void endLighting() const;

  GLuint texture(Attachment a) const { return tex_[int(a)]; }
  GLuint albedo() const { return texture(Attachment::Albedo); }      // RGBA8
  GLuint normalWC() const { return texture(Attachment::NormalWC); }  // RGBA16F: 11-bit mantissa, < 0.03 deg
  GLuint id() const { return texture(Attachment::Id); }              // R32UI
  GLuint depth() const { return texture(Attachment::Depth); }        // DEPTH32F, reversed
  GLuint color() const { return texture(Attachment::Color); }        // RGBA32F, lit
  GLuint occluderDepth() const { return texture(Attachment::OccluderDepth); }  // DEPTH32F, reversed
  // R32F, mip 0 at half size (render/occluder_pyramid.h).
  GLuint occluderPyramid() const { return texture(Attachment::OccluderPyramid); }
  int pyramidWidth() const { return (width_ + 1) / 2; }
  int pyramidHeight() const { return (height_ + 1) / 2; }
  int pyramidLevels() const;
  GLuint colorFramebuffer() const { return fbo_[1]; }

 private:
  // The lighting pass's inputs at their units (shaders/lib/bindings.h).
  void bindLightingInputs() const;
  const gl::Api& gl_;
  int width_, height_;
  GLuint tex_[kAttachmentCount] = {};  // by Attachment
  GLuint fbo_[4] = {};  // geometry, colour, occluders, colour + depth
};

}  // namespace tg::render
