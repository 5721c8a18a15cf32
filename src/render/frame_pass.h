#pragma once
// The frame as declared passes. Each pass names the G-buffer attachments it
// reads and writes (render/gbuffer.h; its own textures are its own), and the
// renderer (render/renderer.h) declares, in frame order, when each runs: a
// pass is built on the first frame that enables it and released by the first
// that does not, so a disabled pass is never built, run or allocated.
// Bindings are those of shaders/lib/bindings.h, shared with the GLSL.
#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "gl/program.h"
#include "view/camera.h"
#include "render/color_scalar.h"
#include "render/context_item.h"
#include "render/frame_params.h"
#include "render/gbuffer.h"
#include "render/legend_layout.h"
#include "render/legend_key.h"

namespace tg::render {

class GlyphPath;
class ShadowPass;

// What the overlays show of the uploaded glyphs: the ranges they are coloured by.
struct UploadedRanges {
  float mdMin = 0, mdMax = 0;         // MD's automatic window
  double eigenMin = 0, eigenMax = 0;  // signed, over the glyphs
  ColorRanges color;                  // every scalar's automatic window, the array's included
  std::string scalarName;             // ColorMode::Array's quantity (GlyphRenderer::setColorScalars)
  std::vector<UnderlayKey> underlays{};  // of the visible context items, each once
};

// What the legend shows for `p` over ranges `r` (the underlays' keys as in r):
// the quantity, its map, window and units, as the glyph shaders draw them.
LegendInputs legendInputs(const FrameParams& p, const UploadedRanges& r);

// What a pass is given: the frame's camera, parameters and target, and what
// the renderer knows of the scene.
struct PassFrame {
  const Camera& cam;
  const FrameParams& p;
  const GBuffer& target;
  double aoRadiusWC;  // GlyphRenderer::aoRadiusWC(p)
  const UploadedRanges& ranges;
  GlyphPath& glyphs;  // the shadow map draws its casters by it
  std::span<const std::unique_ptr<ContextItem>> context;
  const ShadowPass* shadow;  // the key light's map, when this frame drew one
  // Draws the frame's glyphs and context, lit, from another camera (a
  // jittered one: render/antialias_pass.h) into another target.
  std::function<void(const Camera&, const GBuffer&)> drawSample{};
  // A sample's frame: lighting lights only the frame's silhouette pixels
  // (the frame's ids bound at TG_UNIT_AA_FRAME_ID).
  bool edgesOnly = false;
  // Record uploads so far (GlyphRenderer::upload): what a pass keeps of the
  // records is stale once it changes.
  std::uint64_t uploads = 0;
};

class FramePass {
 public:
  virtual ~FramePass() = default;
  virtual std::span<const Attachment> reads() const = 0;
  virtual std::span<const Attachment> writes() const = 0;
  virtual void run(const PassFrame& f) = 0;
  virtual std::size_t gpuBytes() const = 0;
};

using PassFactory = std::unique_ptr<FramePass> (*)(const gl::Api&, const gl::ShaderLibrary&);

// A declared pass: its name, the frames it runs in and how it is built.
struct PassDecl {
  const char* name;
  bool (*enabled)(const FrameParams& p);
  PassFactory make;
};

}  // namespace tg::render
