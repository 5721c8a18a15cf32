#pragma once
// Silhouette and crease lines, a deferred pass composited over the lit colour.
//
//   READS  GBuffer::id(), depth() (reversed window depth), normalWC()
//   WRITES GBuffer::color(), blended: the line colour over the lit colour
//          (alpha = line coverage x colour alpha); alpha of the target kept
//
// An edge lies between a glyph pixel p and a pixel q behind it (or empty)
// when their ids differ (silhouettes, and the curves where glyphs cut each
// other), when q lies off p's tangent plane by a depth jump (one id that
// hides part of itself: issue 8's meshes), or when their normals turn by more
// than the crease angle (superquadric edges). The line is drawn on the front
// pixel's side only, over every pixel within `width` pixels of such a q, so
// that a width of w pixels gives lines w pixels wide (a fractional width
// fades the last pixel). After lighting rather than in it: lines do not
// depend on the lighting model, lighting.frag stays one job, and the pass
// runs only when asked (Sigg et al. 2006 also composite their Sobel lines).
#include <glm/vec4.hpp>

#include "gl/program.h"
#include "render/frame_pass.h"
#include "render/gbuffer.h"

namespace tg::render {

class OutlinePass final : public FramePass {
 public:
  OutlinePass(const gl::Api& gl, const gl::ShaderLibrary& lib);
  ~OutlinePass() override;
  OutlinePass(const OutlinePass&) = delete;
  OutlinePass& operator=(const OutlinePass&) = delete;

  // Needs the camera uniforms already set on program() (setCameraUniforms).
  // `idEdges`: ids bound surfaces (false for blobs, whose ids change on smooth seams).
  void run(const GBuffer& target, const OutlineParams& p, bool idEdges = true) const;
  void run(const PassFrame& f) override;
  std::span<const Attachment> reads() const override;
  std::span<const Attachment> writes() const override;
  std::size_t gpuBytes() const override { return 0; }
  const gl::Program& program() const { return program_; }

 private:
  const gl::Api& gl_;
  gl::Program program_;
  GLuint vao_ = 0;
};

}  // namespace tg::render
