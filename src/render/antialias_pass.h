#pragma once
// Anti-aliasing of silhouettes (FrameParams::samples > 1): Blinn's open
// problem, by supersampling (Taylor: it applies directly to ray-cast
// objects) only where it shows. The frame's own image is the pixel centres'
// sample; the pass draws samples - 1 more frames of glyphs and context, lit,
// each from the camera shifted by a sub-pixel offset (withPixelOffset; the
// Halton (2, 3) points), and where the frame's id changes within a pixel's
// 3x3 neighbourhood replaces its colour by the mean of all samples.
//
//   READS   GBuffer::id (where the edges are), GBuffer::color (the centre
//           sample); its own sample target's lit colour
//   WRITES  GBuffer::color at edge pixels only: every other pixel, and the
//           id, depth, normal and albedo channels (the EXR's, picking's)
//           stay the pixel centre's, bit for bit
//
// A sample reuses the frame's shadow map (light space: the same for every
// sample) and its ambient occlusion (per pixel, the centre's). Built on the
// first frame with samples > 1, released by the first without.
#include <cstddef>
#include <memory>

#include <glm/vec2.hpp>

#include "gl/program.h"
#include "render/frame_pass.h"
#include "render/gbuffer.h"

namespace tg::render {

// Sample k's offset from the pixel centre (k >= 1; 0 is the centre), in
// pixels, x right, y down: the Halton (2, 3) sequence's k-th point, centred.
glm::dvec2 sampleOffset(int k);

class AntialiasPass final : public FramePass {
 public:
  AntialiasPass(const gl::Api& gl, const gl::ShaderLibrary& lib);
  ~AntialiasPass() override;
  AntialiasPass(const AntialiasPass&) = delete;
  AntialiasPass& operator=(const AntialiasPass&) = delete;

  // Needs f.drawSample.
  void run(const PassFrame& f) override;
  std::span<const Attachment> reads() const override;
  std::span<const Attachment> writes() const override;
  std::size_t gpuBytes() const override;

 private:
  void allocate(int width, int height);
  // Adds `color` into the sum where the frame (`frameId`) has an edge.
  void accumulate(GLuint color, GLuint frameId) const;
  const gl::Api& gl_;
  gl::Program accumulate_, resolve_;
  std::unique_ptr<GBuffer> sample_;
  GLuint sum_ = 0, sumFbo_ = 0, vao_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace tg::render
