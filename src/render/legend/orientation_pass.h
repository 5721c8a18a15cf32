#pragma once
// The orientation letters: at the middle of each image edge, the anatomical
// direction the image runs towards there (R/L, A/P, S/I, two letters on an
// oblique view; view/anatomy.h), as Slicer's and mrview's slice views label
// theirs. Text through the legend's font and painter (render/legend/overlay_painter.h).
//
//   READS   nothing of the G-buffer: the camera's axes, LegendParams' text
//           scale and, with a legend, where its panel lies.
//   WRITES  GBuffer::color (RGB blended over the lit colour; alpha kept),
//           after the lighting pass and before the legend.
//
// GlyphRenderer builds it (through makeOrientationPass, handed to its
// constructor) on the first frame with FrameParams::orientationLetters and
// drops it on the first frame without.
#include <cstddef>
#include <memory>

#include "render/frame_pass.h"
#include "render/legend_layout.h"
#include "render/legend/overlay_painter.h"

namespace tg::render {

// GL-free: the four letters' labels, each on a dark backing swatch, inset
// from the middle of its edge: left, right, top, bottom, in that order
// (labels[k] on swatches[k]). A letter that would meet `avoid` (the legend's
// panel; none when empty) slides along its edge until it clears it.
LegendLayout layoutOrientation(const Camera& cam, const LegendFont& font,
                               const LegendRect& avoid = LegendRect{1, 1, 0, 0});

class OrientationPass final : public FramePass {
 public:
  OrientationPass(const gl::Api& gl, const gl::ShaderLibrary& lib) : painter_(gl, lib) {}
  void draw(const Camera& cam, int textScale, const LegendRect& avoid);
  // Clear of the legend's panel when the frame draws one.
  void run(const PassFrame& f) override;
  std::span<const Attachment> reads() const override { return {}; }
  std::span<const Attachment> writes() const override;
  const LegendLayout& layout() const { return layout_; }  // of the last draw
  std::size_t gpuBytes() const override { return painter_.gpuBytes(); }

 private:
  OverlayPainter painter_;
  LegendLayout layout_;
};

std::unique_ptr<FramePass> makeOrientationPass(const gl::Api& gl, const gl::ShaderLibrary& lib);

}  // namespace tg::render
