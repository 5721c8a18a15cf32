// Tier 3: QuadSprites' submissions (render/quad_sprites.h). On llvmpipe a
// draw goes in pieces of a few thousand glyphs, at most two queued, to bound
// the driver's binning memory; every glyph must still be drawn exactly once.
// Each glyph here covers one pixel centre of its own (a 1 px point, or a quad
// of half a pixel around the centre, whose two triangles share the centre on
// their diagonal), and its fragment counts itself in a storage buffer.
#include "render_fixture.h"

#include <vector>

#include "gl/program.h"
#include "render/quad_sprites.h"

using namespace tg;

namespace {

constexpr const char* kVert = R"(#version 450
uniform int uQuads;
uniform int uWidth;
flat out int vGlyph;
void main() {
  int glyph = uQuads != 0 ? gl_VertexID / 4 : gl_VertexID;
  int corner = gl_VertexID % 4;
  vec2 px = vec2(glyph % uWidth, glyph / uWidth) + 0.5;
  if (uQuads != 0) px += 0.25 * vec2((corner & 1) != 0 ? 1.0 : -1.0, (corner & 2) != 0 ? 1.0 : -1.0);
  gl_Position = vec4(px / float(uWidth) * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
  vGlyph = glyph;
}
)";

constexpr const char* kFrag = R"(#version 450
layout(std430, binding = 0) buffer Hits { uint hits[]; };
flat in int vGlyph;
out vec4 color;
void main() {
  atomicAdd(hits[vGlyph], 1u);
  color = vec4(1.0);
}
)";

constexpr int kSide = 64;  // glyphs on a kSide x kSide image, one pixel each

class DrawSubmissions : public test::GlFixture {
 protected:
  // Fragments per glyph after drawing `runs` in submissions of `perSubmit`,
  // directly or (`indirect`) by one command per run.
  std::vector<GLuint> hits(const std::vector<render::GlyphRun>& runs, bool quads, std::uint32_t perSubmit,
                           bool indirect) {
    ctx_->makeCurrent();
    const gl::Api& gl = ctx_->api();
    const gl::ShaderLibrary lib({{"count.vert", kVert}, {"count.frag", kFrag}});
    const gl::Program prog(gl, lib, {{GL_VERTEX_SHADER, "count.vert"}, {GL_FRAGMENT_SHADER, "count.frag"}});
    prog.set("uQuads", quads ? 1 : 0);
    prog.set("uWidth", kSide);
    GLuint tex = 0, fbo = 0, buffer = 0;
    gl.CreateTextures(GL_TEXTURE_2D, 1, &tex);
    gl.TextureStorage2D(tex, 1, GL_RGBA8, kSide, kSide);
    gl.CreateFramebuffers(1, &fbo);
    gl.NamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, tex, 0);
    std::vector<GLuint> counts(std::size_t(kSide) * kSide, 0);
    gl.CreateBuffers(1, &buffer);
    gl.NamedBufferStorage(buffer, GLsizeiptr(counts.size() * sizeof(GLuint)), counts.data(), 0);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.Viewport(0, 0, kSide, kSide);
    gl.Disable(GL_DEPTH_TEST);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer);
    gl.UseProgram(prog.id());
    // Points: DrawArraysIndirectCommand (count, instances, first, base
    // instance); quads: DrawElementsIndirectCommand (count, instances, first
    // index, base vertex, base instance).
    std::vector<GLuint> commands;
    std::vector<render::GlyphRange> ranges;
    for (const render::GlyphRun& r : runs) {
      const GLuint c[5] = {quads ? 6 * r.count : r.count, 1, quads ? 0 : r.first, quads ? 4 * r.first : 0, 0};
      commands.insert(commands.end(), c, c + 5);
      render::GlyphRange range{};
      range.first = r.first;
      range.count = r.count;
      ranges.push_back(range);
    }
    GLuint commandBuffer = 0;
    gl.CreateBuffers(1, &commandBuffer);
    gl.NamedBufferStorage(commandBuffer, GLsizeiptr(commands.size() * sizeof(GLuint)), commands.data(), 0);
    {
      const render::QuadSprites sprites(gl, perSubmit);
      if (indirect)
        sprites.drawIndirect(commandBuffer, 0, ranges, !quads);
      else
        sprites.draw(runs, !quads);
    }
    gl.DeleteBuffers(1, &commandBuffer);
    gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gl.GetNamedBufferSubData(buffer, 0, GLsizeiptr(counts.size() * sizeof(GLuint)), counts.data());
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl.DeleteBuffers(1, &buffer);
    gl.DeleteFramebuffers(1, &fbo);
    gl.DeleteTextures(1, &tex);
    gl::checkError(gl, "DrawSubmissions");
    return counts;
  }
};

// Runs that straddle every submission boundary, one longer than a submission
// and one single glyph, and gaps between them.
const std::vector<render::GlyphRun> kRuns = {{0, 5}, {7, 10}, {20, 13}, {40, 1}, {41, 600}, {1000, 2000}};

TEST_F(DrawSubmissions, EveryGlyphOnceWhateverTheSubmissionSize) {
  std::vector<GLuint> want(std::size_t(kSide) * kSide, 0);
  for (const render::GlyphRun& r : kRuns)
    for (std::uint32_t k = 0; k < r.count; ++k) want[r.first + k] = 1;
  for (const bool indirect : {false, true})
    for (const bool quads : {false, true})
      for (const std::uint32_t perSubmit : {1u, 4u, 7u, 600u, render::QuadSprites::kWholeDraw}) {
        const std::vector<GLuint> got = hits(kRuns, quads, perSubmit, indirect);
        std::size_t wrong = 0;
        for (std::size_t i = 0; i < got.size(); ++i) wrong += got[i] != want[i];
        EXPECT_EQ(wrong, 0u) << (indirect ? "indirect " : "") << (quads ? "quads" : "points") << ", " << perSubmit
                             << " glyphs per submission";
      }
}

}  // namespace
