#pragma once
// Pixel comparisons of two frames of the same camera, for tests that change
// how glyphs are drawn but not what: a pixel differs where its id, depth or
// colour does.
#include <cstddef>

#include "gl/loader.h"
#include "ref/ellipsoid_ref.h"
#include "view/frame_image.h"

namespace tg::test {

inline std::size_t differingPixels(const render::FrameImage& a, const render::FrameImage& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.id.size(); ++i)
    n += a.id[i] != b.id[i] || a.depth[i] != b.depth[i] || a.rgba[4 * i] != b.rgba[4 * i] ||
         a.rgba[4 * i + 1] != b.rgba[4 * i + 1] || a.rgba[4 * i + 2] != b.rgba[4 * i + 2];
  return n;
}

inline std::size_t coveredPixels(const render::FrameImage& a) {
  std::size_t n = 0;
  for (auto id : a.id) n += id != ref::kNoGlyph;
  return n;
}

// What the pipeline statistics query `target` (GL_FRAGMENT_SHADER_INVOCATIONS,
// ...) counts while `draw` runs: how tests tell that a cull acted.
template <class Draw>
GLuint64 countedBy(const gl::Api& gl, GLenum target, Draw&& draw) {
  GLuint query = 0;
  gl.GenQueries(1, &query);  // Mesa 22 refuses statistics targets in glCreateQueries
  gl.BeginQuery(target, query);
  draw();
  gl.EndQuery(target);
  GLuint64 n = 0;
  gl.GetQueryObjectui64v(query, GL_QUERY_RESULT, &n);
  gl.DeleteQueries(1, &query);
  return n;
}

}  // namespace tg::test
