#include "render/lighting_pass.h"

#include <array>
#include <string_view>
#include <vector>

#include "render/camera_uniforms.h"
#include "render/shadow_pass.h"

namespace tg::render {
namespace {

constexpr std::array kReads = {Attachment::Albedo, Attachment::NormalWC, Attachment::Id, Attachment::Depth};
constexpr std::array kWrites = {Attachment::Color};

}  // namespace

LightingPass::LightingPass(const gl::Api& gl, const gl::ShaderLibrary& lib)
    : gl_(gl), lib_(lib), lighting_(gl, lib, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "lighting.frag"}}) {
  gl.CreateVertexArrays(1, &vao_);
}

LightingPass::~LightingPass() { gl_.DeleteVertexArrays(1, &vao_); }

std::span<const Attachment> LightingPass::reads() const { return kReads; }
std::span<const Attachment> LightingPass::writes() const { return kWrites; }

void LightingPass::setParams(const FrameParams& p, const FrameParams* old) {
  auto changed = [&](auto member) { return !old || !(old->*member == p.*member); };
  if (changed(&FrameParams::background)) {
    lighting_.set("uBackground", p.background);
    if (variant_) variant_->set("uBackground", p.background);
  }
  if (changed(&FrameParams::light)) {
    setLighting(lighting_, p);
    if (variant_) setLighting(*variant_, p);
  }
}

void LightingPass::setLighting(const gl::Program& prog, const FrameParams& p) const {
  prog.set("uKeyDirVC", p.light.keyDirVC);
  prog.set("uLightMix", glm::vec4(p.light.ambient, p.light.head, p.light.key, p.light.specular));
  prog.set("uShininess", p.light.shininess);
}

const gl::Program& LightingPass::programFor(const FrameParams& p, bool shadows) {
  const int key = (p.ao.enabled ? 1 : 0) | (shadows ? 2 : 0);
  if (key == 0) {
    variant_.reset();
    return lighting_;
  }
  if (!variant_ || variantKey_ != key) {
    std::vector<std::string_view> on;
    if (key & 1) on.push_back("TG_AO");
    if (key & 2) on.push_back("TG_SHADOWS");
    variant_ = std::make_unique<gl::Program>(
        gl_, lib_,
        std::initializer_list<gl::StageSource>{{GL_VERTEX_SHADER, "fullscreen.vert"},
                                               {GL_FRAGMENT_SHADER, "lighting.frag"}},
        std::move(on));
    variantKey_ = key;
    variant_->set("uBackground", p.background);
    setLighting(*variant_, p);
  }
  return *variant_;
}

void LightingPass::run(const PassFrame& f) {
  const bool shadows = f.shadow != nullptr;
  const gl::Program& lighting = programFor(f.p, shadows);
  // Shadows sample the G-buffer depth: it cannot be the attachment too.
  if (shadows) f.target.beginLighting();
  else f.target.beginLightingCovered(&f.p.background[0]);
  setCameraUniforms(lighting, f.cam);
  lighting.set("uEdgesOnly", f.edgesOnly ? 1 : 0);
  if (shadows) f.shadow->bindForLighting(lighting, f.cam, f.shadow->light(), f.p.shadow, f.target);
  gl_.UseProgram(lighting.id());
  gl_.BindVertexArray(vao_);
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);
  f.target.endLighting();
}

}  // namespace tg::render
