#include "render/kind_programs.h"

#include "render/color_scalar.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace tg::render {

void setGlyphUniforms(const gl::Program& prog, const FrameParams& p, const FrameParams* old) {
  // Only what changed: a slider moves one value, and each uniform update
  // costs a driver call (the viewer reports the total per change).
  auto changed = [&](auto member) { return !old || !(old->*member == p.*member); };
  if (changed(&FrameParams::scale)) prog.set("uScale", float(p.scale));
  if (changed(&FrameParams::sizing)) {
    prog.set("uMagnitude", int(p.sizing.magnitude));
    prog.set("uLambda0", float(p.sizing.lambda0));
    prog.set("uMaxRadiusWC", float(p.sizing.maxRadiusWC));
  }
  if (changed(&FrameParams::faMin)) prog.set("uFaMin", float(p.faMin));
  if (changed(&FrameParams::slab)) {
    prog.set("uSlabAxis", p.slab.axis);
    prog.set("uSlabNormal", glm::vec3(p.slab.direction()));
    prog.set("uSlabWC", glm::vec2(float(p.slab.lo), float(p.slab.hi)));
  }
  if (changed(&FrameParams::color)) prog.set("uColorMode", int(p.color));
  if (changed(&FrameParams::color) || changed(&FrameParams::colormap))
    prog.set("uColormap", int(p.colormap.value_or(defaultColormap(p.color))));
  if (changed(&FrameParams::colorTable)) prog.set("uColorTable", p.colorTable ? 1 : 0);
}

const gl::Program& KindPrograms::program(GlyphKind k, const FrameParams& p) {
  const GlyphKindInfo& kind = glyphKind(k);
  if (kind.draw != KindDraw::ClosedForm)
    throw std::invalid_argument("KindPrograms::program: " + std::string(kind.name) + " is no closed-form kind");
  auto& slot = programs_[std::size_t(k)];
  if (!slot) {
    const auto stages = {gl::StageSource{GL_VERTEX_SHADER, kind.vertex},
                         gl::StageSource{GL_FRAGMENT_SHADER, kind.fragment}};
    std::vector<std::string_view> on;
    if (!kind.option.empty()) on.push_back(kind.option);
    slot = std::make_unique<gl::Program>(gl_, lib_, stages, std::move(on));
    setGlyphUniforms(*slot, p, nullptr);
    slot->set("uColorWindow", colorWindow_);
  }
  return *slot;
}

void KindPrograms::setParams(const FrameParams& p, const FrameParams* old) const {
  for (const auto& prog : programs_)
    if (prog) setGlyphUniforms(*prog, p, old);
}

void KindPrograms::setColorWindow(glm::vec2 window) {
  colorWindow_ = window;
  for (const auto& prog : programs_)
    if (prog) prog->set("uColorWindow", colorWindow_);
}

}  // namespace tg::render
