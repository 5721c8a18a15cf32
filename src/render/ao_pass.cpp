#include "render/ao_pass.h"

#include <stdexcept>

#include "render/camera_uniforms.h"
#include "shaders/lib/bindings.h"

namespace tg::render {

std::span<const Attachment> AoPass::reads() const {
  static constexpr Attachment kReads[] = {Attachment::Depth, Attachment::NormalWC, Attachment::Id};
  return kReads;
}

AoPass::AoPass(const gl::Api& gl, const gl::ShaderLibrary& lib)
    : gl_(gl),
      occlusion_(gl, lib, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "ao.frag"}}),
      blur_(gl, lib, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "ao_blur.frag"}}) {
  gl.CreateVertexArrays(1, &vao_);
}

AoPass::~AoPass() {
  release();
  gl_.DeleteVertexArrays(1, &vao_);
}

void AoPass::release() {
  if (!tex_[0]) return;
  gl_.DeleteFramebuffers(2, fbo_);
  gl_.DeleteTextures(2, tex_);
  tex_[0] = tex_[1] = fbo_[0] = fbo_[1] = 0;
  width_ = height_ = 0;
}

void AoPass::allocate(int width, int height) {
  release();
  gl_.CreateTextures(GL_TEXTURE_2D, 2, tex_);
  gl_.CreateFramebuffers(2, fbo_);
  const GLenum draw = GL_COLOR_ATTACHMENT0;
  for (int k = 0; k < 2; ++k) {
    gl_.TextureStorage2D(tex_[k], 1, GL_R16F, width, height);
    gl_.TextureParameteri(tex_[k], GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl_.TextureParameteri(tex_[k], GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_.NamedFramebufferTexture(fbo_[k], GL_COLOR_ATTACHMENT0, tex_[k], 0);
    gl_.NamedFramebufferDrawBuffers(fbo_[k], 1, &draw);
    if (gl_.CheckNamedFramebufferStatus(fbo_[k], GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("AoPass: framebuffer incomplete");
  }
  width_ = width;
  height_ = height;
}

void AoPass::run(const Camera& cam, const GBuffer& target, const AoParams& p, double radiusWC) {
  if (target.width() != width_ || target.height() != height_) allocate(target.width(), target.height());
  gl_.Disable(GL_DEPTH_TEST);
  gl_.Viewport(0, 0, width_, height_);
  gl_.BindVertexArray(vao_);
  gl_.BindTextureUnit(TG_UNIT_EFFECT_DEPTH, target.depth());
  gl_.BindTextureUnit(TG_UNIT_NORMAL, target.normalWC());
  gl_.BindTextureUnit(TG_UNIT_ID, target.id());

  setCameraUniforms(occlusion_, cam);
  occlusion_.set("uRadiusVC", float(radiusWC));  // a rigid view: world and view units agree
  occlusion_.set("uStrength", float(p.strength));
  occlusion_.set("uSamples", p.samples);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, fbo_[0]);
  gl_.UseProgram(occlusion_.id());
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);

  setCameraUniforms(blur_, cam);
  blur_.set("uRadiusVC", float(radiusWC));
  gl_.BindTextureUnit(TG_UNIT_AO_RAW, tex_[0]);  // the raw occlusion, for the blur
  gl_.BindFramebuffer(GL_FRAMEBUFFER, fbo_[1]);
  gl_.UseProgram(blur_.id());
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);
  gl_.BindTextureUnit(TG_UNIT_AO, tex_[1]);
  gl::checkError(gl_, "AoPass::run");
}

}  // namespace tg::render
