#include "render/antialias_pass.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "render/camera_uniforms.h"
#include "render/glyph_kind.h"
#include "render/glyph_path.h"
#include "render/kind_programs.h"
#include "shaders/lib/bindings.h"
#include "tensor/glyph.h"

namespace tg::render {
namespace {

double halton(int k, int base) {
  double f = 1.0, r = 0.0;
  for (int i = k; i > 0; i /= base) {
    f /= base;
    r += f * (i % base);
  }
  return r;
}

}  // namespace

glm::dvec2 sampleOffset(int k) { return {halton(k, 2) - 0.5, halton(k, 3) - 0.5}; }

AntialiasPass::AntialiasPass(const gl::Api& gl, const gl::ShaderLibrary& lib)
    : gl_(gl),
      lib_(lib),
      accumulate_(gl, lib, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "aa_accumulate.frag"}}),
      resolve_(gl, lib, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "aa_resolve.frag"}}) {
  gl.CreateVertexArrays(1, &vao_);
  gl::checkError(gl, "AntialiasPass");
}

AntialiasPass::~AntialiasPass() {
  if (sumFbo_) gl_.DeleteFramebuffers(1, &sumFbo_);
  if (maskedFbo_) gl_.DeleteFramebuffers(1, &maskedFbo_);
  if (sum_) gl_.DeleteTextures(1, &sum_);
  if (sumDepth_) gl_.DeleteTextures(1, &sumDepth_);
  if (idRecords_) gl_.DeleteBuffers(1, &idRecords_);
  gl_.DeleteVertexArrays(1, &vao_);
}

void AntialiasPass::allocate(int width, int height, bool frames) {
  if (!(sum_ && width_ == width && height_ == height)) {
    sample_.reset();
    if (sumFbo_) gl_.DeleteFramebuffers(1, &sumFbo_);
    if (maskedFbo_) gl_.DeleteFramebuffers(1, &maskedFbo_);
    maskedFbo_ = maskedColor_ = 0;
    if (sum_) gl_.DeleteTextures(1, &sum_);
    if (sumDepth_) gl_.DeleteTextures(1, &sumDepth_);
    gl_.CreateTextures(GL_TEXTURE_2D, 1, &sum_);
    gl_.TextureStorage2D(sum_, 1, GL_RGBA32F, width, height);
    gl_.TextureParameteri(sum_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl_.TextureParameteri(sum_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_.CreateTextures(GL_TEXTURE_2D, 1, &sumDepth_);
    gl_.TextureStorage2D(sumDepth_, 1, GL_DEPTH_COMPONENT32F, width, height);
    gl_.CreateFramebuffers(1, &sumFbo_);
    gl_.NamedFramebufferTexture(sumFbo_, GL_COLOR_ATTACHMENT0, sum_, 0);
    gl_.NamedFramebufferTexture(sumFbo_, GL_DEPTH_ATTACHMENT, sumDepth_, 0);
    if (gl_.CheckNamedFramebufferStatus(sumFbo_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("AntialiasPass: the samples' sum framebuffer is incomplete");
    width_ = width;
    height_ = height;
  }
  if (frames && !sample_) sample_ = std::make_unique<GBuffer>(gl_, width, height);
  if (!frames) sample_.reset();
}

void AntialiasPass::accumulate(GLuint color, GLuint frameId) const {
  gl_.BindFramebuffer(GL_FRAMEBUFFER, sumFbo_);
  gl_.Viewport(0, 0, width_, height_);
  gl_.Disable(GL_DEPTH_TEST);
  gl_.Enable(GL_BLEND);
  gl_.BlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  gl_.BindTextureUnit(TG_UNIT_AA_SAMPLE, color);
  gl_.BindTextureUnit(TG_UNIT_AA_FRAME_ID, frameId);
  gl_.UseProgram(accumulate_.id());
  gl_.BindVertexArray(vao_);
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);
  gl_.Disable(GL_BLEND);
}

bool AntialiasPass::byCoverage(const PassFrame& f) {
  return glyphKind(f.p.glyph).draw != KindDraw::Blob && f.p.tessellation == 0 && f.glyphs.recordBuffer() != 0;
}

void AntialiasPass::run(const PassFrame& f) {
  if (byCoverage(f)) runCoverage(f);
  else runFrames(f);
  gl::checkError(gl_, "AntialiasPass::run");
}

void AntialiasPass::runFrames(const PassFrame& f) {
  if (!f.drawSample) throw std::logic_error("AntialiasPass::run: the frame draws no samples");
  allocate(f.target.width(), f.target.height(), true);
  const float zero[4] = {0, 0, 0, 0};
  gl_.ClearNamedFramebufferfv(sumFbo_, GL_COLOR, 0, zero);
  accumulate(f.target.color(), f.target.id());
  for (int k = 1; k < f.p.samples; ++k) {
    gl_.BindTextureUnit(TG_UNIT_AA_FRAME_ID, f.target.id());  // the sample's lighting lights only the edges
    f.drawSample(withPixelOffset(f.cam, sampleOffset(k)), *sample_);
    accumulate(sample_->color(), f.target.id());
  }
  resolve(f, f.p.samples);
}

void AntialiasPass::runCoverage(const PassFrame& f) {
  allocate(f.target.width(), f.target.height(), false);
  const GLuint records = f.glyphs.recordBuffer();
  if (!idRecords_ || idRecordsOf_ != f.uploads) {
    // Which record holds each input id: read back once per upload, so a
    // frame without anti-aliasing keeps nothing of it.
    GLint64 bytes = 0;
    gl_.GetNamedBufferParameteri64v(records, GL_BUFFER_SIZE, &bytes);
    std::size_t n = std::size_t(bytes) / sizeof(tensor::GlyphRecord);
    std::vector<tensor::GlyphRecord> all(n);
    if (n > 0) gl_.GetNamedBufferSubData(records, 0, GLsizeiptr(n * sizeof(tensor::GlyphRecord)), all.data());
    // A table by id where the ids are dense enough (input indices of a
    // volume, a mask's share of them), else sorted pairs for a binary search.
    std::uint32_t maxId = 0;
    for (const tensor::GlyphRecord& g : all) maxId = std::max(maxId, g.id);
    dense_ = n > 0 && std::uint64_t(maxId) + 1 <= 4 * std::uint64_t(n) + 1024;
    std::vector<std::uint32_t> table;
    if (dense_) {
      table.assign(std::size_t(maxId) + 1, 0xFFFFFFFFu);
      for (std::size_t i = 0; i < n; ++i) table[all[i].id] = std::uint32_t(i);
    } else {
      std::vector<glm::uvec2> pairs(n);
      for (std::size_t i = 0; i < n; ++i) pairs[i] = {all[i].id, std::uint32_t(i)};
      std::sort(pairs.begin(), pairs.end(), [](const glm::uvec2& a, const glm::uvec2& b) { return a.x < b.x; });
      table.reserve(2 * n);
      for (const glm::uvec2& q : pairs) table.insert(table.end(), {q.x, q.y});
    }
    all = {};
    if (table.empty()) table.assign(2, 0xFFFFFFFFu);  // a buffer of no pairs still binds
    if (idRecords_) gl_.DeleteBuffers(1, &idRecords_);
    gl_.CreateBuffers(1, &idRecords_);
    gl_.NamedBufferStorage(idRecords_, GLsizeiptr(table.size() * sizeof(std::uint32_t)), table.data(), 0);
    n = table.size();
    idRecordCount_ = n;  // words
    idRecordsOf_ = f.uploads;
  }
  const KindDraw draw = glyphKind(f.p.glyph).draw;
  const int cast = draw == KindDraw::Ellipsoid ? 0 : draw == KindDraw::Superquadric ? 1 : f.p.glyph == GlyphKind::Cylinder ? 2 : 3;
  if (!coverage_[std::size_t(cast)]) {
    std::vector<std::string_view> enable;
    if (cast == 1) enable.push_back("TG_AA_MARCH");
    if (cast >= 2) enable.push_back("TG_AA_PRISM");
    if (cast == 2) enable.push_back("TG_CYLINDER");
    coverage_[std::size_t(cast)] = std::make_unique<gl::Program>(
        gl_, lib_, std::initializer_list<gl::StageSource>{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "aa_coverage.frag"}},
        enable);
  }
  if (!mark_)
    mark_ = std::make_unique<gl::Program>(
        gl_, lib_, std::initializer_list<gl::StageSource>{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "aa_mark.frag"}});
  const gl::Program& prog = *coverage_[std::size_t(cast)];
  setCameraUniforms(prog, f.cam);
  setGlyphUniforms(prog, f.p, nullptr);
  prog.set("uDenseIds", dense_ ? 1 : 0);
  prog.set("uGamma", float(f.p.gamma));
  prog.set("uEpsilon", float(f.p.march.epsilon));
  prog.set("uMaxIterations", f.p.march.maxIterations);
  prog.set("uSamples", f.p.samples);
  std::vector<glm::vec4> offsets(16, glm::vec4(0.0f));
  for (int k = 1; k < f.p.samples; ++k) {
    const glm::dvec2 o = sampleOffset(k);  // x right, y down: GL's window y is up
    offsets[std::size_t(k)] = glm::vec4(float(o.x), float(-o.y), 0.0f, 0.0f);
  }
  prog.set("uSampleOffsets", std::span<const glm::vec4>(offsets));
  if (maskedColor_ != f.target.color()) {
    if (maskedFbo_) gl_.DeleteFramebuffers(1, &maskedFbo_);
    gl_.CreateFramebuffers(1, &maskedFbo_);
    gl_.NamedFramebufferTexture(maskedFbo_, GL_COLOR_ATTACHMENT0, f.target.color(), 0);
    gl_.NamedFramebufferTexture(maskedFbo_, GL_DEPTH_ATTACHMENT, sumDepth_, 0);
    if (gl_.CheckNamedFramebufferStatus(maskedFbo_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("AntialiasPass: the masked colour framebuffer is incomplete");
    maskedColor_ = f.target.color();
  }
  // The casts read the lit frame from a copy and write the frame itself.
  gl_.CopyImageSubData(f.target.color(), GL_TEXTURE_2D, 0, 0, 0, 0, sum_, GL_TEXTURE_2D, 0, 0, 0, 0, width_, height_, 1);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, maskedFbo_);
  gl_.Viewport(0, 0, width_, height_);
  gl_.Disable(GL_BLEND);
  // The edge mask: the fullscreen triangle's depth (0) where aa_mark.frag
  // keeps the pixel, 1 elsewhere; the casts then pass an EQUAL test only
  // there, early (aa_coverage.frag), so other pixels are never shaded.
  const float one = 1.0f;
  gl_.ClearNamedFramebufferfv(maskedFbo_, GL_DEPTH, 0, &one);
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthMask(GL_TRUE);
  gl_.DepthFunc(GL_ALWAYS);
  gl_.BindTextureUnit(TG_UNIT_AA_FRAME_ID, f.target.id());
  gl_.UseProgram(mark_->id());
  gl_.BindVertexArray(vao_);
  gl_.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);
  gl_.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl_.DepthMask(GL_FALSE);
  gl_.DepthFunc(GL_EQUAL);
  gl_.BindTextureUnit(TG_UNIT_AA_SAMPLE, sum_);
  gl_.BindTextureUnit(TG_UNIT_AA_DEPTH, f.target.depth());
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_GLYPHS, records);
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_AA_ID_RECORDS, idRecords_);
  gl_.UseProgram(prog.id());
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);
  // As the renderer leaves depth for the next passes (reversed Z).
  gl_.DepthMask(GL_TRUE);
  gl_.DepthFunc(GL_GREATER);
  gl_.Disable(GL_DEPTH_TEST);
}

void AntialiasPass::resolve(const PassFrame& f, int samples) const {
  gl_.BindFramebuffer(GL_FRAMEBUFFER, f.target.colorFramebuffer());
  gl_.Viewport(0, 0, width_, height_);
  gl_.BindTextureUnit(TG_UNIT_AA_SUM, sum_);
  gl_.BindTextureUnit(TG_UNIT_AA_FRAME_ID, f.target.id());
  resolve_.set("uSamples", float(samples));
  gl_.UseProgram(resolve_.id());
  gl_.BindVertexArray(vao_);
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);
}

std::span<const Attachment> AntialiasPass::reads() const {
  static constexpr Attachment kReads[] = {Attachment::Id, Attachment::Color};
  return kReads;
}

std::span<const Attachment> AntialiasPass::writes() const {
  static constexpr Attachment kWrites[] = {Attachment::Color};
  return kWrites;
}

std::size_t AntialiasPass::gpuBytes() const {
  const std::size_t sum = sum_ ? std::size_t(width_) * std::size_t(height_) * 20 : 0;
  return sum + (sample_ ? std::size_t(GBuffer::bytesFor(width_, height_)) : 0) + idRecordCount_ * sizeof(std::uint32_t);
}

}  // namespace tg::render
