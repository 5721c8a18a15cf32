#include "render/gbuffer.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "shaders/lib/bindings.h"

namespace tg::render {
namespace {

struct Format {
  GLenum format;
  int bytes;  // per texel
};
// By Attachment: albedo, normal, id, depth, lit colour, occluder depth; then the pyramid.
constexpr Format kTargets[6] = {{GL_RGBA8, 4}, {GL_RGBA16F, 8}, {GL_R32UI, 4}, {GL_DEPTH_COMPONENT32F, 4},
                                {GL_RGBA32F, 16}, {GL_DEPTH_COMPONENT32F, 4}};
constexpr Format kPyramid = {GL_R32F, 4};

int levelsFor(int w, int h) {
  int levels = 1;  // down to 1 x 1
  while ((std::max(w, h) >> levels) > 0) ++levels;
  return levels;
}

}  // namespace

std::uint64_t GBuffer::bytesFor(int width, int height) {
  std::uint64_t perPixel = 0;
  for (const Format& f : kTargets) perPixel += std::uint64_t(f.bytes);
  std::uint64_t total = perPixel * std::uint64_t(width) * std::uint64_t(height);
  const int pw = (width + 1) / 2, ph = (height + 1) / 2;
  for (int l = 0; l < levelsFor(pw, ph); ++l)
    total += std::uint64_t(kPyramid.bytes) * std::uint64_t(std::max(1, pw >> l)) * std::uint64_t(std::max(1, ph >> l));
  return total;
}

GBuffer::GBuffer(const gl::Api& gl, int width, int height) : gl_(gl), width_(width), height_(height) {
  GLint maxSize = 0;
  gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (width < 1 || height < 1 || width > maxSize || height > maxSize)
    throw std::runtime_error("GBuffer: image size " + std::to_string(width) + "x" + std::to_string(height) +
                             " outside 1.." + std::to_string(maxSize));
  gl.CreateTextures(GL_TEXTURE_2D, 6, tex_);
  for (int k = 0; k < 6; ++k) {
    gl.TextureStorage2D(tex_[k], 1, kTargets[k].format, width, height);
    // Nearest: an integer texture with the default linear filter is
    // incomplete, and texelFetch from it silently returns zero.
    gl.TextureParameteri(tex_[k], GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TextureParameteri(tex_[k], GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  gl.CreateTextures(GL_TEXTURE_2D, 1, &tex_[int(Attachment::OccluderPyramid)]);
  gl.TextureStorage2D(occluderPyramid(), pyramidLevels(), kPyramid.format, pyramidWidth(), pyramidHeight());
  gl.CreateFramebuffers(4, fbo_);
  for (int k = 0; k < 3; ++k) gl.NamedFramebufferTexture(fbo_[0], GL_COLOR_ATTACHMENT0 + k, tex_[k], 0);  // albedo, normal, id
  gl.NamedFramebufferTexture(fbo_[0], GL_DEPTH_ATTACHMENT, depth(), 0);
  const GLenum draw[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  gl.NamedFramebufferDrawBuffers(fbo_[0], 3, draw);
  gl.NamedFramebufferTexture(fbo_[1], GL_COLOR_ATTACHMENT0, color(), 0);
  gl.NamedFramebufferDrawBuffers(fbo_[1], 1, draw);
  const GLenum none = GL_NONE;
  gl.NamedFramebufferTexture(fbo_[2], GL_DEPTH_ATTACHMENT, occluderDepth(), 0);
  gl.NamedFramebufferDrawBuffers(fbo_[2], 1, &none);
  gl.NamedFramebufferTexture(fbo_[3], GL_COLOR_ATTACHMENT0, color(), 0);
  gl.NamedFramebufferTexture(fbo_[3], GL_DEPTH_ATTACHMENT, depth(), 0);
  gl.NamedFramebufferDrawBuffers(fbo_[3], 1, draw);
  for (GLuint f : fbo_)
    if (gl.CheckNamedFramebufferStatus(f, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("GBuffer: framebuffer incomplete");
  gl::checkError(gl, "GBuffer");
}

GBuffer::~GBuffer() {
  gl_.DeleteFramebuffers(4, fbo_);
  gl_.DeleteTextures(kAttachmentCount, tex_);
}

void GBuffer::beginGeometry() const {
  gl_.BindFramebuffer(GL_FRAMEBUFFER, fbo_[0]);
  gl_.Viewport(0, 0, width_, height_);
  // Albedo and normal are not cleared: every G-buffer writer writes all
  // three colours, and every reader (lighting, AO, outlines, readback)
  // reads them only where the id is a glyph's or a context item's.
  const GLuint noGlyph[4] = {0xFFFFFFFFu, 0, 0, 0};
  const float farDepth = 0.0f;  // reversed Z
  gl_.ClearNamedFramebufferuiv(fbo_[0], GL_COLOR, 2, noGlyph);
  gl_.ClearNamedFramebufferfv(fbo_[0], GL_DEPTH, 0, &farDepth);
}

int GBuffer::pyramidLevels() const { return levelsFor(pyramidWidth(), pyramidHeight()); }

void GBuffer::beginOccluders() const {
  gl_.BindFramebuffer(GL_FRAMEBUFFER, fbo_[2]);
  gl_.Viewport(0, 0, width_, height_);
  const float farDepth = 0.0f;  // reversed Z
  gl_.ClearNamedFramebufferfv(fbo_[2], GL_DEPTH, 0, &farDepth);
}

void GBuffer::bindLightingInputs() const {
  gl_.BindTextureUnit(TG_UNIT_ALBEDO, albedo());
  gl_.BindTextureUnit(TG_UNIT_NORMAL, normalWC());
  gl_.BindTextureUnit(TG_UNIT_ID, id());
}

void GBuffer::beginLighting() const {
  gl_.BindFramebuffer(GL_FRAMEBUFFER, fbo_[1]);
  gl_.Viewport(0, 0, width_, height_);
  bindLightingInputs();
}

void GBuffer::beginLightingCovered(const float background[4]) const {
  gl_.BindFramebuffer(GL_FRAMEBUFFER, fbo_[3]);
  gl_.Viewport(0, 0, width_, height_);
  bindLightingInputs();
  gl_.ClearNamedFramebufferfv(fbo_[3], GL_COLOR, 0, background);
  // fullscreen.vert draws at window depth 0, the far value (reversed Z):
  // it passes GL_LESS wherever a glyph or context item wrote depth, as
  // those passes' GL_GREATER test against the cleared 0 only lets nearer
  // depths in, and nowhere else.
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_LESS);
  gl_.DepthMask(GL_FALSE);
}

void GBuffer::endLighting() const {
  gl_.Disable(GL_DEPTH_TEST);
  // The depth clears of the next frame (ClearNamedFramebufferfv) obey the mask.
  gl_.DepthMask(GL_TRUE);
}

}  // namespace tg::render
