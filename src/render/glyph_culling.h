#pragma once
// Which glyphs a frame draws, decided on the GPU so that culled glyphs cost
// nothing downstream (docs/design.md, "Culling"):
//  - an FA threshold compacts each range's kept glyphs once per threshold
//    change (shaders/compact_fa.comp), order preserved;
//  - per frame, ranges whose box is outside the view frustum get empty
//    indirect draw commands (shaders/cull_ranges.comp);
//  - on llvmpipe, while glyphs are about a pixel or smaller, a per-frame
//    pass keeps only glyphs that some pixel centre can see
//    (shaders/cull_pixels.comp), so that the vertex stage runs for those alone.
// When the threshold hides nothing and the whole scene is in view, neither
// pass runs and the frame is the plain direct draw.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "gl/async_counter.h"
#include "gl/program.h"
#include "render/frame_params.h"
#include "view/camera.h"
#include "render/glyph_ranges.h"
#include "render/quad_sprites.h"
#include "tensor/glyph_scale.h"

namespace tg::render {

class GlyphCulling {
 public:
  GlyphCulling(const gl::Api& gl, const gl::ShaderLibrary& lib);
  ~GlyphCulling();
  GlyphCulling(const GlyphCulling&) = delete;
  GlyphCulling& operator=(const GlyphCulling&) = delete;

  // Builds the ranges of a set whose records are already in `glyphBuffer`.
  void upload(const tensor::GlyphSet& set, GLuint glyphBuffer);
  // Runs what this frame needs; `frustum` false keeps every range (to
  // measure the culling). A slab (axis >= 0) culls ranges wholly outside it.
  // Glyphs are sized by `scale` and `sizing` (tensor/glyph_scale.h).
  // `points`: this frame's sprites are points (render/sprite_primitive.h).
  // `pixels`: keep only glyphs whose bounding sphere's screen rectangle holds
  // a pixel centre (llvmpipe with small glyphs; render/sprite_primitive.h).
  void prepare(const Camera& cam, double scale, const tensor::SizeMapping& sizing, double faMin, const Slab& slab,
               bool frustum, bool points = false, bool pixels = false);
  // Draws the glyphs of groups [g0, g1) (tensor::GlyphGroup) with the bound
  // program, whose uCompacted must be compacted().
  void draw(const QuadSprites& sprites, int g0, int g1) const;
  // A frame drawn by other means (the tessellated baseline) draws every glyph.
  void bypass() { compacted_ = indirect_ = points_ = false; }

  bool compacted() const { return compacted_; }
  bool pointSprites() const { return points_; }
  bool indirect() const { return indirect_; }
  // Glyphs the last prepared frame sent to the vertex stage: those passing
  // the threshold in ranges that passed the frustum test. Waits for the GPU
  // when that frame was culled.
  std::uint64_t drawnGlyphs() const;
  // The same count without waiting for the GPU: request it after a frame,
  // then read the newest finished one (a frame or two behind).
  void requestDrawnCount();
  std::optional<std::uint64_t> latestDrawnCount() { return drawnCounter_.latest(); }
  // How often each pass has run since upload, so tests can tell that a frame
  // which needs no culling runs none.
  struct Passes {
    std::uint64_t compactions = 0, commandPasses = 0, pixelCulls = 0;
  };
  Passes passes() const { return passes_; }
  // Bytes of GPU memory culling holds: ranges, kept counts and commands,
  // and the compacted indices once a threshold or the pixel cull has needed them.
  std::size_t gpuBytes() const;

 private:
  void dispatch(const gl::Program& prog, std::size_t workgroups) const;
  void allocateKeptIndex();
  void cullPixels(const Camera& cam, double scale, const tensor::SizeMapping& sizing, float faMin, const Slab& slab);
  const gl::Api& gl_;
  const gl::ShaderLibrary& lib_;
  gl::Program compact_, cull_;
  std::unique_ptr<gl::Program> pixels_;  // cull_pixels.comp, built on first use
  RangeTable table_;
  std::array<std::vector<GlyphRun>, 16> runs_;  // [4 * g0 + g1]: direct runs of groups [g0, g1)
  glm::dvec3 centresLo_{0.0}, centresHi_{0.0};
  double maxAbsEigenvalue_ = 0;
  std::size_t glyphCount_ = 0;
  GLuint glyphs_ = 0, ranges_ = 0, keptCount_ = 0, keptIndex_ = 0, commands_ = 0, visible_ = 0;
  gl::AsyncCounter drawnCounter_;
  float compactedFor_ = 0;
  bool compacted_ = false, indirect_ = false, points_ = false;
  Passes passes_;
};

}  // namespace tg::render
