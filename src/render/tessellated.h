#pragma once
// The tessellated baseline: an instanced superquadric mesh of R x R quads per
// glyph (shaders/tessellated.vert), what VTK's vtkTensorGlyph with a
// vtkSuperquadricSource of theta and phi resolution R draws. It exists to be
// measured against the ray-cast glyphs (`bench scale`, `render --tessellate`).
#include <cstddef>
#include <memory>

#include "gl/program.h"

namespace tg::render {

class TessellatedGlyphs {
 public:
  static constexpr int kMinResolution = 4, kMaxResolution = 64;  // (R + 1)^2 vertices fit 16-bit indices

  TessellatedGlyphs(const gl::Api& gl, const gl::ShaderLibrary& lib);
  ~TessellatedGlyphs();
  TessellatedGlyphs(const TessellatedGlyphs&) = delete;
  TessellatedGlyphs& operator=(const TessellatedGlyphs&) = delete;

  // The program, compiled on the first call: only the baseline's own frames
  // (--tessellate, `bench scale`) pay for it. program() is null until then.
  const gl::Program& build();
  const gl::Program* program() const { return program_.get(); }
  // Draws `count` glyphs from the records bound at binding 0, with the
  // built program's uniforms already set (camera included).
  void draw(int resolution, std::size_t count);
  // Bytes of GPU memory the shared mesh takes (its index buffer).
  std::size_t meshBytes() const { return meshBytes_; }

  // What a mesh per glyph (VTK's output, no instancing) would take at
  // resolution R: positions and normals as float3, 32-bit triangle indices.
  static std::size_t perGlyphMeshBytes(int resolution);

 private:
  const gl::Api& gl_;
  const gl::ShaderLibrary& lib_;
  std::unique_ptr<gl::Program> program_;
  GLuint vao_ = 0, indices_ = 0;
  int resolution_ = 0;
  std::size_t meshBytes_ = 0;
};

}  // namespace tg::render
