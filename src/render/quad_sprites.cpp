#include "render/quad_sprites.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace tg::render {

QuadSprites::QuadSprites(const gl::Api& gl) : gl_(gl) {
  std::vector<std::uint16_t> idx(6 * std::size_t(kQuadsPerBatch));
  for (GLsizei q = 0; q < kQuadsPerBatch; ++q) {
    const auto v = std::uint16_t(4 * q);
    const std::uint16_t tri[6] = {v, std::uint16_t(v + 1), std::uint16_t(v + 2),
                                  std::uint16_t(v + 2), std::uint16_t(v + 1), std::uint16_t(v + 3)};
    for (int k = 0; k < 6; ++k) idx[6 * std::size_t(q) + k] = tri[k];
  }
  gl.CreateBuffers(1, &indices_);
  gl.NamedBufferStorage(indices_, GLsizeiptr(idx.size() * sizeof(idx[0])), idx.data(), 0);
  gl.CreateVertexArrays(1, &vao_);
  gl.VertexArrayElementBuffer(vao_, indices_);
  gl::checkError(gl, "QuadSprites::QuadSprites");
}

QuadSprites::~QuadSprites() {
  gl_.DeleteVertexArrays(1, &vao_);
  gl_.DeleteBuffers(1, &indices_);
}

void QuadSprites::draw(std::span<const GlyphRun> runs, bool points) const {
  if (points) {
    std::vector<GLint> firsts;
    std::vector<GLsizei> counts;
    for (const GlyphRun& r : runs) {
      if (std::int64_t(r.first) + r.count > std::int64_t(INT32_MAX))
        throw std::runtime_error("QuadSprites::draw: glyph range beyond 2^31");
      firsts.push_back(GLint(r.first));
      counts.push_back(GLsizei(r.count));
    }
    if (counts.empty()) return;
    gl_.BindVertexArray(vao_);
    gl_.Enable(GL_PROGRAM_POINT_SIZE);
    gl_.MultiDrawArrays(GL_POINTS, firsts.data(), counts.data(), GLsizei(counts.size()));
    return;
  }
  std::vector<GLsizei> counts;
  std::vector<const void*> offsets;
  std::vector<GLint> baseVertices;
  for (const GlyphRun& r : runs) {
    // gl_VertexID = 4 * glyph + corner, so the vertex index range must fit a GLint.
    if (std::int64_t(r.first) + r.count > std::int64_t(INT32_MAX) / 4)
      throw std::runtime_error("QuadSprites::draw: glyph range beyond 2^29");
    for (std::uint32_t done = 0; done < r.count; done += kQuadsPerBatch) {
      const GLsizei n = std::min(kQuadsPerBatch, GLsizei(r.count - done));
      counts.push_back(6 * n);
      offsets.push_back(nullptr);
      baseVertices.push_back(GLint(4 * (r.first + done)));
    }
  }
  if (counts.empty()) return;
  gl_.BindVertexArray(vao_);
  gl_.MultiDrawElementsBaseVertex(GL_TRIANGLES, counts.data(), GL_UNSIGNED_SHORT, offsets.data(),
                                  GLsizei(counts.size()), baseVertices.data());
}

void QuadSprites::drawIndirect(GLuint commands, GLsizei first, GLsizei count, bool points) const {
  if (count <= 0) return;
  gl_.BindVertexArray(vao_);
  gl_.BindBuffer(GL_DRAW_INDIRECT_BUFFER, commands);
  const auto* offset = reinterpret_cast<const void*>(std::size_t(first) * std::size_t(kIndirectCommandBytes));
  if (points) {
    gl_.Enable(GL_PROGRAM_POINT_SIZE);
    gl_.MultiDrawArraysIndirect(GL_POINTS, offset, count, GLsizei(kIndirectCommandBytes));
  } else {
    gl_.MultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_SHORT, offset, count, 0);
  }
  gl_.BindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

}  // namespace tg::render
