#pragma once
// The glyph renderer: one upload, then a geometry pass into the G-buffer and a
// deferred lighting pass per frame.
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl/program.h"
#include "render/ao_pass.h"
#include "render/camera.h"
#include "render/context_item.h"
#include "render/frame_params.h"
#include "render/frame_image.h"
#include "render/gbuffer.h"
#include "render/legend_params.h"
#include "render/occluder_pyramid.h"
#include "render/glyph_culling.h"
#include "render/outline_pass.h"
#include "render/kind_programs.h"
#include "render/quad_sprites.h"
#include "render/renderer_profile.h"
#include "render/shadow_pass.h"
#include "render/tessellated.h"
#include "tensor/glyph.h"
#include "tensor/glyph_scale.h"

namespace tg::render {

// What readback fetches: the float colour, every channel (EXR), or only the
// colour as 8-bit RGBA (PNG and the like; render/color_readback.h), which
// never holds the float image on the CPU.
enum class Channels { Color, All, Rgba8 };

struct IterationStats {
  double mean = 0;
  unsigned max = 0;
  std::uint64_t pixels = 0;  // superquadric fragments that ran the march
  // Passes of the march's loop (one gauge call each) over every fragment,
  // Newton or not: what the grid search and early rejections change.
  std::uint64_t gaugeCalls = 0;
};

// What an overlay shows of the uploaded glyphs: the ranges they are coloured by.
struct UploadedRanges {
  float mdMin = 0, mdMax = 0;         // the uMdRange uniform
  double eigenMin = 0, eigenMax = 0;  // signed, over the glyphs
  std::vector<UnderlayKey> underlays{};  // of the visible context items, each once
};

// A pass drawn over the lit image, last before readback: the legend
// (render/legend_pass.h). The application hands the renderer a factory for
// it, so that the renderer links no font library and the EGL-only GPU
// benchmark needs nothing but libEGL and the C library.
class OverlayPass {
 public:
  virtual ~OverlayPass() = default;
  // Draws into the framebuffer bound for lighting (GBuffer::beginLighting).
  virtual void draw(const Camera& cam, const FrameParams& p, const UploadedRanges& ranges) = 0;
  virtual std::size_t gpuBytes() const = 0;
};
using OverlayFactory = std::unique_ptr<OverlayPass> (*)(const gl::Api&, const gl::ShaderLibrary&);

class GlyphRenderer {
 public:
  // `legend` builds the pass for FrameParams::legend; without it, a frame
  // that asks for a legend throws.
  GlyphRenderer(const gl::Api& gl, const gl::ShaderLibrary& lib, OverlayFactory legend = nullptr);
  ~GlyphRenderer();
  GlyphRenderer(const GlyphRenderer&) = delete;
  GlyphRenderer& operator=(const GlyphRenderer&) = delete;

  // Uploads the records once; later frames change uniforms only.
  void upload(const tensor::GlyphSet& set);
  // How many times upload() has run: parameter changes must leave it alone
  // (the viewer's and the Python module's tests count).
  std::uint64_t uploadCount() const { return uploads_; }
  // Sets the programs' parameter uniforms: all a change of gamma, threshold,
  // scale, colour, slab or lighting costs on the CPU. render() calls it when
  // `p` differs from the last parameters.
  void setParams(const FrameParams& p);
  // Not const: culling caches its compaction between frames.
  void render(const Camera& cam, const FrameParams& p, const GBuffer& target);
  FrameImage readback(const Camera& cam, const GBuffer& target, Channels channels = Channels::All) const;
  // Of the last frame rendered with iterationStats on.
  IterationStats iterationStats() const;
  // Glyphs the last frame sent to the vertex stage (GlyphCulling::drawnGlyphs).
  std::uint64_t drawnGlyphs() const { return culling_.drawnGlyphs(); }
  // The same without waiting for the GPU (GlyphCulling::requestDrawnCount).
  void requestDrawnCount() { culling_.requestDrawnCount(); }
  std::optional<std::uint64_t> latestDrawnCount() { return culling_.latestDrawnCount(); }
  const GlyphCulling& culling() const { return culling_; }
  // Frames that ran the superquadric occlusion pre-pass since construction.
  std::uint64_t occlusionPrepasses() const { return occlusionPrepasses_; }
  // Whether kind k's program exists (cylinder and box: built on first use).
  bool kindBuilt(GlyphKind k) const { return kinds_.built(k); }
  // Frames that drew the shadow map since construction, and whether the
  // shadow pass (its program and map) exists now: only while frames ask for it.
  std::uint64_t shadowMapPasses() const { return shadowMapPasses_; }
  // Whether a frame has needed the Newton march (its program is built then).
  bool marchProgramBuilt() const {
    return std::any_of(march_.begin(), march_.end(), [](const auto& m) { return m != nullptr; });
  }
  // Draws by march variant v since construction.
  std::uint64_t marchDraws(MarchVariant v) const { return marchDraws_[std::size_t(v)]; }
  bool tessellatedProgramBuilt() const { return tessellated_.program() != nullptr; }
  bool shadowPassBuilt() const { return shadow_ != nullptr; }
  int shadowMapSize() const { return shadow_ ? shadow_->mapSize() : 0; }  // texels a side, of the last map
  // GPU memory held for the uploaded glyphs: records, culling's ranges and
  // commands, the compacted indices once a threshold needed them, and the
  // tessellated mesh once drawn, the shadow map while shadows are on, and
  // the context items.
  std::size_t gpuBytes() const;
  std::size_t contextBytes() const;  // of the context items alone
  // The legend pass, while the last frame had one (null: nothing built or held).
  const OverlayPass* legendPass() const { return legend_.get(); }
  // Scene context (render/context_item.h): drawn into the same G-buffer and
  // shadow map as the glyphs, in every frame, in the order added; an item's
  // id is kContextIdBase + its slot. With none added a frame runs no context
  // code. Throws past kMaxContextItems.
  ContextItem& addContext(std::unique_ptr<ContextItem> item);
  void clearContext() { context_.clear(); }
  std::span<const std::unique_ptr<ContextItem>> context() const { return context_; }
  // The legend keys of the visible items, each once (the planes of one
  // underlay share theirs): what the legend shows beside the glyphs' key.
  std::vector<UnderlayKey> legendKeys() const;
  // The item an id-channel value names, or null for a glyph or nothing.
  ContextItem* contextItem(std::uint32_t id) const;
  // The deferred effects' passes, created on the first frame that enables
  // them (null before).
  const AoPass* aoPass() const { return ao_.get(); }
  const OutlinePass* outlinePass() const { return outline_.get(); }
  // The occlusion radius a frame with `p` uses: p.ao.radius, or when 0,
  // AoParams::kAutoRadius times the typical glyph diameter at p.scale (that
  // of the glyph the default scale sizes, tensor::defaultScale).
  double aoRadiusWC(const FrameParams& p) const;

 private:
  void setCamera(const gl::Program& prog, const Camera& cam) const;
  // Depth test and the records bound: what every glyph pass needs.
  void beginGlyphs() const;
  // Whether this frame draws point sprites (render/sprite_primitive.h).
  bool pointSprites(const Camera& cam, const FrameParams& p) const;
  // The width in pixels of this frame's typical glyph (typicalSpritePx).
  double typicalPx(const Camera& cam, const FrameParams& p) const;
  void useGlyphProgram(const gl::Program& prog, const Camera& cam) const;
  // Every glyph `cam` sees, into the bound framebuffer; groups from `split`
  // on by the marching program (superquadrics), the counting one when `stats`.
  void drawGlyphs(const Camera& cam, const FrameParams& p, int split, bool stats, bool occluders);
  // The marching program (with Newton counting when `stats`), built on first use.
  const gl::Program& marchProgram(bool stats, MarchVariant v, const FrameParams& p);
  const gl::Program& tessellatedProgram(const FrameParams& p);
  void setShapeUniforms(const gl::Program& prog, const FrameParams& p, const FrameParams* old) const;
  // Programs that draw glyphs, and those of them that take the superquadric
  // shape uniforms; null where a marching program is not built yet.
  std::array<const gl::Program*, 9> glyphPrograms() const;
  std::array<const gl::Program*, 7> shapePrograms() const;
  const gl::Program& occluderProgram(const FrameParams& p);
  // Sets the lighting uniforms of `p` on a lighting program.
  void setLighting(const gl::Program& prog, const FrameParams& p) const;
  // lighting_, or the variant the frame's effects need (`shadows`: the key
  // light's map was drawn), compiled on first use; only the last is kept.
  const gl::Program& lightingFor(const FrameParams& p, bool shadows);
  // The visible context items' opaque surfaces into the bound target.
  void drawContext(const Camera& cam, const FrameParams& p, ContextTarget target) const;
  // Draws the glyphs' depth from the key light into the shadow map; returns the light's camera.
  Camera renderShadowMap(const Camera& cam, const FrameParams& p, int split);
  const gl::Api& gl_;
  const gl::ShaderLibrary& lib_;
  gl::Program ellipsoid_;
  // [2 * MarchVariant + stats], each built on first use (marchProgram).
  std::array<std::unique_ptr<gl::Program>, 6> march_;
  // The pre-pass's occluders (ellipsoid.vert TG_OCCLUDER_DISC, occluder_disc.frag), built on first use.
  std::unique_ptr<gl::Program> occluders_;
  std::array<std::uint64_t, 3> marchDraws_{};
  std::array<std::size_t, 3> groupCounts_{};  // uploaded glyphs by tensor::GlyphGroup
  // Spheres or definite glyphs uploaded: what the occlusion pre-pass draws.
  bool hasOccluders() const { return groupCounts_[0] + groupCounts_[1] > 0; }
  gl::Program lighting_;
  RendererProfile profile_;  // this context's measured choices
  QuadSprites sprites_;
  GlyphCulling culling_;
  OccluderPyramid pyramid_;
  TessellatedGlyphs tessellated_;
  KindPrograms kinds_;  // closed-form kinds' programs
  std::unique_ptr<ShadowPass> shadow_;  // built on first use
  GLuint vao_ = 0, buffer_ = 0, stats_ = 0;
  GLsizei count_ = 0;
  std::uint64_t uploads_ = 0;
  double maxPointPx_ = 0;      // GL_POINT_SIZE_RANGE's upper end
  std::uint64_t occlusionPrepasses_ = 0, shadowMapPasses_ = 0;
  glm::dvec3 centresLoWC_{0.0}, centresHiWC_{0.0};  // of the uploaded glyphs
  double maxAbsEigenvalue_ = 0;
  float mdMin_ = 0, mdMax_ = 0;
  double eigenMin_ = 0, eigenMax_ = 0;
  double typicalDiameter_ = 1.0;  // in eigenvalue units
  std::unique_ptr<AoPass> ao_;
  std::unique_ptr<OutlinePass> outline_;
  std::unique_ptr<gl::Program> lightingVariant_;  // lighting.frag with TG_AO and/or TG_SHADOWS
  int lightingVariantKey_ = 0;                    // 1: TG_AO, 2: TG_SHADOWS, 3: both
  std::optional<FrameParams> params_;  // as last set
  std::vector<std::unique_ptr<ContextItem>> context_;
  OverlayFactory makeLegend_;
  std::unique_ptr<OverlayPass> legend_;
};

}  // namespace tg::render
