#include "render/tessellated.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace tg::render {

TessellatedGlyphs::TessellatedGlyphs(const gl::Api& gl, const gl::ShaderLibrary& lib) : gl_(gl), lib_(lib) {
  gl.CreateVertexArrays(1, &vao_);
}

const gl::Program& TessellatedGlyphs::build() {
  if (!program_)
    program_ = std::make_unique<gl::Program>(
        gl_, lib_, std::initializer_list<gl::StageSource>{{GL_VERTEX_SHADER, "tessellated.vert"},
                                                          {GL_FRAGMENT_SHADER, "tessellated.frag"}});
  return *program_;
}

TessellatedGlyphs::~TessellatedGlyphs() {
  if (indices_) gl_.DeleteBuffers(1, &indices_);
  gl_.DeleteVertexArrays(1, &vao_);
}

std::size_t TessellatedGlyphs::perGlyphMeshBytes(int r) {
  const auto n = std::size_t(r);
  return (n + 1) * (n + 1) * 6 * sizeof(float) + 2 * n * n * 3 * sizeof(std::uint32_t);
}

void TessellatedGlyphs::draw(int r, std::size_t count) {
  if (r < kMinResolution || r > kMaxResolution)
    throw std::runtime_error("TessellatedGlyphs::draw: resolution " + std::to_string(r) + " outside " +
                             std::to_string(kMinResolution) + ".." + std::to_string(kMaxResolution));
  if (count == 0) return;
  if (r != resolution_) {
    // Two triangles per grid cell; vertex (i, j) is j * (R + 1) + i.
    std::vector<std::uint16_t> idx;
    const int w = r + 1;
    for (int j = 0; j < r; ++j)
      for (int i = 0; i < r; ++i) {
        const auto a = std::uint16_t(j * w + i), b = std::uint16_t(a + 1), c = std::uint16_t(a + w),
                   d = std::uint16_t(a + w + 1);
        idx.insert(idx.end(), {a, c, b, b, c, d});
      }
    if (indices_) gl_.DeleteBuffers(1, &indices_);
    gl_.CreateBuffers(1, &indices_);
    meshBytes_ = idx.size() * sizeof(idx[0]);
    gl_.NamedBufferStorage(indices_, GLsizeiptr(meshBytes_), idx.data(), 0);
    gl_.VertexArrayElementBuffer(vao_, indices_);
    resolution_ = r;
  }
  const gl::Program& prog = build();
  prog.set("uResolution", r);
  gl_.UseProgram(prog.id());
  gl_.BindVertexArray(vao_);
  gl_.DrawElementsInstanced(GL_TRIANGLES, 6 * r * r, GL_UNSIGNED_SHORT, nullptr, GLsizei(count));
  gl::checkError(gl_, "TessellatedGlyphs::draw");
}

}  // namespace tg::render
