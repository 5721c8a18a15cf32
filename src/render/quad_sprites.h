#pragma once
// Draws one screen quad per glyph record (see shaders/lib/sprite.glsl): a
// shared 16-bit index pattern for kQuadsPerBatch glyphs, replayed with a base
// vertex per batch, so index memory stays fixed whatever the glyph count.
#include "gl/loader.h"

namespace tg::render {

class QuadSprites {
 public:
  static constexpr GLsizei kQuadsPerBatch = 16384;  // 4 vertices each: the largest 16-bit batch

  explicit QuadSprites(const gl::Api& gl);
  ~QuadSprites();
  QuadSprites(const QuadSprites&) = delete;
  QuadSprites& operator=(const QuadSprites&) = delete;

  // Draws the quads of glyphs [first, first + count) with the bound program.
  void draw(GLint first, GLsizei count) const;

 private:
  const gl::Api& gl_;
  GLuint vao_ = 0, indices_ = 0;
};

}  // namespace tg::render
