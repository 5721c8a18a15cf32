#include "render/cast_targets.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "render/camera_uniforms.h"
#include "render/kind_programs.h"
#include "render/shadow_pass.h"
#include "render/tile_binning.h"
#include "shaders/lib/bindings.h"

namespace tg::render {

CastTargets::CastTargets(const gl::Api& gl, const gl::ShaderLibrary& lib, GLenum normalFormat, bool mapped)
    : gl_(gl),
      lib_(lib),
      normalFormat_(normalFormat),
      mapped_(mapped),
      gbuffer_(gl, lib, {{GL_VERTEX_SHADER, mapped ? "cast_runs.vert" : "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "cpu_gbuffer.frag"}}) {
  gl.CreateVertexArrays(1, &vao_);
  gl::checkError(gl, "CastTargets");
}

CastTargets::~CastTargets() {
  if (reads_) gl_.DeleteSync(reads_);
  for (Target& t : view_) release(t);
  for (Target& t : light_) release(t);
  release(runs_);
  gl_.DeleteVertexArrays(1, &vao_);
}

void CastTargets::release(Target& t) {
  if (t.texture) gl_.DeleteTextures(1, &t.texture);
  if (t.buffer) gl_.DeleteBuffers(1, &t.buffer);  // unmaps it
  t = {};
}

void CastTargets::resize(Target& t, GLenum format, std::size_t texelBytes, std::size_t texels) {
  if (t.texture && t.texels == texels) return;
  GLint most = 0;
  gl_.GetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &most);
  if (texels > std::size_t(std::max(most, 0)))
    throw std::runtime_error("GlyphRenderer::render: " + std::to_string(texels) + " pixels pass this GL's " +
                             std::to_string(most) + " texels of a buffer texture (GL_MAX_TEXTURE_BUFFER_SIZE)");
  waitForReads();
  release(t);
  const auto bytes = GLsizeiptr(texels * texelBytes);
  gl_.CreateBuffers(1, &t.buffer);
  constexpr GLbitfield kMap = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
  gl_.NamedBufferStorage(t.buffer, bytes, nullptr, mapped_ ? kMap : 0);
  if (mapped_) {
    t.mapped = gl_.MapNamedBufferRange(t.buffer, 0, bytes, kMap);
    if (!t.mapped) throw std::runtime_error("GlyphRenderer::render: this GL maps no " + std::to_string(bytes) + "-byte buffer for the casts");
  }
  gl_.CreateTextures(GL_TEXTURE_BUFFER, 1, &t.texture);
  gl_.TextureBuffer(t.texture, format, t.buffer);
  t.texels = texels;
  gl::checkError(gl_, "CastTargets::allocate");
}

void CastTargets::allocateView(int width, int height, bool hitGC) {
  const std::size_t n = std::size_t(width) * std::size_t(height);
  resize(view_[kDepth], GL_R32F, 4, n);
  resize(view_[kRecord], GL_R32UI, 4, n);
  resize(view_[kNormal], normalFormat_, normalFormat_ == GL_RGB32F ? 12 : 16, n);
  resize(view_[kHitGC], GL_RGBA32F, 16, hitGC ? n : 1);
  width_ = width;
  height_ = height;
}

void CastTargets::allocateLight(int size) {
  const std::size_t n = std::size_t(size) * std::size_t(size);
  resize(light_[0], GL_R32F, 4, n);
  resize(light_[1], GL_R32UI, 4, n);
  lightSize_ = size;
}

void CastTargets::fence() {
  if (reads_) gl_.DeleteSync(reads_);
  reads_ = gl_.FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

void CastTargets::waitForReads() {
  if (!reads_) return;
  while (true) {
    const GLenum r = gl_.ClientWaitSync(reads_, GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000);
    if (r == GL_ALREADY_SIGNALED || r == GL_CONDITION_SATISFIED) break;
    if (r == GL_WAIT_FAILED) throw std::runtime_error("CastTargets: waiting for GL to read the casts failed");
  }
  gl_.DeleteSync(reads_);
  reads_ = nullptr;
}

void CastTargets::draw(const gl::Program& prog, int width, int height, std::span<const PixelRect> runs) {
  if (!mapped_ && !runs.empty()) throw std::logic_error("CastTargets::draw: runs for targets a compute shader wrote");
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_ALWAYS);
  gl_.DepthMask(GL_TRUE);
  gl_.UseProgram(prog.id());
  gl_.BindVertexArray(vao_);
  if (!mapped_) {
    gl_.DrawArrays(GL_TRIANGLES, 0, 3);
  } else if (!runs.empty()) {
    static_assert(sizeof(PixelRect) == 8);  // a GL_RG32UI texel: (x0 | y0 << 16, x1 | y1 << 16)
    if (runs_.texels < runs.size()) resize(runs_, GL_RG32UI, 8, std::max(runs.size(), 2 * runs_.texels));
    waitForReads();
    std::memcpy(runs_.mapped, runs.data(), runs.size_bytes());
    gl_.BindTextureUnit(TG_UNIT_CPU_RUNS, runs_.texture);
    prog.set("uRunViewportDC", glm::vec2(float(width), float(height)));
    gl_.DrawArrays(GL_TRIANGLES, 0, GLsizei(6 * runs.size()));
  }
  gl_.DepthFunc(GL_GREATER);  // reversed Z, as the raster path leaves it for the context
}

void CastTargets::setGlyphParams(const FrameParams& p, const FrameParams* old) const { setGlyphUniforms(gbuffer_, p, old); }

void CastTargets::setColorWindow(glm::dvec2 window) const { gbuffer_.set("uColorWindow", glm::vec2(window)); }

void CastTargets::writeView(const Camera& cam, std::span<const RecordChunk> chunks, std::span<const PixelRect> runs) {
  setCameraUniforms(gbuffer_, cam);
  gl_.BindTextureUnit(TG_UNIT_CPU_DEPTH, view_[kDepth].texture);
  gl_.BindTextureUnit(TG_UNIT_CPU_RECORD, view_[kRecord].texture);
  gl_.BindTextureUnit(TG_UNIT_CPU_NORMAL, view_[kNormal].texture);
  gl_.BindTextureUnit(TG_UNIT_CPU_HIT_GC, view_[kHitGC].texture);
  gbuffer_.set("uCastWidth", width_);
  for (const RecordChunk& c : chunks) {
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_GLYPHS, c.records);
    if (c.scalars) gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_COLOR_SCALARS, c.scalars);
    gbuffer_.set("uRecordBase", int(c.first));
    gbuffer_.set("uRecordCount", int(std::min<std::size_t>(c.count, std::numeric_limits<int>::max())));
    draw(gbuffer_, cam.width, cam.height, runs);
  }
  fence();
  gl::checkError(gl_, "CastTargets::writeView");
}

void CastTargets::writeLight(int size, ShadowPass& shadow, std::span<const PixelRect> runs) {
  if (!depth_)
    depth_ = std::make_unique<gl::Program>(
        gl_, lib_, std::initializer_list<gl::StageSource>{{GL_VERTEX_SHADER, mapped_ ? "cast_runs.vert" : "fullscreen.vert"},
                                                          {GL_FRAGMENT_SHADER, "cpu_depth.frag"}});
  shadow.beginMap(size);
  gl_.BindTextureUnit(TG_UNIT_CPU_DEPTH, light_[0].texture);
  gl_.BindTextureUnit(TG_UNIT_CPU_RECORD, light_[1].texture);
  depth_->set("uCastWidth", size);
  draw(*depth_, size, size, runs);
  fence();
  gl::checkError(gl_, "CastTargets::writeLight");
}

std::size_t CastTargets::bytes() const {
  return view_[kDepth].texels * 4 + view_[kRecord].texels * 4 +
         view_[kNormal].texels * (normalFormat_ == GL_RGB32F ? 12 : 16) + view_[kHitGC].texels * 16 +
         light_[0].texels * 8 + runs_.texels * 8;
}

}  // namespace tg::render
