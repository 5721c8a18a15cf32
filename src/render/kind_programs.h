#pragma once
// The programs of the glyph kinds drawn by closed-form intersections of their
// own (KindDraw::ClosedForm: Teem's cylinder and box, shaders/prism.*), with
// no ellipsoid pass and no Newton march, each from its row of the kind table
// (render/glyph_kind.h). Each is compiled on the first frame that draws its
// kind, so a scene without them pays nothing.
#include <array>
#include <memory>

#include <glm/vec2.hpp>

#include "gl/program.h"
#include "render/frame_params.h"

namespace tg::render {

// Sets the uniforms every glyph program takes from `p` (scale, sizing,
// threshold, slab, colour): all of them without `old`, else those that differ.
void setGlyphUniforms(const gl::Program& prog, const FrameParams& p, const FrameParams* old);

class KindPrograms {
 public:
  KindPrograms(const gl::Api& gl, const gl::ShaderLibrary& lib) : gl_(gl), lib_(lib) {}
  // The program of closed-form kind `k`, built (and given `p`'s uniforms) on first use.
  const gl::Program& program(GlyphKind k, const FrameParams& p);
  // Keeps built programs in step with the renderer's parameters.
  void setParams(const FrameParams& p, const FrameParams* old) const;
  void setColorWindow(glm::vec2 window);
  bool built(GlyphKind k) const { return programs_[std::size_t(k)] != nullptr; }

 private:
  const gl::Api& gl_;
  const gl::ShaderLibrary& lib_;
  std::array<std::unique_ptr<gl::Program>, kGlyphKindCount> programs_;
  glm::vec2 colorWindow_{0.0f};
};

}  // namespace tg::render
