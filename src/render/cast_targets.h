#pragma once
// The casts' textures of the paths that cast rays outside GL's rasteriser
// (render/cpu_glyphs.h uploads them, render/compute_glyphs.h writes them by
// compute), and the two full-screen passes that write them into GL's
// targets: cpu_gbuffer.frag into the G-buffer, taking albedo and id from the
// record with the raster path's colour code, and cpu_depth.frag into the key
// light's shadow map. One home, so that both paths shade alike.
#include <cstddef>
#include <memory>
#include <span>

#include "gl/program.h"
#include "render/frame_params.h"
#include "view/camera.h"

namespace tg::render {

class ShadowPass;
struct PixelRect;  // render/tile_binning.h

// Records [first, first + count) in their own buffers (records, and colour
// scalars or 0): a path whose records pass one storage block
// (GL_MAX_SHADER_STORAGE_BLOCK_SIZE) holds them in several.
struct RecordChunk {
  GLuint records = 0, scalars = 0;
  std::size_t first = 0, count = 0;
};

// Each target is a buffer texture, one texel per pixel, rows bottom first
// (texel y * width + x): the CPU path writes them in place through a
// persistent mapping, with no copy into a texture (at 1920x1080 that copy
// held 41 MB more and took a frame 10 ms on llvmpipe); the compute path
// stores them as image buffers.
class CastTargets {
 public:
  // The view's targets: window depth (R32F, reversed, 0 where empty),
  // record + 1 (R32UI, 0: empty), WC normal (float, in `normalFormat`) and
  // GC hit (RGBA32F, one texel unless a frame of the sign colour asks for
  // it: 33 MB at 1920x1080). The normal stays float so that
  // cpu_gbuffer.frag's output rounds it to the G-buffer's half floats as the
  // raster path's fragments do.
  enum View { kDepth = 0, kRecord = 1, kNormal = 2, kHitGC = 3 };

  // normalFormat: GL_RGB32F where the CPU writes the normal (12 bytes a
  // pixel), GL_RGBA32F where a compute shader stores it (an image format).
  // mapped: the CPU writes the targets (view and viewMapped).
  CastTargets(const gl::Api& gl, const gl::ShaderLibrary& lib, GLenum normalFormat, bool mapped);
  ~CastTargets();
  CastTargets(const CastTargets&) = delete;
  CastTargets& operator=(const CastTargets&) = delete;

  // cpu_gbuffer.frag's glyph and colour inputs as the raster path takes
  // them (RasterGlyphs), for the same colour code.
  void setGlyphParams(const FrameParams& p, const FrameParams* old) const;
  void setColorWindow(glm::dvec2 window) const;
  // The view's targets for width x height, the GC hit's only when `hitGC`
  // (each reallocated when its size changes). Throws std::runtime_error
  // past GL_MAX_TEXTURE_BUFFER_SIZE texels.
  void allocateView(int width, int height, bool hitGC);
  GLuint view(View k) const { return view_[k].texture; }
  // Where the CPU writes target k (mapped targets only): width x height texels.
  void* viewMapped(View k) const { return view_[k].mapped; }
  // The light's depth and record targets, size x size.
  void allocateLight(int size);
  GLuint lightDepth() const { return light_[0].texture; }
  GLuint lightRecord() const { return light_[1].texture; }
  void* lightMapped(int k) const { return light_[k].mapped; }
  // Waits until GL has read what the last writeView or writeLight drew
  // from, so that the CPU may write the mapped targets again.
  void waitForReads();

  // The view textures into the bound geometry framebuffer (what
  // GBuffer::beginGeometry left bound), over the records' chunks, one draw
  // each; leaves the depth test at GL_GREATER, as the raster path. Mapped
  // targets write only the pixels of `runs` (tileRuns: where glyphs reach),
  // the others the whole viewport (`runs` empty).
  void writeView(const Camera& cam, std::span<const RecordChunk> chunks, std::span<const PixelRect> runs = {});
  // The light textures into shadow's map (ShadowPass::beginMap, which it
  // calls), over `runs` as writeView.
  void writeLight(int size, ShadowPass& shadow, std::span<const PixelRect> runs = {});
  std::size_t bytes() const;

 private:
  // A buffer and the buffer texture over it.
  struct Target {
    GLuint buffer = 0, texture = 0;
    void* mapped = nullptr;
    std::size_t texels = 0;
  };
  // prog over `runs` (mapped targets) or the whole viewport.
  void draw(const gl::Program& prog, int width, int height, std::span<const PixelRect> runs);
  void resize(Target& t, GLenum format, std::size_t texelBytes, std::size_t texels);
  void release(Target& t);
  void fence();

  const gl::Api& gl_;
  const gl::ShaderLibrary& lib_;
  GLenum normalFormat_;
  bool mapped_;
  gl::Program gbuffer_;
  std::unique_ptr<gl::Program> depth_;  // cpu_depth.frag, built by the first shadow map
  GLuint vao_ = 0;
  Target view_[4];
  int width_ = 0, height_ = 0;
  Target light_[2];
  Target runs_;  // mapped targets: the runs of the last draw, as cast_runs.vert reads them
  int lightSize_ = 0;
  GLsync reads_ = nullptr;  // after the last draw that read the targets
};

}  // namespace tg::render
