#pragma once
// Draws one screen quad per glyph record (see shaders/lib/sprite.glsl): a
// shared 16-bit index pattern for kQuadsPerBatch glyphs, replayed with a base
// vertex per batch, so index memory stays fixed whatever the glyph count.
#include <span>

#include "gl/loader.h"
#include "render/glyph_ranges.h"

namespace tg::render {

class QuadSprites {
 public:
  static constexpr GLsizei kQuadsPerBatch = 16384;  // 4 vertices each: the largest 16-bit batch
  static constexpr GLsizeiptr kIndirectCommandBytes = 5 * sizeof(GLuint);  // DrawElementsIndirectCommand

  explicit QuadSprites(const gl::Api& gl);
  ~QuadSprites();
  QuadSprites(const QuadSprites&) = delete;
  QuadSprites& operator=(const QuadSprites&) = delete;

  // Draws the quads of these glyph runs with the bound program, in one call.
  void draw(std::span<const GlyphRun> runs) const;
  // Draws commands [first, first + count) of an indirect buffer of
  // DrawElementsIndirectCommand, each naming its glyphs by base vertex.
  void drawIndirect(GLuint commands, GLsizei first, GLsizei count) const;

 private:
  const gl::Api& gl_;
  GLuint vao_ = 0, indices_ = 0;
};

}  // namespace tg::render
