#include "render/cast_targets.h"

#include <algorithm>
#include <limits>

#include "render/camera_uniforms.h"
#include "render/kind_programs.h"
#include "render/shadow_pass.h"
#include "shaders/lib/bindings.h"

namespace tg::render {

namespace {

void makeTextures(const gl::Api& gl, std::size_t n, GLuint* tex, const GLenum* formats, int width, int height) {
  gl.CreateTextures(GL_TEXTURE_2D, GLsizei(n), tex);
  for (std::size_t k = 0; k < n; ++k) {
    gl.TextureStorage2D(tex[k], 1, formats[k], width, height);
    gl.TextureParameteri(tex[k], GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TextureParameteri(tex[k], GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
}

}  // namespace

CastTargets::CastTargets(const gl::Api& gl, const gl::ShaderLibrary& lib, GLenum normalFormat)
    : gl_(gl), lib_(lib), normalFormat_(normalFormat), gbuffer_(gl, lib, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "cpu_gbuffer.frag"}}) {
  gl.CreateVertexArrays(1, &vao_);
  gl::checkError(gl, "CastTargets");
}

CastTargets::~CastTargets() {
  if (view_[0]) gl_.DeleteTextures(4, view_);
  if (light_[0]) gl_.DeleteTextures(2, light_);
  gl_.DeleteVertexArrays(1, &vao_);
}

void CastTargets::allocateView(int width, int height, bool hitGC) {
  if (!view_[0] || width_ != width || height_ != height) {
    if (view_[0]) gl_.DeleteTextures(3, view_);
    width_ = width;
    height_ = height;
    const GLenum formats[3] = {GL_R32F, GL_R32UI, normalFormat_};
    makeTextures(gl_, 3, view_, formats, width, height);
  }
  const int hw = hitGC ? width : 1, hh = hitGC ? height : 1;
  if (!view_[kHitGC] || hitSize_[0] != hw || hitSize_[1] != hh) {
    if (view_[kHitGC]) gl_.DeleteTextures(1, &view_[kHitGC]);
    hitSize_[0] = hw;
    hitSize_[1] = hh;
    const GLenum format = GL_RGBA32F;
    makeTextures(gl_, 1, &view_[kHitGC], &format, hw, hh);
  }
}

void CastTargets::allocateLight(int size) {
  if (light_[0] && lightSize_ == size) return;
  if (light_[0]) gl_.DeleteTextures(2, light_);
  lightSize_ = size;
  const GLenum formats[2] = {GL_R32F, GL_R32UI};
  makeTextures(gl_, 2, light_, formats, size, size);
}

void CastTargets::fullScreen(const gl::Program& prog) const {
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_ALWAYS);
  gl_.DepthMask(GL_TRUE);
  gl_.UseProgram(prog.id());
  gl_.BindVertexArray(vao_);
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);
  gl_.DepthFunc(GL_GREATER);  // reversed Z, as the raster path leaves it for the context
}

void CastTargets::setGlyphParams(const FrameParams& p, const FrameParams* old) const { setGlyphUniforms(gbuffer_, p, old); }

void CastTargets::setColorWindow(glm::dvec2 window) const { gbuffer_.set("uColorWindow", glm::vec2(window)); }

void CastTargets::writeView(const Camera& cam, std::span<const RecordChunk> chunks) const {
  setCameraUniforms(gbuffer_, cam);
  gl_.BindTextureUnit(TG_UNIT_CPU_DEPTH, view_[kDepth]);
  gl_.BindTextureUnit(TG_UNIT_CPU_RECORD, view_[kRecord]);
  gl_.BindTextureUnit(TG_UNIT_CPU_NORMAL, view_[kNormal]);
  gl_.BindTextureUnit(TG_UNIT_CPU_HIT_GC, view_[kHitGC]);
  for (const RecordChunk& c : chunks) {
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_GLYPHS, c.records);
    if (c.scalars) gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_COLOR_SCALARS, c.scalars);
    gbuffer_.set("uRecordBase", int(c.first));
    gbuffer_.set("uRecordCount", int(std::min<std::size_t>(c.count, std::numeric_limits<int>::max())));
    fullScreen(gbuffer_);
  }
  gl::checkError(gl_, "CastTargets::writeView");
}

void CastTargets::writeLight(int size, ShadowPass& shadow) {
  if (!depth_)
    depth_ = std::make_unique<gl::Program>(
        gl_, lib_, std::initializer_list<gl::StageSource>{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "cpu_depth.frag"}});
  shadow.beginMap(size);
  gl_.BindTextureUnit(TG_UNIT_CPU_DEPTH, light_[0]);
  gl_.BindTextureUnit(TG_UNIT_CPU_RECORD, light_[1]);
  fullScreen(*depth_);
  gl::checkError(gl_, "CastTargets::writeLight");
}

std::size_t CastTargets::bytes() const {
  return (view_[0] ? std::size_t(width_) * std::size_t(height_) * (normalFormat_ == GL_RGB32F ? 20 : 24) : 0) +
         std::size_t(hitSize_[0]) * std::size_t(hitSize_[1]) * 16 +
         (light_[0] ? std::size_t(lightSize_) * std::size_t(lightSize_) * 8 : 0);
}

}  // namespace tg::render
