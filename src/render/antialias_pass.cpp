#include "render/antialias_pass.h"

#include <stdexcept>

#include "shaders/lib/bindings.h"

namespace tg::render {
namespace {

double halton(int k, int base) {
  double f = 1.0, r = 0.0;
  for (int i = k; i > 0; i /= base) {
    f /= base;
    r += f * (i % base);
  }
  return r;
}

}  // namespace

glm::dvec2 sampleOffset(int k) { return {halton(k, 2) - 0.5, halton(k, 3) - 0.5}; }

AntialiasPass::AntialiasPass(const gl::Api& gl, const gl::ShaderLibrary& lib)
    : gl_(gl),
      accumulate_(gl, lib, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "aa_accumulate.frag"}}),
      resolve_(gl, lib, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "aa_resolve.frag"}}) {
  gl.CreateVertexArrays(1, &vao_);
  gl::checkError(gl, "AntialiasPass");
}

AntialiasPass::~AntialiasPass() {
  if (sumFbo_) gl_.DeleteFramebuffers(1, &sumFbo_);
  if (sum_) gl_.DeleteTextures(1, &sum_);
  gl_.DeleteVertexArrays(1, &vao_);
}

void AntialiasPass::allocate(int width, int height) {
  if (sample_ && width_ == width && height_ == height) return;
  sample_ = std::make_unique<GBuffer>(gl_, width, height);
  if (sumFbo_) gl_.DeleteFramebuffers(1, &sumFbo_);
  if (sum_) gl_.DeleteTextures(1, &sum_);
  gl_.CreateTextures(GL_TEXTURE_2D, 1, &sum_);
  gl_.TextureStorage2D(sum_, 1, GL_RGBA32F, width, height);
  gl_.TextureParameteri(sum_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl_.TextureParameteri(sum_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl_.CreateFramebuffers(1, &sumFbo_);
  gl_.NamedFramebufferTexture(sumFbo_, GL_COLOR_ATTACHMENT0, sum_, 0);
  if (gl_.CheckNamedFramebufferStatus(sumFbo_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("AntialiasPass: the samples' sum framebuffer is incomplete");
  width_ = width;
  height_ = height;
}

void AntialiasPass::accumulate(GLuint color, GLuint frameId) const {
  gl_.BindFramebuffer(GL_FRAMEBUFFER, sumFbo_);
  gl_.Viewport(0, 0, width_, height_);
  gl_.Disable(GL_DEPTH_TEST);
  gl_.Enable(GL_BLEND);
  gl_.BlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  gl_.BindTextureUnit(TG_UNIT_AA_SAMPLE, color);
  gl_.BindTextureUnit(TG_UNIT_AA_FRAME_ID, frameId);
  gl_.UseProgram(accumulate_.id());
  gl_.BindVertexArray(vao_);
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);
  gl_.Disable(GL_BLEND);
}

void AntialiasPass::run(const PassFrame& f) {
  if (!f.drawSample) throw std::logic_error("AntialiasPass::run: the frame draws no samples");
  const int samples = f.p.samples;
  allocate(f.target.width(), f.target.height());
  const float zero[4] = {0, 0, 0, 0};
  gl_.ClearNamedFramebufferfv(sumFbo_, GL_COLOR, 0, zero);
  accumulate(f.target.color(), f.target.id());
  for (int k = 1; k < samples; ++k) {
    gl_.BindTextureUnit(TG_UNIT_AA_FRAME_ID, f.target.id());  // the sample's lighting lights only the edges
    f.drawSample(withPixelOffset(f.cam, sampleOffset(k)), *sample_);
    accumulate(sample_->color(), f.target.id());
  }
  gl_.BindFramebuffer(GL_FRAMEBUFFER, f.target.colorFramebuffer());
  gl_.Viewport(0, 0, width_, height_);
  gl_.BindTextureUnit(TG_UNIT_AA_SUM, sum_);
  gl_.BindTextureUnit(TG_UNIT_AA_FRAME_ID, f.target.id());
  resolve_.set("uSamples", float(samples));
  gl_.UseProgram(resolve_.id());
  gl_.BindVertexArray(vao_);
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);
  gl::checkError(gl_, "AntialiasPass::run");
}

std::span<const Attachment> AntialiasPass::reads() const {
  static constexpr Attachment kReads[] = {Attachment::Id, Attachment::Color};
  return kReads;
}

std::span<const Attachment> AntialiasPass::writes() const {
  static constexpr Attachment kWrites[] = {Attachment::Color};
  return kWrites;
}

std::size_t AntialiasPass::gpuBytes() const {
  if (!sample_) return 0;
  return std::size_t(GBuffer::bytesFor(width_, height_)) + std::size_t(width_) * std::size_t(height_) * 16;
}

}  // namespace tg::render
