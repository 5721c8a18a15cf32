#include "render/quad_sprites.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace tg::render {
namespace {

// Splits `runs` into pieces of at most `maxPiece` glyphs, in order, and
// hands them to submit() in groups of at most `perSubmit` glyphs.
template <class Submit>
void forEachSubmission(std::span<const GlyphRun> runs, std::uint32_t perSubmit, std::uint32_t maxPiece,
                       const Submit& submit) {
  std::vector<GlyphRun> pieces;
  std::uint32_t pending = 0;
  for (const GlyphRun& r : runs)
    for (std::uint32_t done = 0; done < r.count;) {
      const std::uint32_t n = std::min({r.count - done, maxPiece, perSubmit - pending});
      pieces.push_back({r.first + done, n});
      done += n;
      pending += n;
      if (pending == perSubmit) {
        submit(std::span<const GlyphRun>(pieces));
        pieces.clear();
        pending = 0;
      }
    }
  if (!pieces.empty()) submit(std::span<const GlyphRun>(pieces));
}

// Keeps at most two submissions queued: after each, waits for the one
// before. Off, it does nothing.
class Throttle {
 public:
  Throttle(const gl::Api& gl, bool on) : gl_(gl), on_(on) {}
  ~Throttle() {
    if (last_) gl_.DeleteSync(last_);
  }
  Throttle(const Throttle&) = delete;
  Throttle& operator=(const Throttle&) = delete;
  void submitted() {
    if (!on_) return;
    GLsync fence = gl_.FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    if (last_) {
      // A second's timeout only repeats the wait; GL_WAIT_FAILED ends it.
      while (gl_.ClientWaitSync(last_, GL_SYNC_FLUSH_COMMANDS_BIT, 1000000000) == GL_TIMEOUT_EXPIRED) {}
      gl_.DeleteSync(last_);
    }
    last_ = fence;
  }

 private:
  const gl::Api& gl_;
  bool on_;
  GLsync last_ = nullptr;
};

}  // namespace

QuadSprites::QuadSprites(const gl::Api& gl, std::uint32_t glyphsPerSubmit)
    : gl_(gl), glyphsPerSubmit_(std::max<std::uint32_t>(glyphsPerSubmit, 1)) {
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
  std::uint64_t glyphs = 0;
  for (const GlyphRun& r : runs) {
    // Points: gl_VertexID = glyph; quads: 4 * glyph + corner. Either must fit a GLint.
    if (std::int64_t(r.first) + r.count > std::int64_t(INT32_MAX) / (points ? 1 : 4))
      throw std::runtime_error(points ? "QuadSprites::draw: glyph range beyond 2^31"
                                      : "QuadSprites::draw: glyph range beyond 2^29");
    glyphs += r.count;
  }
  if (glyphs == 0) return;
  gl_.BindVertexArray(vao_);
  if (points) gl_.Enable(GL_PROGRAM_POINT_SIZE);
  Throttle throttle(gl_, glyphsPerSubmit_ != kWholeDraw);
  if (points) {
    std::vector<GLint> firsts;
    std::vector<GLsizei> counts;
    forEachSubmission(runs, glyphsPerSubmit_, kWholeDraw, [&](std::span<const GlyphRun> pieces) {
      firsts.clear();
      counts.clear();
      for (const GlyphRun& p : pieces) {
        firsts.push_back(GLint(p.first));
        counts.push_back(GLsizei(p.count));
      }
      gl_.MultiDrawArrays(GL_POINTS, firsts.data(), counts.data(), GLsizei(counts.size()));
      throttle.submitted();
    });
    return;
  }
  std::vector<GLsizei> counts;
  std::vector<const void*> offsets;
  std::vector<GLint> baseVertices;
  forEachSubmission(runs, glyphsPerSubmit_, std::uint32_t(kQuadsPerBatch), [&](std::span<const GlyphRun> pieces) {
    counts.clear();
    offsets.clear();
    baseVertices.clear();
    for (const GlyphRun& p : pieces) {
      counts.push_back(GLsizei(6 * p.count));
      offsets.push_back(nullptr);
      baseVertices.push_back(GLint(4 * p.first));
    }
    gl_.MultiDrawElementsBaseVertex(GL_TRIANGLES, counts.data(), GL_UNSIGNED_SHORT, offsets.data(),
                                    GLsizei(counts.size()), baseVertices.data());
    throttle.submitted();
  });
}

void QuadSprites::drawIndirect(GLuint commands, GLsizei first, std::span<const GlyphRange> ranges, bool points) const {
  if (ranges.empty()) return;
  gl_.BindVertexArray(vao_);
  gl_.BindBuffer(GL_DRAW_INDIRECT_BUFFER, commands);
  if (points) gl_.Enable(GL_PROGRAM_POINT_SIZE);
  Throttle throttle(gl_, glyphsPerSubmit_ != kWholeDraw);
  for (std::size_t k = 0; k < ranges.size();) {
    // At least one command; then as many as fit.
    std::size_t n = 1;
    std::uint64_t glyphs = ranges[k].count;
    while (k + n < ranges.size() && glyphs + ranges[k + n].count <= glyphsPerSubmit_) glyphs += ranges[k + n++].count;
    const auto* offset = reinterpret_cast<const void*>((std::size_t(first) + k) * std::size_t(kIndirectCommandBytes));
    if (points)
      gl_.MultiDrawArraysIndirect(GL_POINTS, offset, GLsizei(n), GLsizei(kIndirectCommandBytes));
    else
      gl_.MultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_SHORT, offset, GLsizei(n), 0);
    throttle.submitted();
    k += n;
  }
  gl_.BindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

}  // namespace tg::render
