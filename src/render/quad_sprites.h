#pragma once
// Draws one screen quad per glyph record (see shaders/lib/sprite.glsl): a
// shared 16-bit index pattern for kQuadsPerBatch glyphs, replayed with a base
// vertex per batch, so index memory stays fixed whatever the glyph count; or
// one point sprite per glyph (`points`, render/sprite_primitive.h), which
// needs no indices.
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

  // Draws the sprites of these glyph runs with the bound program, in one call.
  void draw(std::span<const GlyphRun> runs, bool points) const;
  // Draws commands [first, first + count) of an indirect buffer of
  // kIndirectCommandBytes each: DrawElementsIndirectCommand naming its glyphs
  // by base vertex, or for points DrawArraysIndirectCommand by first vertex.
  void drawIndirect(GLuint commands, GLsizei first, GLsizei count, bool points) const;

 private:
  const gl::Api& gl_;
  GLuint vao_ = 0, indices_ = 0;
};

}  // namespace tg::render
