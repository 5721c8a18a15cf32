#include "render/compute_glyphs.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>

#include "render/camera_uniforms.h"
#include "render/glyph_kind.h"
#include "render/kind_programs.h"
#include "render/march_groups.h"
#include "render/raster_glyphs.h"
#include "render/shadow_pass.h"
#include "shaders/lib/bindings.h"

namespace tg::render {

namespace {

// lib/compute_vis.glsl's ComputeState (std430).
struct ComputeState {
  GLuint tiledCount, entryCount, tiledCapacity, entryCapacity;
  GLuint binDispatch[4];
  GLuint tiledNeeded, entryNeeded, drawn, entryOverflow;
  GLuint setupDispatch[4];
  GLuint batchesKept, pad[3];
  GLuint castDispatch[4];
  GLuint sortDispatch[4];
};
static_assert(sizeof(ComputeState) == 112);
constexpr GLintptr kBinDispatchOffset = offsetof(ComputeState, binDispatch);
constexpr GLintptr kSetupDispatchOffset = offsetof(ComputeState, setupDispatch);
constexpr GLintptr kCastDispatchOffset = offsetof(ComputeState, castDispatch);
constexpr GLintptr kSortDispatchOffset = offsetof(ComputeState, sortDispatch);
constexpr GLuint kSetupGroupSize = 64;  // compute_setup.comp's local size
constexpr std::size_t kCandidateBytes = 80;  // lib/compute_vis.glsl's CastCandidate
constexpr int kTilePx = 16;

bool hasExtension(const gl::Api& gl, std::string_view name) {
  GLint n = 0;
  gl.GetIntegerv(GL_NUM_EXTENSIONS, &n);
  for (GLint k = 0; k < n; ++k) {
    const auto* e = reinterpret_cast<const char*>(gl.GetStringi(GL_EXTENSIONS, GLuint(k)));
    if (e && name == e) return true;
  }
  return false;
}

void deleteBuffer(const gl::Api& gl, GLuint& b) {
  if (b) gl.DeleteBuffers(1, &b);
  b = 0;
}

GLuint makeBuffer(const gl::Api& gl, std::size_t bytes, GLbitfield flags = 0) {
  GLuint b = 0;
  gl.CreateBuffers(1, &b);
  gl.NamedBufferStorage(b, GLsizeiptr(std::max<std::size_t>(bytes, 16)), nullptr, flags);
  return b;
}

}  // namespace

std::vector<BatchBounds> batchBoundsOf(std::span<const tensor::GlyphRecord> records) {
  std::vector<BatchBounds> out((records.size() + kBatchRecords - 1) / kBatchRecords);
  for (std::size_t b = 0; b < out.size(); ++b) {
    BatchBounds& o = out[b];
    const std::size_t first = b * kBatchRecords, last = std::min(records.size(), first + kBatchRecords);
    for (int k = 0; k < 3; ++k) {
      o.loWC[k] = INFINITY;
      o.hiWC[k] = -INFINITY;
    }
    o.maxAbsEigenvalue = 0;
    o.maxFA = -1;
    for (std::size_t i = first; i < last; ++i) {
      const tensor::GlyphRecord& g = records[i];
      for (int k = 0; k < 3; ++k) {
        o.loWC[k] = std::min(o.loWC[k], g.posWC[k]);
        o.hiWC[k] = std::max(o.hiWC[k], g.posWC[k]);
      }
      // Descending eigenvalues: the largest magnitude is the first's or the last's.
      o.maxAbsEigenvalue = std::max({o.maxAbsEigenvalue, std::abs(g.eigenvalues[0]), std::abs(g.eigenvalues[2])});
      if (g.fa > o.maxFA) o.maxFA = g.fa;  // false for NaN
    }
  }
  return out;
}

std::vector<ComputeGlyphs::CastClass> computeCastClasses(const FrameParams& p, const std::array<std::size_t, 3>& groups) {
  using C = ComputeGlyphs;
  std::vector<C::CastClass> out;
  const GlyphKindInfo& kind = glyphKind(p.glyph);
  if (kind.draw == KindDraw::ClosedForm) {
    out.push_back({p.glyph == GlyphKind::Cylinder ? C::kCylinder : C::kBox, 0, 3});
    return out;
  }
  // The raster path's dispatch (RasterGlyphs::drawGlyphs): groups below the
  // split as ellipsoids, the rest by their march variant.
  const int split = marchSplit(p);
  auto add = [&](int program, int lo, int hi) {
    std::size_t n = 0;
    for (int g = lo; g < hi; ++g) n += groups[std::size_t(g)];
    if (n > 0) out.push_back({program, lo, hi});
  };
  add(C::kEllipsoid, 0, split);
  const int definite = int(tensor::GlyphGroup::Definite), mixed = int(tensor::GlyphGroup::Mixed);
  const bool convex = marchVariant(definite, split, p.marchVariants) == MarchVariant::Convex;
  if (convex) add(C::kMarchConvex, definite, definite + 1);
  const int rest = convex ? mixed : split;
  if (rest == mixed && marchVariant(mixed, split, p.marchVariants) == MarchVariant::Mixed) add(C::kMarchMixed, mixed, 3);
  else if (rest < 3) add(C::kMarchGeneral, rest, 3);
  return out;
}

ComputeGlyphs::ComputeGlyphs(const gl::Api& gl, const gl::ShaderLibrary& lib, std::size_t tiled, std::size_t entries,
                             std::size_t chunkRecords)
    : gl_(gl),
      lib_(lib),
      targets_(gl, lib, GL_RGBA32F, false),
      vis64_(hasExtension(gl, "GL_ARB_gpu_shader_int64") && hasExtension(gl, "GL_NV_shader_atomic_int64")),
      initialTiled_(std::max<std::size_t>(tiled, 1)),
      initialEntries_(std::max<std::size_t>(entries, 1)) {
  GLint64 maxBlock = 0;
  gl.GetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  // GLSL indexes a block with an int; GL guarantees 2^27 bytes.
  blockBytes_ = std::size_t(std::clamp<GLint64>(maxBlock, GLint64(1) << 27, std::numeric_limits<GLint>::max()));
  chunkRecords_ = blockBytes_ / sizeof(tensor::GlyphRecord);
  if (chunkRecords > 0) chunkRecords_ = std::min(chunkRecords_, chunkRecords);
  state_ = makeBuffer(gl, sizeof(ComputeState), GL_DYNAMIC_STORAGE_BIT);
  gl::checkError(gl, "ComputeGlyphs");
}

ComputeGlyphs::~ComputeGlyphs() {
  freeChunks(false);
  for (GLuint* b : {&vis_, &state_, &candidates_, &tileCount_, &tileStart_, &tileList_, &activeTiles_, &keptBatches_})
    deleteBuffer(gl_, *b);
}

void ComputeGlyphs::freeChunks(bool scalarsOnly) {
  for (RecordChunk& c : chunks_) {
    deleteBuffer(gl_, c.scalars);
    if (!scalarsOnly) deleteBuffer(gl_, c.records);
  }
  if (scalarsOnly) return;
  chunks_.clear();
  for (GLuint& b : batchBounds_) deleteBuffer(gl_, b);
  batchBounds_.clear();
  deleteBuffer(gl_, keptBatches_);
}

std::string ComputeGlyphs::how() const {
  return vis64_ ? "visibility buffer by 64-bit atomics (GL_NV_shader_atomic_int64)"
                : "visibility buffer by two passes of 32-bit atomics (no GL_NV_shader_atomic_int64)";
}

const gl::Program& ComputeGlyphs::classProgram(Stage stage, int program) {
  auto& slot = programs_[std::size_t(stage) * std::size_t(kPrograms) + std::size_t(program)];
  if (!slot) {
    static constexpr std::string_view kSources[kStages] = {"compute_setup.comp", "compute_cast.comp",
                                                           "compute_resolve.comp"};
    std::vector<std::string_view> on;
    if (program >= kMarchGeneral && program <= kMarchMixed) on.push_back("TG_CAST_MARCH");
    if (program == kMarchConvex) on.push_back("TG_MARCH_CONVEX");
    if (program == kMarchMixed) on.push_back("TG_MARCH_MIXED");
    if (program == kCylinder || program == kBox) on.push_back("TG_CAST_PRISM");
    if (program == kCylinder) on.push_back("TG_CYLINDER");
    if (stage == kSurface) on.push_back("TG_RESOLVE_SURFACE");
    else if (vis64_) on.push_back("TG_VIS64");
    slot = std::make_unique<gl::Program>(gl_, lib_, std::initializer_list<gl::StageSource>{{GL_COMPUTE_SHADER, kSources[stage]}},
                                         std::move(on));
  }
  return *slot;
}

void ComputeGlyphs::upload(const tensor::GlyphSet& set) {
  // Record ids are 32-bit words of the visibility buffer and GLSL ints.
  if (set.glyphs.size() >= std::size_t(std::numeric_limits<std::int32_t>::max()))
    throw std::runtime_error("GlyphRenderer::upload: " + std::to_string(set.glyphs.size()) +
                             " glyphs; the compute path draws fewer than 2^31");
  freeChunks(false);
  records_ = set.glyphs.size();
  sphereCount_ = set.sphereCount;
  definiteCount_ = set.definiteCount;
  centresLoWC_ = set.boundsMinWC;
  centresHiWC_ = set.boundsMaxWC;
  maxAbsEigenvalue_ = set.maxAbsEigenvalue;
  for (std::size_t first = 0; first < records_; first += chunkRecords_) {
    RecordChunk c;
    c.first = first;
    c.count = std::min(chunkRecords_, records_ - first);
    gl_.CreateBuffers(1, &c.records);
    chunks_.push_back(c);
    const std::span<const tensor::GlyphRecord> records(set.glyphs.data() + first, c.count);
    gl_.NamedBufferStorage(c.records, GLsizeiptr(c.count * sizeof(tensor::GlyphRecord)), records.data(), 0);
    const std::vector<BatchBounds> bounds = batchBoundsOf(records);
    GLuint b = 0;
    gl_.CreateBuffers(1, &b);
    batchBounds_.push_back(b);
    gl_.NamedBufferStorage(b, GLsizeiptr(bounds.size() * sizeof(BatchBounds)), bounds.data(), 0);
  }
  if (!chunks_.empty())
    keptBatches_ = makeBuffer(gl_, (std::min(chunkRecords_, records_) + kBatchRecords - 1) / kBatchRecords * 4);
  gl::checkError(gl_, "GlyphRenderer::upload");
}

void ComputeGlyphs::setParams(const FrameParams& p, const FrameParams* old) { targets_.setGlyphParams(p, old); }

void ComputeGlyphs::setColorWindow(glm::dvec2 window) { targets_.setColorWindow(window); }

void ComputeGlyphs::uploadColorScalars(std::span<const float> byRecord) {
  if (byRecord.size() != records_)
    throw std::invalid_argument("GlyphRenderer::setColorScalars: " + std::to_string(byRecord.size()) +
                                " values for " + std::to_string(records_) + " glyphs");
  freeChunks(true);
  for (RecordChunk& c : chunks_) {
    gl_.CreateBuffers(1, &c.scalars);
    gl_.NamedBufferStorage(c.scalars, GLsizeiptr(c.count * sizeof(float)), byRecord.data() + c.first, 0);
  }
  gl::checkError(gl_, "GlyphRenderer::setColorScalars");
}

void ComputeGlyphs::allocateFrame(int width, int height, bool light) {
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  if (pixels * 8 > blockBytes_)
    throw std::runtime_error("GlyphRenderer::render: the compute path's visibility buffer for " + std::to_string(width) +
                             "x" + std::to_string(height) + " is " + std::to_string(pixels * 8) +
                             " bytes, more than one storage block holds (" + std::to_string(blockBytes_) +
                             ", GL_MAX_SHADER_STORAGE_BLOCK_SIZE); use a smaller " +
                             (light ? "--shadow-map-size" : "--size") + " or --pipeline raster");
  width_ = width;
  height_ = height;
  tilesX_ = (width + kTilePx - 1) / kTilePx;
  tilesY_ = (height + kTilePx - 1) / kTilePx;
  const std::size_t tiles = std::size_t(tilesX_) * std::size_t(tilesY_);
  // Sized for the largest target so far: a frame with shadows alternates
  // the view's and the light's sizes.
  if (vis_ && pixels <= pixelCapacity_ && tiles <= tileCapacity_) return;
  pixelCapacity_ = std::max(pixelCapacity_, pixels);
  tileCapacity_ = std::max(tileCapacity_, tiles);
  for (GLuint* b : {&vis_, &tileCount_, &tileStart_, &activeTiles_}) deleteBuffer(gl_, *b);
  vis_ = makeBuffer(gl_, pixelCapacity_ * 8);
  tileCount_ = makeBuffer(gl_, tileCapacity_ * 4);
  tileStart_ = makeBuffer(gl_, (2 * tileCapacity_ + 1) * 4);
  activeTiles_ = makeBuffer(gl_, tileCapacity_ * 4);
}

void ComputeGlyphs::allocateLists(std::size_t tiled, std::size_t entries) {
  if (candidates_ && tiled <= tiledCapacity_ && entries <= entryCapacity_) return;
  // A quarter more than asked, so that a slowly moving camera regrows rarely.
  const bool first = !candidates_;
  tiledCapacity_ = std::max(tiledCapacity_, std::min(records_, first ? tiled : tiled + tiled / 4));
  entryCapacity_ = std::max(entryCapacity_, first ? entries : entries + entries / 4);
  // Storage blocks and GLuint indices bound the lists.
  const std::size_t limit = blockBytes_;
  if (tiledCapacity_ * kCandidateBytes > limit || entryCapacity_ * 4 > limit ||
      entryCapacity_ >= std::numeric_limits<GLuint>::max())
    throw std::runtime_error("GlyphRenderer::render: the compute path's tile lists need " +
                             std::to_string(entryCapacity_) + " entries and " + std::to_string(tiledCapacity_) +
                             " glyphs, more than one storage block holds; use --pipeline raster");
  deleteBuffer(gl_, candidates_);
  deleteBuffer(gl_, tileList_);
  candidates_ = makeBuffer(gl_, tiledCapacity_ * kCandidateBytes);
  tileList_ = makeBuffer(gl_, entryCapacity_ * 4);
}

void ComputeGlyphs::setUniforms(const gl::Program& prog, const Camera& cam, const FrameParams& p, const CastClass* c,
                                int pass) const {
  setCameraUniforms(prog, cam);
  setGlyphUniforms(prog, p, nullptr);
  prog.set("uGamma", float(p.gamma));
  prog.set("uEpsilon", float(p.march.epsilon));
  prog.set("uMaxIterations", p.march.maxIterations);
  prog.set("uGroupLo", c ? c->groupLo : 0);
  prog.set("uGroupHi", c ? c->groupHi : 3);
  prog.set("uPass", pass);
  prog.set("uTilesX", tilesX_);
  prog.set("uTiles", tilesX_ * tilesY_);
  gl_.UseProgram(prog.id());
}

void ComputeGlyphs::bindChunk(const gl::Program& prog, const RecordChunk& c) const {
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_GLYPHS, c.records);
  prog.set("uRecordBase", int(c.first));
  prog.set("uRecordCount", int(c.count));
}

void ComputeGlyphs::castPasses(const Camera& cam, const FrameParams& p, const std::vector<CastClass>& classes) {
  const GLuint ones = 0xFFFFFFFFu, zero = 0;
  const std::size_t tiles = std::size_t(tilesX_) * std::size_t(tilesY_);
  gl_.ClearNamedBufferSubData(vis_, GL_R32UI, 0, GLsizeiptr(std::size_t(width_) * std::size_t(height_) * 8), GL_RED_INTEGER,
                              GL_UNSIGNED_INT, &ones);
  ComputeState s{};
  s.tiledCapacity = GLuint(tiledCapacity_);
  s.entryCapacity = GLuint(entryCapacity_);
  s.setupDispatch[0] = GLuint(kBatchRecords) / kSetupGroupSize;
  s.setupDispatch[2] = 1;
  gl_.NamedBufferSubData(state_, 0, sizeof s, &s);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_BATCH_LIST, keptBatches_);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_VIS, vis_);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_COMPUTE_STATE, state_);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_CANDIDATES, candidates_);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_TILE_COUNT, tileCount_);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_TILE_START, tileStart_);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_TILE_LIST, tileList_);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_ACTIVE_TILES, activeTiles_);
  gl_.BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, state_);
  if (!scan_) {
    cull_ = std::make_unique<gl::Program>(gl_, lib_, std::initializer_list<gl::StageSource>{{GL_COMPUTE_SHADER, "compute_batches.comp"}});
    scan_ = std::make_unique<gl::Program>(gl_, lib_, std::initializer_list<gl::StageSource>{{GL_COMPUTE_SHADER, "compute_scan.comp"}});
    sort_ = std::make_unique<gl::Program>(gl_, lib_, std::initializer_list<gl::StageSource>{{GL_COMPUTE_SHADER, "compute_sort.comp"}});
    bin_ = std::make_unique<gl::Program>(gl_, lib_, std::initializer_list<gl::StageSource>{{GL_COMPUTE_SHADER, "compute_bin.comp"}});
  }
  for (int pass = 0; pass < (vis64_ ? 1 : 2); ++pass)
    for (const CastClass& c : classes) {
      // This class's tiles: counters and counts from zero.
      gl_.ClearNamedBufferSubData(state_, GL_R32UI, 0, 8, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
      gl_.ClearNamedBufferSubData(state_, GL_R32UI, offsetof(ComputeState, entryOverflow), 4, GL_RED_INTEGER,
                                  GL_UNSIGNED_INT, &zero);
      gl_.ClearNamedBufferSubData(tileCount_, GL_R32UI, 0, GLsizeiptr(tiles * 4), GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
      gl_.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
      const gl::Program& setup = classProgram(kSetup, c.program);
      setUniforms(*cull_, cam, p, &c, pass);
      setUniforms(setup, cam, p, &c, pass);
      for (std::size_t k = 0; k < chunks_.size(); ++k) {
        // The chunk's batches culled into the set-up's dispatch.
        gl_.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
        gl_.ClearNamedBufferSubData(state_, GL_R32UI, kSetupDispatchOffset + 4, 4, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
        gl_.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        const std::size_t batches = (chunks_[k].count + kBatchRecords - 1) / kBatchRecords;
        gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_BATCH_BOUNDS, batchBounds_[k]);
        cull_->set("uBatchCount", int(batches));
        gl_.UseProgram(cull_->id());
        gl_.DispatchCompute(GLuint((batches + 63) / 64), 1, 1);
        gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
        bindChunk(setup, chunks_[k]);
        gl_.UseProgram(setup.id());
        gl_.DispatchComputeIndirect(kSetupDispatchOffset);
      }
      gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      setUniforms(*scan_, cam, p, &c, pass);
      gl_.DispatchCompute(1, 1, 1);
      gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
      setUniforms(*bin_, cam, p, &c, pass);
      gl_.DispatchComputeIndirect(kBinDispatchOffset);
      gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      setUniforms(*sort_, cam, p, &c, pass);
      gl_.DispatchComputeIndirect(kSortDispatchOffset);
      gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      setUniforms(classProgram(kCast, c.program), cam, p, &c, pass);
      gl_.DispatchComputeIndirect(kCastDispatchOffset);
      gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
}

void ComputeGlyphs::castFrame(const Camera& cam, const FrameParams& p, const std::vector<CastClass>& classes, bool light) {
  allocateFrame(cam.width, cam.height, light);
  allocateLists(std::min(records_, initialTiled_), initialEntries_);
  drawn_ = 0;
  batchesKept_ = 0;
  if (classes.empty() || records_ == 0) return;
  // At most twice: the second cast has room for what the first counted.
  for (int attempt = 0; attempt < 2; ++attempt) {
    castPasses(cam, p, classes);
    gl_.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    ComputeState s{};
    gl_.GetNamedBufferSubData(state_, 0, sizeof s, &s);
    drawn_ = s.drawn;
    batchesKept_ = s.batchesKept;
    if (s.tiledNeeded <= tiledCapacity_ && s.entryNeeded <= entryCapacity_) break;
    if (attempt == 1)
      throw std::logic_error("ComputeGlyphs::castFrame: the tile lists overflowed a cast sized for them");
    allocateLists(s.tiledNeeded, s.entryNeeded);
  }
  gl::checkError(gl_, "ComputeGlyphs::castFrame");
}

void ComputeGlyphs::resolve(const Camera& cam, const FrameParams& p, const std::vector<CastClass>& classes,
                            GLuint depth, GLuint record, bool surface, bool hitGC) {
  if (!depthResolve_)
    depthResolve_ = std::make_unique<gl::Program>(
        gl_, lib_, std::initializer_list<gl::StageSource>{{GL_COMPUTE_SHADER, "compute_resolve.comp"}});
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_VIS, vis_);
  gl_.BindImageTexture(TG_IMAGE_CAST_DEPTH, depth, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  gl_.BindImageTexture(TG_IMAGE_CAST_RECORD, record, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32UI);
  const auto gx = GLuint((cam.width + 7) / 8), gy = GLuint((cam.height + 7) / 8);
  setUniforms(*depthResolve_, cam, p, nullptr, 0);
  gl_.DispatchCompute(gx, gy, 1);
  if (surface) {
    gl_.BindImageTexture(TG_IMAGE_CAST_NORMAL, targets_.view(CastTargets::kNormal), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                         GL_RGBA32F);
    gl_.BindImageTexture(TG_IMAGE_CAST_HIT_GC, targets_.view(CastTargets::kHitGC), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                         GL_RGBA32F);
    for (const CastClass& c : classes) {
      const gl::Program& prog = classProgram(kSurface, c.program);
      setUniforms(prog, cam, p, &c, 0);
      prog.set("uHitGC", hitGC ? 1 : 0);
      for (const RecordChunk& chunk : chunks_) {
        bindChunk(prog, chunk);
        gl_.DispatchCompute(gx, gy, 1);
      }
    }
  }
  gl_.MemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  gl::checkError(gl_, "ComputeGlyphs::resolve");
}

namespace {

void refuse(const FrameParams& p) {
  if (p.tessellation > 0)
    throw std::invalid_argument(
        "GlyphRenderer::render: the compute glyph path casts rays; a tessellated frame needs the raster path");
  if (glyphKind(p.glyph).draw == KindDraw::Blob)
    throw std::invalid_argument("GlyphRenderer::render: the compute glyph path casts no blobs; use the cpu path");
}

}  // namespace

void ComputeGlyphs::drawView(const Camera& cam, const FrameParams& p, const GBuffer& target) {
  refuse(p);
  if (target.width() != cam.width || target.height() != cam.height)
    throw std::invalid_argument("GlyphRenderer::render: the target is not the camera's size");
  const auto classes = computeCastClasses(p, {sphereCount_, definiteCount_, records_ - sphereCount_ - definiteCount_});
  castFrame(cam, p, classes, false);
  targets_.allocateView(cam.width, cam.height, p.color == ColorMode::Sign);
  if (drawn_ > 0)
    resolve(cam, p, classes, targets_.view(CastTargets::kDepth), targets_.view(CastTargets::kRecord), true,
            p.color == ColorMode::Sign);
  target.beginGeometry();
  if (drawn_ == 0) return;
  targets_.writeView(cam, chunks_);
}

std::pair<glm::dvec3, glm::dvec3> ComputeGlyphs::castersBoxWC(const FrameParams& p) const {
  return render::castersBoxWC(centresLoWC_, centresHiWC_, maxAbsEigenvalue_, p);
}

void ComputeGlyphs::drawShadowCasters(const Camera& light, const FrameParams& p, ShadowPass& shadow) {
  refuse(p);
  const auto classes = computeCastClasses(p, {sphereCount_, definiteCount_, records_ - sphereCount_ - definiteCount_});
  castFrame(light, p, classes, true);
  targets_.allocateLight(light.width);
  resolve(light, p, classes, targets_.lightDepth(), targets_.lightRecord(), false, false);
  targets_.writeLight(light.width, shadow);
}

std::size_t ComputeGlyphs::gpuBytes() const {
  const bool scalars = !chunks_.empty() && chunks_[0].scalars;
  const std::size_t batches = (records_ + kBatchRecords - 1) / kBatchRecords + chunks_.size();
  return records_ * (sizeof(tensor::GlyphRecord) + (scalars ? sizeof(float) : 0)) + batches * (sizeof(BatchBounds) + 4) +
         targets_.bytes() +
         pixelCapacity_ * 8 + tileCapacity_ * 16 + tiledCapacity_ * kCandidateBytes +
         entryCapacity_ * 4;
}

}  // namespace tg::render
