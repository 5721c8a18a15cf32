#pragma once
// Draws one screen quad per glyph record (see shaders/lib/sprite.glsl): a
// shared 16-bit index pattern for kQuadsPerBatch glyphs, replayed with a base
// vertex per batch, so index memory stays fixed whatever the glyph count; or
// one point sprite per glyph (`points`, render/sprite_primitive.h), which
// needs no indices.
#include <cstdint>
#include <span>
#include <string_view>

#include "gl/loader.h"
#include "render/glyph_ranges.h"

namespace tg::render {

class QuadSprites {
 public:
  static constexpr GLsizei kQuadsPerBatch = 16384;  // 4 vertices each: the largest 16-bit batch
  static constexpr GLsizeiptr kIndirectCommandBytes = 5 * sizeof(GLuint);  // DrawElementsIndirectCommand

  // No limit: one draw call per draw().
  static constexpr std::uint32_t kWholeDraw = UINT32_MAX;

  // Glyphs per submission for a GL_RENDERER string. llvmpipe bins a whole
  // draw call (every glyph's interpolants: about 440 bytes a superquadric
  // point sprite, 25 MB for the dt-helix) before it rasterises any of it, so
  // there draws go in submissions of 4096 glyphs, at most two queued, and its
  // binning memory stays a few MB whatever the count. kWholeDraw elsewhere.
  static std::uint32_t glyphsPerSubmit(std::string_view glRenderer);

  // Submissions as glyphsPerSubmit gives for the context's renderer.
  explicit QuadSprites(const gl::Api& gl);
  QuadSprites(const gl::Api& gl, std::uint32_t glyphsPerSubmit);
  ~QuadSprites();
  QuadSprites(const QuadSprites&) = delete;
  QuadSprites& operator=(const QuadSprites&) = delete;

  // Draws the sprites of these glyph runs with the bound program: in one call,
  // or in submissions of glyphsPerSubmit glyphs.
  void draw(std::span<const GlyphRun> runs, bool points) const;
  // Draws commands [first, first + ranges.size()) of an indirect buffer of
  // kIndirectCommandBytes each: DrawElementsIndirectCommand naming its glyphs
  // by base vertex, or for points DrawArraysIndirectCommand by first vertex.
  // Command k draws at most ranges[k].count glyphs, which sizes the submissions.
  void drawIndirect(GLuint commands, GLsizei first, std::span<const GlyphRange> ranges, bool points) const;

 private:
  const gl::Api& gl_;
  std::uint32_t glyphsPerSubmit_;
  GLuint vao_ = 0, indices_ = 0;
};

}  // namespace tg::render
