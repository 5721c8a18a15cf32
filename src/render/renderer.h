#pragma once
// The glyph renderer: the frame's orchestration. One upload, then per frame
// the declared passes (render/frame_pass.h) in order: the key light's shadow
// map, the glyph path's geometry into the G-buffer (render/glyph_path.h) and
// the context items, ambient occlusion, lighting, the see-through context,
// outlines and the legend.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gl/program.h"
#include "view/camera.h"
#include "render/color_readback.h"
#include "render/context_item.h"
#include "view/frame_image.h"
#include "render/frame_params.h"
#include "render/frame_pass.h"
#include "render/gbuffer.h"
#include "render/glyph_path.h"
#include "render/legend_layout.h"
#include "render/lighting_pass.h"
#include "tensor/glyph.h"

namespace tg::render {

// The overlays that draw text, built by their factories (render/legend/legend_pass.h,
// render/legend/orientation_pass.h), so that the renderer links no font library and
// the EGL-only GPU benchmark needs nothing but libEGL and the C library;
// without one, a frame that asks for it throws.
struct OverlayFactories {
  OverlayFactories(PassFactory legendPass = nullptr, PassFactory orientationPass = nullptr)  // NOLINT: implicit
      : legend(legendPass), orientation(orientationPass) {}
  PassFactory legend;       // FrameParams::legend
  PassFactory orientation;  // FrameParams::orientationLetters
};

// Told after each pass of a frame ("shadow", "glyphs", "ao", "lighting",
// "outline", "orientation", "legend": those the frame runs) that the GPU
// has finished it: the pass, passes done and passes in the frame. The wait
// (a glFinish per pass) is made only when someone listens.
using PassProgress = std::function<void(std::string_view pass, int done, int total)>;

class GlyphRenderer {
 public:
  // `overlays` builds the text passes. `glyphPath` names how glyphs reach
  // the G-buffer (makeGlyphPath).
  GlyphRenderer(const gl::Api& gl, const gl::ShaderLibrary& lib, OverlayFactories overlays = {},
                std::string_view glyphPath = "raster");
  // With a glyph path of the caller's (the tests' CPU-made G-buffer).
  GlyphRenderer(const gl::Api& gl, const gl::ShaderLibrary& lib, OverlayFactories overlays,
                std::unique_ptr<GlyphPath> path);
  ~GlyphRenderer();
  GlyphRenderer(const GlyphRenderer&) = delete;
  GlyphRenderer& operator=(const GlyphRenderer&) = delete;

  // Uploads the records once; later frames change uniforms only.
  void upload(const tensor::GlyphSet& set);
  // How many times upload() has run: parameter changes must leave it alone
  // (the viewer's and the Python module's tests count).
  std::uint64_t uploadCount() const { return uploads_; }
  // ColorMode::Array's values, one per record of the uploaded set in its
  // order (tensor::GlyphSet::glyphs; colorScalarsByRecord reorders values
  // given per input index), named `name` in the legend. Its own buffer: the
  // records are not uploaded again. Throws std::invalid_argument for
  // another count. NaN values draw mid grey; the window is of the finite ones.
  void setColorScalars(std::span<const float> byRecord, std::string name);
  bool hasColorScalars() const { return hasScalars_; }
  // A host's own map for ColorMode::Array (FrameParams::colorTable; the
  // ParaView plugin's lookup table): n colours for n equal parts of the
  // window (nearest, as a discretised table maps), then the colours of NaN,
  // of values below and of values above the window. Its own small buffer:
  // a new table or window uploads no records and no scalars. Throws
  // std::invalid_argument for fewer than 4 entries.
  void setColorTable(std::span<const glm::vec4> table);
  // The automatic colour windows: by default each scalar's range over the
  // uploaded glyphs (render/color_scalar.h); a caller that knows the whole
  // field's (before a slice or threshold selected these glyphs, or over
  // every MPI rank) sets those instead. An array's range is kept where
  // `ranges` has none.
  void setColorRanges(const ColorRanges& ranges);
  const ColorRanges& colorRanges() const { return ranges_.color; }
  // The window frames with `p` map their scalar over (resolveColorWindow).
  glm::dvec2 colorWindow(const FrameParams& p) const;
  // What the legend shows for `p`: the quantity, its map, window and units.
  LegendInputs legendInputs(const FrameParams& p) const;
  // Sets the programs' parameter uniforms: all a change of gamma, threshold,
  // scale, colour, slab or lighting costs on the CPU. render() calls it when
  // `p` differs from the last parameters.
  void setParams(const FrameParams& p);
  // Not const: culling caches its compaction between frames.
  void render(const Camera& cam, const FrameParams& p, const GBuffer& target, const PassProgress& progress = {});
  FrameImage readback(const Camera& cam, const GBuffer& target, Channels channels = Channels::All) const;
  // Of the last frame rendered with iterationStats on.
  IterationStats iterationStats() const { return path_->iterationStats(); }
  // Glyphs the last frame submitted, waiting for the GPU or not.
  std::uint64_t drawnGlyphs() const { return path_->drawnGlyphs(); }
  void requestDrawnCount() { path_->requestDrawnCount(); }
  std::optional<std::uint64_t> latestDrawnCount() { return path_->latestDrawnCount(); }
  const GlyphPath& glyphPath() const { return *path_; }
  // A declared pass ("shadow", "ao", "outline", "orientation", "legend") while built, else
  // null: a pass exists only while frames enable it. Throws for another name.
  const FramePass* pass(std::string_view name) const;
  // Frames that ran pass `name` since construction.
  std::uint64_t passRuns(std::string_view name) const;
  const FramePass* legendPass() const { return slots_[kLegend].pass.get(); }
  int shadowMapSize() const;  // texels a side of the last map, 0 while shadows are off
  // GPU memory held: the glyph path's records and buffers, the passes' own
  // textures while built, and the context items.
  std::size_t gpuBytes() const;
  // Scene context (render/context_item.h): drawn into the same G-buffer and
  // shadow map as the glyphs, in every frame, in the order added; an item's
  // id is kContextIdBase + its slot. With none added a frame runs no context
  // code. Throws past kMaxContextItems.
  ContextItem& addContext(std::unique_ptr<ContextItem> item);
  std::span<const std::unique_ptr<ContextItem>> context() const { return context_; }
  // The legend keys of the visible items, each once (the planes of one
  // underlay share theirs): what the legend shows beside the glyphs' key.
  std::vector<UnderlayKey> legendKeys() const;
  // The item an id-channel value names, or null for a glyph or nothing.
  ContextItem* contextItem(std::uint32_t id) const;
  // The occlusion radius a frame with `p` uses: p.ao.radius, or when 0,
  // AoParams::kAutoRadius times the typical glyph diameter at p.scale (that
  // of the glyph the default scale sizes, tensor::defaultScale).
  double aoRadiusWC(const FrameParams& p) const;

 private:
  // A declared pass and, while frames enable it, the pass itself.
  struct Slot {
    PassDecl decl;
    std::unique_ptr<FramePass> pass;
    std::uint64_t runs = 0;
  };
  enum SlotIndex { kShadow, kAo, kAntialias, kOutline, kOrientation, kLegend, kSlots };
  // Builds slot s's pass if this frame enables it (else releases it) and
  // runs it; whether it ran.
  bool runSlot(Slot& s, const PassFrame& f);
  const Slot& slotNamed(std::string_view name) const;
  const gl::Api& gl_;
  const gl::ShaderLibrary& lib_;
  std::unique_ptr<GlyphPath> path_;
  LightingPass lighting_;
  std::array<Slot, kSlots> slots_;
  std::size_t glyphCount_ = 0;
  std::uint64_t uploads_ = 0;
  UploadedRanges ranges_;  // less the underlays, which each frame reads from the context
  bool hasScalars_ = false;
  GLuint colorTable_ = 0;  // setColorTable's buffer, or none
  double typicalDiameter_ = 1.0;  // in eigenvalue units
  std::optional<FrameParams> params_;  // as last set
  std::vector<std::unique_ptr<ContextItem>> context_;
};

}  // namespace tg::render
