#include "render/prism_kinds.h"

#include <stdexcept>

#include "render/renderer.h"

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
    prog.set("uSlabWC", glm::vec2(float(p.slab.lo), float(p.slab.hi)));
  }
  if (changed(&FrameParams::color)) prog.set("uColorMode", int(p.color));
}

bool isPrismKind(GlyphKind k) { return k == GlyphKind::Cylinder || k == GlyphKind::Box; }

const gl::Program& PrismKinds::program(GlyphKind k, const FrameParams& p) {
  if (!isPrismKind(k)) throw std::invalid_argument("PrismKinds::program: not a cylinder or box kind");
  auto& slot = k == GlyphKind::Cylinder ? cylinder_ : box_;
  if (!slot) {
    const auto stages = {gl::StageSource{GL_VERTEX_SHADER, "prism.vert"},
                         gl::StageSource{GL_FRAGMENT_SHADER, "prism.frag"}};
    slot = k == GlyphKind::Cylinder ? std::make_unique<gl::Program>(gl_, lib_, stages, std::vector<std::string_view>{"TG_CYLINDER"})
                                    : std::make_unique<gl::Program>(gl_, lib_, stages);
    setGlyphUniforms(*slot, p, nullptr);
    slot->set("uMdRange", mdRange_);
  }
  return *slot;
}

void PrismKinds::setParams(const FrameParams& p, const FrameParams* old) const {
  for (const auto* prog : {cylinder_.get(), box_.get()})
    if (prog) setGlyphUniforms(*prog, p, old);
}

void PrismKinds::setMdRange(glm::vec2 mdRange) {
  mdRange_ = mdRange;
  for (const auto* prog : {cylinder_.get(), box_.get()})
    if (prog) prog->set("uMdRange", mdRange_);
}

bool PrismKinds::built(GlyphKind k) const { return (k == GlyphKind::Cylinder ? cylinder_ : box_) != nullptr; }

}  // namespace tg::render
