#pragma once
// A layout's swatches and text (render/legend_layout.h) drawn over the lit
// image: the one way an overlay puts text on a frame, shared by the legend
// and the orientation letters. Text comes from LegendFont's atlas (Dear
// ImGui's font builder); the shaders are legend_swatch.* and legend_text.*.
#include <cstddef>
#include <memory>

#include "gl/program.h"
#include "render/legend_layout.h"

namespace tg::render {

class OverlayPainter {
 public:
  OverlayPainter(const gl::Api& gl, const gl::ShaderLibrary& lib);
  ~OverlayPainter();
  OverlayPainter(const OverlayPainter&) = delete;
  OverlayPainter& operator=(const OverlayPainter&) = delete;

  // The font at this text scale, its atlas uploaded: built on first need
  // and again when the scale changes.
  const LegendFont& font(int textScale);
  // Into the framebuffer bound for lighting, straight alpha over the colour
  // (and "over" for alpha, so a transparent background keeps the overlay).
  // The layout's text must have been laid out with font().
  void draw(const Camera& cam, const LegendLayout& layout);
  std::size_t gpuBytes() const;

 private:
  const gl::Api& gl_;
  gl::Program swatch_;
  gl::Program text_;
  std::unique_ptr<LegendFont> font_;
  GLuint vao_ = 0, atlas_ = 0, vertices_ = 0;
  std::size_t vertexCapacity_ = 0;  // bytes
};

}  // namespace tg::render
