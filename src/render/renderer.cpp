#include "render/renderer.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

namespace tg::render {

GlyphRenderer::GlyphRenderer(const gl::Api& gl, const gl::ShaderLibrary& lib)
    : gl_(gl),
      ellipsoid_(gl, lib, {{GL_VERTEX_SHADER, "ellipsoid.vert"}, {GL_GEOMETRY_SHADER, "sprite.geom"},
                           {GL_FRAGMENT_SHADER, "ellipsoid.frag"}}),
      lighting_(gl, lib, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "lighting.frag"}}) {
  // Core profile draws need a vertex array object even with no attributes:
  // every glyph is pulled from the storage buffer by gl_VertexID.
  gl.CreateVertexArrays(1, &vao_);
}

GlyphRenderer::~GlyphRenderer() {
  if (buffer_) gl_.DeleteBuffers(1, &buffer_);
  gl_.DeleteVertexArrays(1, &vao_);
}

void GlyphRenderer::upload(const tensor::GlyphSet& set) {
  if (set.glyphs.size() > std::size_t(std::numeric_limits<GLsizei>::max()))
    throw std::runtime_error("GlyphRenderer::upload: more glyphs than one draw call can address");
  if (buffer_) gl_.DeleteBuffers(1, &buffer_);
  buffer_ = 0;
  count_ = GLsizei(set.glyphs.size());
  mdMin_ = float(set.mdMin);
  mdMax_ = float(set.mdMax);
  if (count_ == 0) return;
  gl_.CreateBuffers(1, &buffer_);
  gl_.NamedBufferStorage(buffer_, GLsizeiptr(set.glyphs.size() * sizeof(tensor::GlyphRecord)),
                         set.glyphs.data(), 0);
  gl::checkError(gl_, "GlyphRenderer::upload");
}

void GlyphRenderer::setCamera(const gl::Program& prog, const Camera& cam) const {
  prog.set("uViewWCVC", glm::mat4(cam.viewWCVC));
  prog.set("uProjVCCC", glm::mat4(cam.projVCCC));
  prog.set("uViewportDC", glm::vec2(float(cam.width), float(cam.height)));
  const bool ortho = cam.desc.projection == Projection::Orthographic;
  prog.set("uOrtho", ortho ? 1 : 0);
  const double aspect = double(cam.width) / cam.height;
  const double h = ortho ? 0.5 * cam.desc.orthoHeight : std::tan(glm::radians(cam.desc.fovYDeg) * 0.5);
  prog.set("uRayScaleVC", glm::vec2(float(h * aspect), float(h)));
  prog.set("uNearVC", float(cam.nearVC));
  prog.set("uFarVC", ortho ? float(cam.farVC) : std::numeric_limits<float>::max());
}

void GlyphRenderer::render(const Camera& cam, const FrameParams& p, const GBuffer& target) const {
  gl_.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  target.beginGeometry();
  if (count_ > 0) {
    gl_.Enable(GL_DEPTH_TEST);
    gl_.DepthFunc(GL_GREATER);  // reversed Z
    gl_.DepthMask(GL_TRUE);
    setCamera(ellipsoid_, cam);
    ellipsoid_.set("uScale", float(p.scale));
    ellipsoid_.set("uFaMin", float(p.faMin));
    ellipsoid_.set("uColorMode", int(p.color));
    ellipsoid_.set("uMdRange", glm::vec2(mdMin_, mdMax_));
    gl_.UseProgram(ellipsoid_.id());
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer_);
    gl_.BindVertexArray(vao_);
    gl_.DrawArrays(GL_POINTS, 0, count_);
  }
  gl_.Disable(GL_DEPTH_TEST);
  target.beginLighting();
  setCamera(lighting_, cam);
  lighting_.set("uBackground", p.background);
  lighting_.set("uKeyDirVC", p.light.keyDirVC);
  lighting_.set("uLightMix", glm::vec4(p.light.ambient, p.light.head, p.light.key, p.light.specular));
  lighting_.set("uShininess", p.light.shininess);
  gl_.UseProgram(lighting_.id());
  gl_.BindVertexArray(vao_);
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);
  gl::checkError(gl_, "GlyphRenderer::render");
}

FrameImage GlyphRenderer::readback(const Camera& cam, const GBuffer& t) const {
  FrameImage img;
  const int w = t.width(), h = t.height();
  img.width = w;
  img.height = h;
  const std::size_t n = std::size_t(w) * h;
  std::vector<float> rgba(4 * n), normal(4 * n), depth(n);
  std::vector<std::uint32_t> id(n);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  auto bytes = [](const auto& v) { return GLsizei(v.size() * sizeof(v[0])); };
  gl_.GetTextureImage(t.color(), 0, GL_RGBA, GL_FLOAT, bytes(rgba), rgba.data());
  gl_.GetTextureImage(t.normalWC(), 0, GL_RGBA, GL_FLOAT, bytes(normal), normal.data());
  gl_.GetTextureImage(t.depth(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, bytes(depth), depth.data());
  gl_.GetTextureImage(t.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, bytes(id), id.data());
  gl::checkError(gl_, "GlyphRenderer::readback");
  img.rgba.resize(4 * n);
  img.depth.resize(n);
  img.normalWC.resize(3 * n);
  img.id.resize(n);
  for (int j = 0; j < h; ++j) {
    const std::size_t src = std::size_t(h - 1 - j) * w, dst = std::size_t(j) * w;  // GL rows run bottom-up
    for (int i = 0; i < w; ++i) {
      const std::size_t s = src + i, d = dst + i;
      for (int c = 0; c < 4; ++c) img.rgba[4 * d + c] = rgba[4 * s + c];
      img.id[d] = id[s];
      const bool empty = id[s] == 0xFFFFFFFFu;
      img.depth[d] = empty ? INFINITY : float(cam.viewDepthFromWindowDepth(depth[s]));
      for (int c = 0; c < 3; ++c) img.normalWC[3 * d + c] = empty ? 0.0f : normal[4 * s + c];
    }
  }
  return img;
}

}  // namespace tg::render
