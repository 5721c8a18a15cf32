#include "render/glyph_culling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "render/camera_uniforms.h"
#include "view/frustum.h"
#include "shaders/lib/bindings.h"

namespace tg::render {
namespace {

void deleteBuffers(const gl::Api& gl, std::initializer_list<GLuint*> buffers) {
  for (GLuint* b : buffers) {
    if (*b) gl.DeleteBuffers(1, b);
    *b = 0;
  }
}

}  // namespace

GlyphCulling::GlyphCulling(const gl::Api& gl, const gl::ShaderLibrary& lib)
    : gl_(gl),
      lib_(lib),
      compact_(gl, lib, {{GL_COMPUTE_SHADER, "compact_fa.comp"}}),
      cull_(gl, lib, {{GL_COMPUTE_SHADER, "cull_ranges.comp"}}),
      drawnCounter_(gl) {
  gl.CreateBuffers(1, &visible_);
  gl.NamedBufferStorage(visible_, sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

GlyphCulling::~GlyphCulling() {
  deleteBuffers(gl_, {&ranges_, &keptCount_, &keptIndex_, &commands_, &visible_});
}

void GlyphCulling::upload(const tensor::GlyphSet& set, GLuint glyphBuffer) {
  deleteBuffers(gl_, {&ranges_, &keptCount_, &keptIndex_, &commands_});
  glyphs_ = glyphBuffer;
  glyphCount_ = set.glyphs.size();
  table_ = buildRanges(set);
  for (int g0 = 0; g0 < 3; ++g0)
    for (int g1 = g0 + 1; g1 <= 3; ++g1) runs_[std::size_t(4 * g0 + g1)] = groupRuns(set, g0, g1);
  centresLo_ = set.boundsMinWC;
  centresHi_ = set.boundsMaxWC;
  maxAbsEigenvalue_ = set.maxAbsEigenvalue;
  compacted_ = indirect_ = points_ = false;
  passes_ = {};
  const std::size_t n = table_.ranges.size();
  if (n == 0) return;
  gl_.CreateBuffers(1, &ranges_);
  gl_.NamedBufferStorage(ranges_, GLsizeiptr(n * sizeof(GlyphRange)), table_.ranges.data(), 0);
  gl_.CreateBuffers(1, &keptCount_);
  gl_.NamedBufferStorage(keptCount_, GLsizeiptr(n * sizeof(GLuint)), nullptr, 0);
  gl_.CreateBuffers(1, &commands_);
  gl_.NamedBufferStorage(commands_, GLsizeiptr(n) * QuadSprites::kIndirectCommandBytes, nullptr, 0);
  gl::checkError(gl_, "GlyphCulling::upload");
}

void GlyphCulling::dispatch(const gl::Program& prog, std::size_t workgroups) const {
  // GL guarantees 65535 workgroups per dimension; 10^8 glyphs make more ranges.
  const std::size_t x = std::min<std::size_t>(workgroups, 65535);
  gl_.UseProgram(prog.id());
  gl_.DispatchCompute(GLuint(x), GLuint((workgroups + x - 1) / x), 1);
}

void GlyphCulling::prepare(const Camera& cam, double scale, const tensor::SizeMapping& sizing, double faMin,
                           const Slab& slab, bool frustum, bool points, bool pixels) {
  const std::size_t n = table_.ranges.size();
  compacted_ = indirect_ = false;
  points_ = points;
  if (n == 0) return;
  // Same float comparison as the shaders: a threshold at or below every
  // glyph's FA hides nothing and costs nothing.
  const auto faMinF = float(faMin);
  if (pixels) {
    // The pixel cull applies the threshold too, and overwrites the kept list.
    cullPixels(cam, scale, sizing, faMinF, slab);
    compacted_ = true;
    compactedFor_ = std::numeric_limits<float>::quiet_NaN();
  } else if (faMinF > table_.minFa) {
    compacted_ = true;
    if (!(passes_.compactions > 0 && faMinF == compactedFor_)) {
      allocateKeptIndex();
      gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_GLYPHS, glyphs_);
      gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_RANGES, ranges_);
      gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_KEPT_COUNT, keptCount_);
      gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_KEPT_INDEX, keptIndex_);
      compact_.set("uFaMin", faMinF);
      compact_.set("uRangeCount", int(n));
      dispatch(compact_, n);
      gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      compactedFor_ = faMinF;
      ++passes_.compactions;
    }
  }
  const FrustumWC f = frustumPlanesWC(cam);
  const double pad = std::sqrt(3.0) * tensor::glyphRadiusWC(scale, sizing, maxAbsEigenvalue_);
  // Whether any range could fall outside, judged on the four side planes:
  // cameras put the near plane at the scene's nearest point, so the grown box
  // always crosses it, and a range wholly in front of it costs only the
  // vertex stage's own rejection.
  FrustumWC sides = f;
  sides[4] = sides[5] = glm::dvec4(0, 0, 0, 1);
  const bool cullRanges = frustum && !boxInside(sides, centresLo_ - pad, centresHi_ + pad);
  const bool slabbed = slab.axis >= 0;
  indirect_ = compacted_ || cullRanges || slabbed;
  if (!indirect_) return;
  // The frustum's six planes, then the slab's two (on centres; the shader's
  // growth of the box by the glyph extent only keeps more).
  std::array<glm::vec4, 8> planes;
  planes.fill(glm::vec4(0, 0, 0, 1));
  for (std::size_t k = 0; k < 6 && cullRanges; ++k) planes[k] = glm::vec4(f[k]);
  if (slabbed) {
    const glm::vec3 across(slab.direction());
    planes[6] = glm::vec4(across, -float(slab.lo));
    planes[7] = glm::vec4(-across, float(slab.hi));
  }
  const GLuint zero = 0;
  gl_.NamedBufferSubData(visible_, 0, sizeof(zero), &zero);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_RANGES, ranges_);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_KEPT_COUNT, keptCount_);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_COMMANDS, commands_);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_VISIBLE, visible_);
  cull_.set("uFrustumWC", planes);
  cull_.set("uScale", float(scale));
  cull_.set("uMagnitude", int(sizing.magnitude));
  cull_.set("uLambda0", float(sizing.lambda0));
  cull_.set("uMaxRadiusWC", float(sizing.maxRadiusWC));
  cull_.set("uCompacted", compacted_ ? 1 : 0);
  cull_.set("uRangeCount", int(n));
  cull_.set("uPointSprites", points_ ? 1 : 0);
  dispatch(cull_, (n + 63) / 64);
  gl_.MemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  ++passes_.commandPasses;
  gl::checkError(gl_, "GlyphCulling::prepare");
}

void GlyphCulling::allocateKeptIndex() {
  if (keptIndex_) return;
  gl_.CreateBuffers(1, &keptIndex_);
  gl_.NamedBufferStorage(keptIndex_, GLsizeiptr(glyphCount_ * sizeof(GLuint)), nullptr, 0);
}

void GlyphCulling::cullPixels(const Camera& cam, double scale, const tensor::SizeMapping& sizing, float faMin,
                              const Slab& slab) {
  if (!pixels_) pixels_ = std::make_unique<gl::Program>(gl_, lib_, std::initializer_list<gl::StageSource>{
                                                                    {GL_COMPUTE_SHADER, "cull_pixels.comp"}});
  allocateKeptIndex();
  const gl::Program& prog = *pixels_;
  setCameraUniforms(prog, cam);
  prog.set("uScale", float(scale));
  prog.set("uMagnitude", int(sizing.magnitude));
  prog.set("uLambda0", float(sizing.lambda0));
  prog.set("uMaxRadiusWC", float(sizing.maxRadiusWC));
  prog.set("uFaMin", faMin);
  prog.set("uSlabAxis", slab.axis);
  prog.set("uSlabNormal", glm::vec3(slab.direction()));
  prog.set("uSlabWC", glm::vec2(float(slab.lo), float(slab.hi)));
  const std::size_t n = table_.ranges.size();
  prog.set("uRangeCount", int(n));
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_GLYPHS, glyphs_);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_RANGES, ranges_);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_KEPT_COUNT, keptCount_);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_KEPT_INDEX, keptIndex_);
  dispatch(prog, (n + 7) / 8);
  gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  ++passes_.pixelCulls;
}

void GlyphCulling::draw(const QuadSprites& sprites, int g0, int g1) const {
  if (g0 >= g1 || table_.ranges.empty()) return;
  if (!indirect_) {
    sprites.draw(runs_[std::size_t(4 * g0 + g1)], points_);
    return;
  }
  if (compacted_) gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_KEPT_INDEX, keptIndex_);
  const GLuint b = table_.groupStart[std::size_t(g0)], e = table_.groupStart[std::size_t(g1)];
  sprites.drawIndirect(commands_, GLsizei(b), std::span<const GlyphRange>(table_.ranges).subspan(b, e - b), points_);
}

std::size_t GlyphCulling::gpuBytes() const {
  const std::size_t n = table_.ranges.size();
  return n * (sizeof(GlyphRange) + sizeof(GLuint) + std::size_t(QuadSprites::kIndirectCommandBytes)) + sizeof(GLuint) +
         (keptIndex_ ? glyphCount_ * sizeof(GLuint) : 0);
}

std::uint64_t GlyphCulling::drawnGlyphs() const {
  if (!indirect_) return glyphCount_;
  GLuint v = 0;
  gl_.GetNamedBufferSubData(visible_, 0, sizeof(v), &v);
  gl::checkError(gl_, "GlyphCulling::drawnGlyphs");
  return v;
}

void GlyphCulling::requestDrawnCount() {
  if (indirect_)
    drawnCounter_.request(visible_);
  else
    drawnCounter_.requestKnown(glyphCount_);
}

}  // namespace tg::render
