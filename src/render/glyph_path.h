#pragma once
// How glyphs reach the G-buffer: the seam between the frame's orchestration
// (render/renderer.h) and a way of drawing glyphs. A path writes the view's
// albedo, normalWC, id and depth attachments (render/gbuffer.h), and the key
// light's shadow map; every deferred pass then reads only the G-buffer, so
// that a path which fills it by a compute shader or from the CPU is shaded as
// the raster path is. The depth the deferred passes read is a depth
// attachment; a path that cannot raster it writes a float depth channel and
// resolves it (render/depth_resolve.h). Paths are selected by name
// (makeGlyphPath): "raster" (render/raster_glyphs.h), "cpu"
// (render/cpu_glyphs.h) and "compute" (render/compute_glyphs.h).
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "gl/program.h"
#include "view/camera.h"
#include "render/frame_params.h"
#include "render/gbuffer.h"
#include "tensor/glyph.h"

namespace tg::render {

class ShadowPass;

struct IterationStats {
  double mean = 0;
  unsigned max = 0;
  std::uint64_t pixels = 0;  // superquadric fragments that ran the march
  // Passes of the march's loop (one gauge call each) over every fragment,
  // Newton or not: what the grid search and early rejections change.
  std::uint64_t gaugeCalls = 0;
};

class GlyphPath {
 public:
  virtual ~GlyphPath() = default;
  virtual std::string_view name() const = 0;
  // How it draws on this GL, where that depends on the GL (for --verbose).
  virtual std::string how() const { return ""; }
  // Takes the records once; later frames change parameters only.
  virtual void upload(const tensor::GlyphSet& set) = 0;
  // The parameters of the next frames; `old`: those last set, or null.
  virtual void setParams(const FrameParams& p, const FrameParams* old) = 0;
  // The colour window of the next frames (GlyphRenderer::colorWindow): the
  // values at the colormap's ends; for the sign colour (-M, M).
  virtual void setColorWindow(glm::dvec2 window) { static_cast<void>(window); }
  // ColorMode::Array's values, one per record in the records' order, into
  // a buffer of their own: the records stay as uploaded.
  virtual void uploadColorScalars(std::span<const float> byRecord);
  // The view's glyphs: clears and binds the geometry framebuffer
  // (GBuffer::beginGeometry) and writes albedo, normalWC, id and depth;
  // the caller draws context into what it leaves bound.
  virtual void drawView(const Camera& cam, const FrameParams& p, const GBuffer& target) = 0;
  // The casters' box (WC) at p's scale and slab, for the key light's camera.
  virtual std::pair<glm::dvec3, glm::dvec3> castersBoxWC(const FrameParams& p) const = 0;
  // The glyphs' depth from `light` into shadow's map (ShadowPass::beginMap,
  // which it calls, glyphs or none).
  virtual void drawShadowCasters(const Camera& light, const FrameParams& p, ShadowPass& shadow) = 0;
  virtual std::size_t gpuBytes() const = 0;
  // The records' storage buffer (lib/glyph_record.glsl's), in upload order,
  // for passes that cast glyphs again (anti-aliasing's coverage); 0 where
  // the path keeps none on the GPU.
  virtual GLuint recordBuffer() const { return 0; }
  // Of the last frame with iterationStats on (zeros for a path with no march).
  virtual IterationStats iterationStats() const { return {}; }
  // Glyphs the last frame submitted, waiting for the GPU or not.
  virtual std::uint64_t drawnGlyphs() const = 0;
  virtual void requestDrawnCount() {}
  virtual std::optional<std::uint64_t> latestDrawnCount() { return std::nullopt; }
};

// The paths' names, GL-free, for the options that choose one.
inline constexpr std::string_view kGlyphPathNames[] = {"raster", "cpu", "compute"};

inline void GlyphPath::uploadColorScalars(std::span<const float>) {
  throw std::invalid_argument("GlyphRenderer::setColorScalars: the " + std::string(name()) +
                              " glyph path draws no per-glyph scalars");
}

// The path called `name`; throws std::invalid_argument naming the choices.
std::unique_ptr<GlyphPath> makeGlyphPath(std::string_view name, const gl::Api& gl, const gl::ShaderLibrary& lib);
// "raster, cpu, compute": the names makeGlyphPath takes, for messages.
std::string glyphPathNames();

}  // namespace tg::render
