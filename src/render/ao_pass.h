#pragma once
// Screen-space ambient occlusion, a deferred pass over the G-buffer.
//
//   READS  GBuffer::depth() (reversed window depth), normalWC(), id()
//   WRITES its own R16F textures: the raw occlusion (noisy, one of 16 kernel
//          rotations per pixel of a 4 x 4 tile) and the depth-aware blur of
//          it, ao(): the fraction of ambient and head light each pixel keeps,
//          1 on the background. shaders/lighting.frag (option TG_AO) reads
//          ao() at texture unit TG_UNIT_AO and multiplies its ambient and head
//          terms by it.
//
// Method: a normal-oriented hemisphere of `samples` points within `radius`
// of each visible surface point (VC), each projected into the depth buffer;
// a point behind the visible surface there, within the radius in depth,
// is occluded (Crytek's SSAO with the hemisphere of Bavoil and Sainz 2008).
// A convex glyph cannot occlude its own hemisphere (the segment from the
// eye to a point above the tangent plane stays above it), so an isolated
// ellipsoid keeps all its light: only neighbours darken a glyph.
#include <cstddef>

#include "gl/program.h"
#include "view/camera.h"
#include "render/frame_pass.h"
#include "render/gbuffer.h"

namespace tg::render {

class AoPass final : public FramePass {
 public:
  AoPass(const gl::Api& gl, const gl::ShaderLibrary& lib);
  ~AoPass() override;
  AoPass(const AoPass&) = delete;
  AoPass& operator=(const AoPass&) = delete;

  // Computes and blurs the occlusion of target's G-buffer; (re)allocates its
  // textures when the target's size changes. Leaves ao() bound to TG_UNIT_AO.
  void run(const Camera& cam, const GBuffer& target, const AoParams& p, double radiusWC);
  void run(const PassFrame& f) override { run(f.cam, f.target, f.p.ao, f.aoRadiusWC); }
  std::span<const Attachment> reads() const override;
  std::span<const Attachment> writes() const override { return {}; }  // its own textures
  GLuint ao() const { return tex_[1]; }
  // Bytes of its textures (0 before the first run).
  std::size_t gpuBytes() const override { return std::size_t(width_) * std::size_t(height_) * 2 * kBytesPerTexel; }

 private:
  static constexpr std::size_t kBytesPerTexel = 2;  // R16F
  void allocate(int width, int height);
  void release();
  const gl::Api& gl_;
  gl::Program occlusion_, blur_;
  GLuint vao_ = 0;
  GLuint tex_[2] = {};  // raw, blurred
  GLuint fbo_[2] = {};
  int width_ = 0, height_ = 0;
};

}  // namespace tg::render
