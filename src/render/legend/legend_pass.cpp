#include "render/legend/legend_pass.h"

namespace tg::render {

LegendPass::LegendPass(const gl::Api& gl, const gl::ShaderLibrary& lib) : painter_(gl, lib) {}

void LegendPass::draw(const Camera& cam, const LegendParams& p, const LegendInputs& in) {
  layout_ = layoutLegend(p, in, cam, painter_.font(legendTextScale(p, cam.height)));
  painter_.draw(cam, layout_);
}

std::span<const Attachment> LegendPass::writes() const {
  static constexpr Attachment kWrites[] = {Attachment::Color};
  return kWrites;
}

std::unique_ptr<FramePass> makeLegendPass(const gl::Api& gl, const gl::ShaderLibrary& lib) {
  return std::make_unique<LegendPass>(gl, lib);
}

}  // namespace tg::render
