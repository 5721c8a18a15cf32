#include "render/outline_pass.h"

#include <cmath>

#include <glm/trigonometric.hpp>

#include "render/camera_uniforms.h"
#include "shaders/lib/bindings.h"

namespace tg::render {

OutlinePass::OutlinePass(const gl::Api& gl, const gl::ShaderLibrary& lib)
    : gl_(gl), program_(gl, lib, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "outline.frag"}}) {
  gl.CreateVertexArrays(1, &vao_);
}

OutlinePass::~OutlinePass() { gl_.DeleteVertexArrays(1, &vao_); }

std::span<const Attachment> OutlinePass::reads() const {
  static constexpr Attachment kReads[] = {Attachment::Depth, Attachment::NormalWC, Attachment::Id};
  return kReads;
}

std::span<const Attachment> OutlinePass::writes() const {
  static constexpr Attachment kWrites[] = {Attachment::Color};
  return kWrites;
}

void OutlinePass::run(const PassFrame& f) {
  setCameraUniforms(program_, f.cam);
  run(f.target, f.p.outline, f.p.glyph != GlyphKind::Blob);
}

void OutlinePass::run(const GBuffer& target, const OutlineParams& p, bool idEdges) const {
  program_.set("uIdEdges", idEdges ? 1 : 0);
  program_.set("uWidth", float(p.width));
  program_.set("uColor", p.color);
  program_.set("uCosCrease", float(std::cos(glm::radians(p.creaseDeg))));
  gl_.BindFramebuffer(GL_FRAMEBUFFER, target.colorFramebuffer());
  gl_.Viewport(0, 0, target.width(), target.height());
  gl_.Disable(GL_DEPTH_TEST);
  gl_.BindTextureUnit(TG_UNIT_EFFECT_DEPTH, target.depth());
  gl_.BindTextureUnit(TG_UNIT_NORMAL, target.normalWC());
  gl_.BindTextureUnit(TG_UNIT_ID, target.id());
  gl_.Enable(GL_BLEND);
  gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  gl_.UseProgram(program_.id());
  gl_.BindVertexArray(vao_);
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);
  gl_.Disable(GL_BLEND);
  gl::checkError(gl_, "OutlinePass::run");
}

}  // namespace tg::render
