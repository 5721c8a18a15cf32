#pragma once
// The legend pass: a colour key, an orientation key for dec and a scale bar,
// drawn over the lit image (render/legend_layout.h places them).
//
//   READS   nothing of the G-buffer: the camera, LegendParams and
//           LegendInputs (the md range and scale the glyphs were drawn with).
//   WRITES  GBuffer::color (RGB blended over the lit colour; alpha kept),
//           after the lighting pass and before readback.
//
// GlyphRenderer builds it (through makeLegendPass, handed to its
// constructor) on the first frame with LegendParams::enabled and drops it on
// the first frame without: a frame without a legend runs and holds none of
// this (no programs, no font texture, no buffers).
#include <cstddef>
#include <memory>

#include "gl/program.h"
#include "render/legend_layout.h"
#include "render/frame_pass.h"
#include "render/legend/overlay_painter.h"

namespace tg::render {

class LegendPass final : public FramePass {
 public:
  LegendPass(const gl::Api& gl, const gl::ShaderLibrary& lib);

  // Draws into the framebuffer bound for lighting (GBuffer::beginLighting).
  void draw(const Camera& cam, const LegendParams& p, const LegendInputs& in);
  void run(const PassFrame& f) override {
    draw(f.cam, f.p.legend, legendInputs(f.p, f.ranges));
  }
  std::span<const Attachment> reads() const override { return {}; }
  std::span<const Attachment> writes() const override;
  const LegendLayout& layout() const { return layout_; }  // of the last draw
  std::size_t gpuBytes() const override { return painter_.gpuBytes(); }

 private:
  OverlayPainter painter_;  // the font texture, programs and buffers
  LegendLayout layout_;
};

// The factory GlyphRenderer takes (render/renderer.h).
std::unique_ptr<FramePass> makeLegendPass(const gl::Api& gl, const gl::ShaderLibrary& lib);

}  // namespace tg::render
