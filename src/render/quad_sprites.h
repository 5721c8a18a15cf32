#pragma once
// Draws one screen quad per glyph record (see shaders/lib/sprite.glsl): a
// shared 16-bit index pattern for kQuadsPerBatch glyphs, replayed with a base
// vertex per batch, so index memory stays fixed whatever the glyph count; or
// one point sprite per glyph (`points`, render/sprite_primitive.h), which
// needs no indices.
#include <cstdint>
#include <span>

#include "gl/loader.h"
#include "render/glyph_ranges.h"
#include "render/renderer_profile.h"

namespace tg::render {

class QuadSprites {
 public:
  static constexpr GLsizei kQuadsPerBatch = 16384;  // 4 vertices each: the largest 16-bit batch
  static constexpr GLsizeiptr kIndirectCommandBytes = 5 * sizeof(GLuint);  // DrawElementsIndirectCommand

  // No limit: one draw call per draw().
  static constexpr std::uint32_t kWholeDraw = RendererProfile::kWholeDraw;

  // Draws in submissions of at most glyphsPerSubmit glyphs (the renderer's
  // RendererProfile), at most two queued behind a fence, or in one call.
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
