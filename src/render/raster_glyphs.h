#pragma once
// The raster glyph path (render/glyph_path.h, "raster"): one sprite per glyph
// whose fragment program ray casts the exact surface (Sigg et al. 2006), the
// kind's programs from its row of the kind table (render/glyph_kind.h), after
// GPU culling (render/glyph_culling.h) and, for superquadrics, the occlusion
// pre-pass (render/occluder_pyramid.h). Every program is built on the first
// frame that needs it.
#include <array>
#include <cstdint>
#include <memory>

#include "render/glyph_culling.h"
#include "render/glyph_path.h"
#include "render/kind_programs.h"
#include "render/occluder_pyramid.h"
#include "render/quad_sprites.h"
#include "render/renderer_profile.h"
#include "render/tessellated.h"

namespace tg::render {

class RasterGlyphs final : public GlyphPath {
 public:
  RasterGlyphs(const gl::Api& gl, const gl::ShaderLibrary& lib);
  ~RasterGlyphs() override;
  RasterGlyphs(const RasterGlyphs&) = delete;
  RasterGlyphs& operator=(const RasterGlyphs&) = delete;

  std::string_view name() const override { return "raster"; }
  void upload(const tensor::GlyphSet& set) override;
  void setParams(const FrameParams& p, const FrameParams* old) override;
  void setColorWindow(glm::dvec2 window) override;
  void uploadColorScalars(std::span<const float> byRecord) override;
  void drawView(const Camera& cam, const FrameParams& p, const GBuffer& target) override;
  std::pair<glm::dvec3, glm::dvec3> castersBoxWC(const FrameParams& p) const override;
  void drawShadowCasters(const Camera& light, const FrameParams& p, ShadowPass& shadow) override;
  std::size_t gpuBytes() const override;
  GLuint recordBuffer() const override { return buffer_; }
  IterationStats iterationStats() const override;
  std::uint64_t drawnGlyphs() const override { return culling_.drawnGlyphs(); }
  void requestDrawnCount() override { culling_.requestDrawnCount(); }
  std::optional<std::uint64_t> latestDrawnCount() override { return culling_.latestDrawnCount(); }

  // What the tests of culling, dispatch and lazy building look at.
  const GlyphCulling& culling() const { return culling_; }
  // Frames that ran the superquadric occlusion pre-pass since construction.
  std::uint64_t occlusionPrepasses() const { return occlusionPrepasses_; }
  // Whether kind k's closed-form program exists (built on first use).
  bool kindBuilt(GlyphKind k) const { return kinds_.built(k); }
  // Whether a frame has needed the Newton march (its program is built then).
  bool marchProgramBuilt() const;
  // Draws by march variant v since construction.
  std::uint64_t marchDraws(MarchVariant v) const { return marchDraws_[std::size_t(v)]; }
  bool tessellatedProgramBuilt() const { return tessellated_.program() != nullptr; }
  // Times the records' buffer was made (one per upload): colour changes must
  // leave it alone.
  std::uint64_t recordBufferUploads() const { return recordUploads_; }

 private:
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
  const gl::Program& occluderProgram(const FrameParams& p);
  void setShapeUniforms(const gl::Program& prog, const FrameParams& p, const FrameParams* old) const;
  // Programs that draw glyphs, and those of them that take the superquadric
  // shape uniforms; null where a marching program is not built yet.
  std::array<const gl::Program*, 9> glyphPrograms() const;
  std::array<const gl::Program*, 7> shapePrograms() const;
  // Spheres or definite glyphs uploaded: what the occlusion pre-pass draws.
  bool hasOccluders() const { return groupCounts_[0] + groupCounts_[1] > 0; }

  const gl::Api& gl_;
  const gl::ShaderLibrary& lib_;
  gl::Program ellipsoid_;
  // [2 * MarchVariant + stats], each built on first use (marchProgram).
  std::array<std::unique_ptr<gl::Program>, 6> march_;
  // The pre-pass's occluders (ellipsoid.vert TG_OCCLUDER_DISC, occluder_disc.frag), built on first use.
  std::unique_ptr<gl::Program> occluders_;
  std::array<std::uint64_t, 3> marchDraws_{};
  std::array<std::size_t, 3> groupCounts_{};  // uploaded glyphs by tensor::GlyphGroup
  RendererProfile profile_;  // this context's measured choices
  QuadSprites sprites_;
  GlyphCulling culling_;
  OccluderPyramid pyramid_;
  TessellatedGlyphs tessellated_;
  KindPrograms kinds_;  // closed-form kinds' programs
  GLuint buffer_ = 0, stats_ = 0, scalars_ = 0;
  std::uint64_t recordUploads_ = 0;
  GLsizei count_ = 0;
  double maxPointPx_ = 0;  // GL_POINT_SIZE_RANGE's upper end
  std::uint64_t occlusionPrepasses_ = 0;
  glm::dvec3 centresLoWC_{0.0}, centresHiWC_{0.0};  // of the uploaded glyphs
  double maxAbsEigenvalue_ = 0;
  glm::vec2 colorWindow_{0.0f};  // uColorWindow
  double typicalDiameter_ = 1.0;  // in eigenvalue units
  bool orientedSprites_ = false;  // as last set
};

// The casters' box (GlyphPath::castersBoxWC) of glyphs whose centres span
// [centresLoWC, centresHiWC] and whose largest |eigenvalue| is maxAbsEigenvalue.
std::pair<glm::dvec3, glm::dvec3> castersBoxWC(const glm::dvec3& centresLoWC, const glm::dvec3& centresHiWC,
                                               double maxAbsEigenvalue, const FrameParams& p);

// `path` as the raster path, for what only it counts; throws std::bad_cast
// for another path.
inline const RasterGlyphs& asRaster(const GlyphPath& path) { return dynamic_cast<const RasterGlyphs&>(path); }

}  // namespace tg::render
