#pragma once
// The compute glyph path (render/glyph_path.h, "compute"): every glyph's
// set-up and cast by compute shaders in the frame's own GL context, for GPUs
// whose graphics stages run on a small part of the chip (H100/H200) while
// compute runs on all of it. Per cast class (the ellipsoid, each march
// variant, cylinders, boxes: the raster path's programs), from the records
// as uploaded, so that no parameter or camera change uploads anything:
//  0. compute_batches.comp, per batch of kBatchRecords records (bounds made
//     at upload): batches no glyph of which the selection keeps or the
//     frustum holds are left out of the set-up's indirect dispatch;
//  1. compute_setup.comp, per record of the kept batches (a dispatch per
//     chunk of the records, whose buffers hold at most one storage block): the sprite stage's culls and exact
//     screen rectangle; a glyph of at most 16 pixel centres is cast at each
//     and written to the visibility buffer; a larger one is kept, with the
//     count of each tile it touches;
//  2. compute_scan.comp: the tiles' starts and the list of tiles with
//     glyphs by prefix sums, and the next passes' indirect dispatches (no
//     CPU round trip);
//  3. compute_bin.comp: each kept glyph into its tiles' lists;
//  4. compute_sort.comp, per tile with glyphs: its list in runs of 1,024
//     sorted by nearest depth;
//  5. compute_cast.comp, per tile with glyphs and pixel: its list's glyphs,
//     each run front to back until the next lies behind the nearest hit so
//     far, the nearest into the buffer.
// The visibility buffer holds, per pixel, the minimum of (inverted window
// depth, record) as 64 bits: by one atomic where GL_NV_shader_atomic_int64
// is present, else by two passes of 32-bit minima (depth, then the record
// at that depth). compute_resolve.comp turns it into the CPU path's textures
// (render/cast_targets.h), casting each pixel's glyph once more for its
// normal; cpu_gbuffer.frag writes the G-buffer, so that every deferred pass,
// context and picking run unchanged. The key light's shadow map is cast the
// same way from the light. Blobs and the tessellated baseline are refused.
// The lists are sized by the last frame's need: a frame that needs more is
// cast again with room (the counters are read back once a frame).
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "render/cast_targets.h"
#include "render/glyph_path.h"

namespace tg::render {

// lib/compute_vis.glsl's batches: kBatchRecords consecutive records of a
// chunk (input order, so that a grid's batches are slabs of its rows).
inline constexpr std::size_t kBatchRecords = 8192;
struct BatchBounds {
  float loWC[3], maxAbsEigenvalue;
  float hiWC[3], maxFA;  // -1 where no record's FA is a number (none is selected)
};
static_assert(sizeof(BatchBounds) == 32);
std::vector<BatchBounds> batchBoundsOf(std::span<const tensor::GlyphRecord> records);

class ComputeGlyphs final : public GlyphPath {
 public:
  // The tile lists start with room for `tiled` glyphs and `entries` tile
  // entries (they grow as frames need; tests start them small). Records
  // are held in chunks of at most `chunkRecords` (0: as many as one storage
  // block holds, GL_MAX_SHADER_STORAGE_BLOCK_SIZE; tests split small sets).
  ComputeGlyphs(const gl::Api& gl, const gl::ShaderLibrary& lib, std::size_t tiled = std::size_t(1) << 16,
                std::size_t entries = std::size_t(1) << 18, std::size_t chunkRecords = 0);
  ~ComputeGlyphs() override;
  ComputeGlyphs(const ComputeGlyphs&) = delete;
  ComputeGlyphs& operator=(const ComputeGlyphs&) = delete;

  std::string_view name() const override { return "compute"; }
  std::string how() const override;
  void upload(const tensor::GlyphSet& set) override;
  void setParams(const FrameParams& p, const FrameParams* old) override;
  void setColorWindow(glm::dvec2 window) override;
  void uploadColorScalars(std::span<const float> byRecord) override;
  void drawView(const Camera& cam, const FrameParams& p, const GBuffer& target) override;
  std::pair<glm::dvec3, glm::dvec3> castersBoxWC(const FrameParams& p) const override;
  void drawShadowCasters(const Camera& light, const FrameParams& p, ShadowPass& shadow) override;
  std::size_t gpuBytes() const override;
  // The records' one buffer; 0 where they are in several chunks (the
  // anti-aliasing then casts whole frames per sample).
  GLuint recordBuffer() const override { return chunks_.size() == 1 ? chunks_[0].records : 0; }
  std::size_t recordChunks() const { return chunks_.size(); }
  // Batches the last frame's culls kept, summed over its chunks, cast
  // classes and passes (read back with the frame's counters).
  std::uint64_t batchesKept() const { return batchesKept_; }
  std::uint64_t drawnGlyphs() const override { return drawn_; }

  // Whether the visibility buffer takes one 64-bit atomic (else two 32-bit passes).
  bool atomics64() const { return vis64_; }

  // A frame's cast classes: which programs cast which glyph groups.
  struct CastClass {
    int program;  // kEllipsoid ... kBox
    int groupLo, groupHi;
  };
  enum Program { kEllipsoid = 0, kMarchGeneral, kMarchConvex, kMarchMixed, kCylinder, kBox, kPrograms };

 private:
  enum Stage { kSetup = 0, kCast, kSurface, kStages };
  const gl::Program& classProgram(Stage stage, int program);
  // The visibility buffer of `cam` at p's parameters, and the frame's
  // glyph count; grows the lists and casts again where they overflowed.
  // `light`: cam is the key light's (for messages).
  void castFrame(const Camera& cam, const FrameParams& p, const std::vector<CastClass>& classes, bool light);
  void castPasses(const Camera& cam, const FrameParams& p, const std::vector<CastClass>& classes);
  void setUniforms(const gl::Program& prog, const Camera& cam, const FrameParams& p, const CastClass* c, int pass) const;
  void allocateFrame(int width, int height, bool light);
  void freeChunks(bool scalarsOnly);
  // c's records bound, and prog's uRecordBase and uRecordCount set.
  void bindChunk(const gl::Program& prog, const RecordChunk& c) const;
  void allocateLists(std::size_t tiled, std::size_t entries);
  // vis_ into the depth and record images (and, with `surface`, each
  // class's normals and hits), for cpu_gbuffer.frag or cpu_depth.frag.
  void resolve(const Camera& cam, const FrameParams& p, const std::vector<CastClass>& classes, GLuint depth,
               GLuint record, bool surface, bool hitGC);

  const gl::Api& gl_;
  const gl::ShaderLibrary& lib_;
  CastTargets targets_;
  bool vis64_ = false;
  std::array<std::unique_ptr<gl::Program>, std::size_t(kStages) * std::size_t(kPrograms)> programs_;
  std::unique_ptr<gl::Program> cull_, scan_, bin_, sort_, depthResolve_;
  std::size_t records_ = 0, sphereCount_ = 0, definiteCount_ = 0;
  glm::dvec3 centresLoWC_{0.0}, centresHiWC_{0.0};
  double maxAbsEigenvalue_ = 0;
  FrameParams params_;
  bool paramsSet_ = false;
  std::vector<RecordChunk> chunks_;
  std::vector<GLuint> batchBounds_;  // per chunk
  std::size_t blockBytes_ = 0;  // one storage block, as this path uses it
  std::size_t chunkRecords_;
  GLuint keptBatches_ = 0, activeTiles_ = 0;
  std::uint64_t batchesKept_ = 0;
  GLuint vis_ = 0, state_ = 0, candidates_ = 0, tileCount_ = 0, tileStart_ = 0, tileList_ = 0;
  int width_ = 0, height_ = 0, tilesX_ = 0, tilesY_ = 0;
  std::size_t pixelCapacity_ = 0, tileCapacity_ = 0;
  std::size_t initialTiled_, initialEntries_;
  std::size_t tiledCapacity_ = 0, entryCapacity_ = 0;
  std::uint64_t drawn_ = 0;
};

// The cast classes of a frame at p over groups of these sizes (spheres,
// definite, mixed), in the raster path's program order; GL-free, for tests.
std::vector<ComputeGlyphs::CastClass> computeCastClasses(const FrameParams& p, const std::array<std::size_t, 3>& groups);

}  // namespace tg::render
