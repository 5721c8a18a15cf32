#include "render/legend/overlay_painter.h"

#include <algorithm>
#include <vector>

#include <glm/mat3x3.hpp>

#include "shaders/lib/bindings.h"

namespace tg::render {

OverlayPainter::OverlayPainter(const gl::Api& gl, const gl::ShaderLibrary& lib)
    : gl_(gl),
      swatch_(gl, lib, {{GL_VERTEX_SHADER, "legend_swatch.vert"}, {GL_FRAGMENT_SHADER, "legend_swatch.frag"}}),
      text_(gl, lib, {{GL_VERTEX_SHADER, "legend_text.vert"}, {GL_FRAGMENT_SHADER, "legend_text.frag"}}) {
  gl.CreateVertexArrays(1, &vao_);  // attribute-less draws still need one in the core profile
}

OverlayPainter::~OverlayPainter() {
  if (atlas_) gl_.DeleteTextures(1, &atlas_);
  if (vertices_) gl_.DeleteBuffers(1, &vertices_);
  gl_.DeleteVertexArrays(1, &vao_);
}

const LegendFont& OverlayPainter::font(int textScale) {
  if (font_ && font_->textScale() == textScale) return *font_;
  font_ = std::make_unique<LegendFont>(textScale);
  if (atlas_) gl_.DeleteTextures(1, &atlas_);
  gl_.CreateTextures(GL_TEXTURE_2D, 1, &atlas_);
  gl_.TextureStorage2D(atlas_, 1, GL_R8, font_->atlasWidth(), font_->atlasHeight());
  gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // Atlas row 0 at v = 0, as ImGui's texture coordinates expect.
  gl_.TextureSubImage2D(atlas_, 0, 0, 0, font_->atlasWidth(), font_->atlasHeight(), GL_RED, GL_UNSIGNED_BYTE,
                        font_->atlasPixels());
  // Text quads sit on whole pixels at the atlas's own size: nearest samples
  // each texel once, exactly.
  gl_.TextureParameteri(atlas_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl_.TextureParameteri(atlas_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl_.TextureParameteri(atlas_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl_.TextureParameteri(atlas_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return *font_;
}

void OverlayPainter::draw(const Camera& cam, const LegendLayout& layout) {
  const std::vector<LegendVertex> tri = legendTriangles(layout, *font_);
  const glm::vec2 viewport(float(cam.width), float(cam.height));
  gl_.Enable(GL_BLEND);
  gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl_.BindVertexArray(vao_);

  swatch_.set("uViewportDC", viewport);
  swatch_.set("uRotWCVC", glm::mat3(glm::dmat3(cam.viewWCVC)));
  gl_.UseProgram(swatch_.id());
  for (const LegendSwatch& s : layout.swatches) {
    swatch_.set("uRectDC", glm::vec4(s.rect.x0, s.rect.y0, s.rect.x1, s.rect.y1));
    swatch_.set("uKind", int(s.kind));
    swatch_.set("uRange", glm::vec2(s.t0, s.t1));
    swatch_.set("uFill", s.fill);
    gl_.DrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  }

  if (!tri.empty()) {
    const std::size_t bytes = tri.size() * sizeof(LegendVertex);
    if (bytes > vertexCapacity_) {
      if (vertices_) gl_.DeleteBuffers(1, &vertices_);
      vertexCapacity_ = std::max<std::size_t>(bytes, 64 * 1024);
      gl_.CreateBuffers(1, &vertices_);
      gl_.NamedBufferStorage(vertices_, GLsizeiptr(vertexCapacity_), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    gl_.NamedBufferSubData(vertices_, 0, GLsizeiptr(bytes), tri.data());
    gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_LEGEND_VERTICES, vertices_);
    text_.set("uViewportDC", viewport);
    gl_.BindTextureUnit(TG_UNIT_LEGEND_ATLAS, atlas_);
    gl_.UseProgram(text_.id());
    gl_.DrawArrays(GL_TRIANGLES, 0, GLsizei(tri.size()));
  }
  gl_.Disable(GL_BLEND);
  gl::checkError(gl_, "OverlayPainter::draw");
}

std::size_t OverlayPainter::gpuBytes() const {
  const std::size_t atlas = font_ ? std::size_t(font_->atlasWidth()) * std::size_t(font_->atlasHeight()) : 0;
  return atlas + vertexCapacity_;
}

}  // namespace tg::render
