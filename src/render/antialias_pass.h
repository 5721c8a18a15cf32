#pragma once
// Anti-aliasing of silhouettes (FrameParams::samples > 1): Blinn's open
// problem, by supersampling (Taylor: it applies directly to ray-cast
// objects) only where it shows: pixels whose 3x3 neighbourhood in the
// frame's id channel holds another id. The frame's own image is the pixel
// centres' sample; samples - 1 more lie at the Halton (2, 3) points.
//
// Coverage (every kind a glyph's own cast draws): one pass casts each edge
// pixel's further samples against the glyphs its 3x3 block shows, with the
// kinds' shared set-up and cast code (shaders/aa_coverage.frag), and takes
// each sample's colour from the block's pixel nearest it that shows the
// winning surface; context and background pixels compete by their depth.
// Coverage is exact per sample, shading per pixel, as a multisampled raster
// shades once per pixel and primitive. It reads the records through the
// path's buffer, found by input id in a table made on the first such frame
// after an upload.
//
// Frames (blobs, whose surface no one glyph's cast gives, and tessellated
// frames): samples - 1 more frames of glyphs and context, lit, from the
// camera shifted by each sub-pixel offset (withPixelOffset), averaged at the
// edge pixels.
//
//   READS   GBuffer::id (where the edges are; which glyphs), GBuffer::color
//           (the centre sample), GBuffer::depth (coverage: the context's
//           depth); its own sample target's lit colour (frames)
//   WRITES  GBuffer::color at edge pixels only: every other pixel, and the
//           id, depth, normal and albedo channels (the EXR's, picking's)
//           stay the pixel centre's, bit for bit
//
// A sample frame reuses the frame's shadow map (light space: the same for
// every sample) and its ambient occlusion (per pixel, the centre's). Built
// on the first frame with samples > 1, released by the first without.
#include <array>
#include <cstddef>
#include <cstdint>
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

  // Needs f.drawSample for frames that sample by frames.
  void run(const PassFrame& f) override;
  // Whether frames like f's sample by coverage (else by frames).
  static bool byCoverage(const PassFrame& f);
  std::span<const Attachment> reads() const override;
  std::span<const Attachment> writes() const override;
  std::size_t gpuBytes() const override;

 private:
  // The sum's texture at width x height (and with `frames`, the sample target).
  void allocate(int width, int height, bool frames);
  // Adds `color` into the sum where the frame (`frameId`) has an edge.
  void accumulate(GLuint color, GLuint frameId) const;
  void runFrames(const PassFrame& f);
  void runCoverage(const PassFrame& f);
  // The sum over the frame's colour at its edges, divided by `samples`.
  void resolve(const PassFrame& f, int samples) const;
  const gl::Api& gl_;
  const gl::ShaderLibrary& lib_;
  gl::Program accumulate_, resolve_;
  // By cast (ellipsoid, march, cylinder, box), each built by its first frame;
  // and the edge mask's.
  std::array<std::unique_ptr<gl::Program>, 4> coverage_;
  std::unique_ptr<gl::Program> mark_;
  std::unique_ptr<GBuffer> sample_;
  GLuint sum_ = 0, sumDepth_ = 0, sumFbo_ = 0, vao_ = 0;  // sumDepth_: the edge mask
  // Coverage writes the frame's colour under the edge mask: target's colour
  // texture and sumDepth_ (made again for another target texture).
  GLuint maskedFbo_ = 0, maskedColor_ = 0;
  int width_ = 0, height_ = 0;
  GLuint idRecords_ = 0;  // (input id, record) pairs by id, for the coverage casts
  std::size_t idRecordCount_ = 0;  // its words
  bool dense_ = false;             // indexed by id (else sorted (id, record) pairs)
  std::uint64_t idRecordsOf_ = 0;  // PassFrame::uploads they were made for
};

}  // namespace tg::render
