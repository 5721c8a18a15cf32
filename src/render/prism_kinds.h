#pragma once
// The glyph kinds drawn by closed-form intersections of their own, with no
// ellipsoid pass and no Newton march: Teem's cylinder and box glyphs
// (shaders/prism.{vert,frag}, lib/prism.glsl). Each program is compiled on
// the first frame that draws its kind, so a scene without them pays nothing.
#include <memory>

#include <glm/vec2.hpp>

#include "gl/program.h"

namespace tg::render {

struct FrameParams;
enum class GlyphKind;

// Sets the uniforms every glyph program takes from `p` (scale, sizing,
// threshold, slab, colour): all of them without `old`, else those that differ.
void setGlyphUniforms(const gl::Program& prog, const FrameParams& p, const FrameParams* old);

bool isPrismKind(GlyphKind k);

class PrismKinds {
 public:
  PrismKinds(const gl::Api& gl, const gl::ShaderLibrary& lib) : gl_(gl), lib_(lib) {}
  // The program of prism kind `k`, built (and given `p`'s uniforms) on first use.
  const gl::Program& program(GlyphKind k, const FrameParams& p);
  // Keeps built programs in step with the renderer's parameters.
  void setParams(const FrameParams& p, const FrameParams* old) const;
  void setMdRange(glm::vec2 mdRange);
  bool built(GlyphKind k) const;

 private:
  const gl::Api& gl_;
  const gl::ShaderLibrary& lib_;
  std::unique_ptr<gl::Program> cylinder_, box_;
  glm::vec2 mdRange_{0.0f};
};

}  // namespace tg::render
