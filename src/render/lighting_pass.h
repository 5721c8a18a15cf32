#pragma once
// Deferred Blinn-Phong (shaders/lighting.frag), every frame.
//
//   READS  GBuffer albedo, normalWC, id; with AO on its blurred occlusion
//          (AoPass), with shadows the key light's map and the G-buffer depth
//          (ShadowPass)
//   WRITES GBuffer::color, every pixel (background where the id is empty)
//
// With every effect off it runs main's exact shader; an effect's variant is
// compiled on first use, and only the variant in use is kept.
#include <memory>

#include "render/frame_pass.h"

namespace tg::render {

class LightingPass final : public FramePass {
 public:
  LightingPass(const gl::Api& gl, const gl::ShaderLibrary& lib);
  ~LightingPass() override;
  LightingPass(const LightingPass&) = delete;
  LightingPass& operator=(const LightingPass&) = delete;

  std::span<const Attachment> reads() const override;
  std::span<const Attachment> writes() const override;
  // The light and background uniforms of `p`: all without `old`, else those that differ.
  void setParams(const FrameParams& p, const FrameParams* old);
  void run(const PassFrame& f) override;
  std::size_t gpuBytes() const override { return 0; }

 private:
  void setLighting(const gl::Program& prog, const FrameParams& p) const;
  // lighting_, or the variant the frame's effects need (`shadows`: the key
  // light's map was drawn), compiled on first use; only the last is kept.
  const gl::Program& programFor(const FrameParams& p, bool shadows);
  const gl::Api& gl_;
  const gl::ShaderLibrary& lib_;
  gl::Program lighting_;
  std::unique_ptr<gl::Program> variant_;  // lighting.frag with TG_AO and/or TG_SHADOWS
  int variantKey_ = 0;                    // 1: TG_AO, 2: TG_SHADOWS, 3: both
  GLuint vao_ = 0;  // the core profile's draw needs one, with no attributes
};

}  // namespace tg::render
