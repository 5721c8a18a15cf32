#pragma once
// The CPU glyph path (render/glyph_path.h, "cpu"): one pass over all cores
// sets up every glyph's sprite as the raster path's vertex stage does
// (shaders/lib/ellipsoid_sprite.glsl, compiled as C++: render/glsl_cpp.h)
// and bins its pixel rectangle to screen tiles (render/tile_binning.h); then
// per tile each pixel centre is cast against the tile's glyphs in order of
// their nearest depth, stopping where the next lies behind the hit
// (shaders/lib/ellipsoid.glsl's castEllipsoid, the fragment stage's own
// code). The casts are written in place into mapped cast targets
// (render/cast_targets.h) and into the G-buffer by
// cpu_gbuffer.frag, which takes albedo and id from the record, so that the
// deferred passes, context and picking run unchanged.
//
// Superquadric frames cast each group as the raster path draws it: spheres
// (at gamma 0 definite glyphs too) as ellipsoids, the rest by the Newton
// march's variant for their group (lib/superquadric_sprite.glsl's set-up,
// lib/superquadric_cast.glsl's cast); Teem's cylinders and boxes by
// lib/prism.glsl's prismSprite and castPrism, as prism.vert and prism.frag.
// The tessellated baseline is refused. The key light's shadow map is cast
// the same way from the light and written by cpu_depth.frag.
//
// Blob frames (GlyphKind::Blob) cast the sum of the glyphs' bumps instead
// (render/cpu_blobs.h), into the same textures and shadow map.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/cast_targets.h"
#include "render/glyph_path.h"
#include "render/tile_binning.h"

namespace tg::render {

struct BlobCandidate;

// A glyph that some pixel centre may see: what its fragments would receive.
struct CastCandidate {
  glm::vec3 centreVC;
  glm::mat3 gcFromVC;
  float nearVC;  // no hit lies nearer: the raster quad's depth
  std::uint32_t record;
};

// A marched glyph's shape (superquadricShape's a, b, c), which cast it takes
// (0: the ellipsoid's, else 1 + MarchVariant) and its symmetry axis.
struct CastShape {
  glm::vec3 shape;
  std::uint8_t kind;
  std::uint8_t axis;
};

// Where a frame's casts go, one element per pixel, rows bottom first as
// GL's: the CPU path's mapped cast targets (render/cast_targets.h). A null
// normalWC or hitGC is not written.
struct CastStorage {
  float* windowDepth = nullptr;
  std::uint32_t* record = nullptr;
  glm::vec3* normalWC = nullptr;
  glm::vec4* hitGC = nullptr;
};

// A glyph's set-up: what a tile casts it from.
struct CastSetUp {
  CastCandidate c;
  CastShape shape;
};
// Frames whose set-ups take at most this keep them from the set-up pass to
// the tiles (466,000 glyphs); larger, lean, ones bound each glyph by a
// sphere there and set up in the tiles only what they cast, so that 2 M
// glyphs hold 12 bytes each, not 96, and most never pay for a set-up.
inline constexpr std::size_t kKeptSetUpBytes = std::size_t(32) << 20;

// One pixel's cast: what the CPU path hands GL; and the set-up's buffers,
// kept from frame to frame so that a frame allocates nothing.
struct CpuCasts {
  int width = 0, height = 0;
  std::span<float> windowDepth;     // reversed, 0 where empty; rows bottom first as GL's
  std::span<std::uint32_t> record;  // index into the uploaded records + 1; 0 where empty
  std::span<glm::vec3> normalWC;    // unit; empty where not asked for
  std::span<glm::vec4> hitGC;       // the GC hit point; filled only when asked
  // Where they point: `into` when set, else these, sized per frame.
  std::optional<CastStorage> into;
  std::vector<float> ownDepth;
  std::vector<std::uint32_t> ownRecord;
  std::vector<glm::vec3> ownNormal;
  std::vector<glm::vec4> ownHit;
  // Per record, what the tiles sort by (the raster quad's depth) and its
  // pixels (kNoPixels where it reaches none; blob frames: per bump).
  std::vector<float> nearVC;
  std::vector<PixelRect> rects;
  std::vector<CastSetUp> setUps;  // per record, in frames within keptSetUpBytes
  std::size_t keptSetUpBytes = kKeptSetUpBytes;  // the tests' 0 makes every frame lean
  // The glyphs (blob frames: bumps) that reached a pixel centre; in lean
  // frames, whose bounding spheres did.
  std::size_t count = 0;
  TileBins bins;
  // When it holds a byte per pixel (rows as `record`'s), only its nonzero
  // pixels are cast, the rest left empty: anti-aliasing's extra samples,
  // which keep only the centre frame's silhouette pixels (render/antialias_pass.h).
  std::vector<std::uint8_t> only;
  bool masked() const { return only.size() == std::size_t(width) * std::size_t(height); }
};

// `out` sized for a width x height frame (over out.into where set), every
// pixel empty.
void beginCasts(CpuCasts& out, int width, int height, bool hitGC);

// The casts of `cam` at p's parameters over `records` on `threads` threads
// (what CpuGlyphs::drawView uploads; the tests compare it directly). Depth,
// normal and hit are left undefined where the record says empty. Returns the
// glyphs that reached a tile.
std::uint64_t castGlyphs(std::span<const tensor::GlyphRecord> records, const Camera& cam, const FrameParams& p,
                         bool hitGC, int threads, CpuCasts& out);

class CpuGlyphs final : public GlyphPath {
 public:
  CpuGlyphs(const gl::Api& gl, const gl::ShaderLibrary& lib);
  ~CpuGlyphs() override;
  CpuGlyphs(const CpuGlyphs&) = delete;
  CpuGlyphs& operator=(const CpuGlyphs&) = delete;

  std::string_view name() const override { return "cpu"; }
  void upload(const tensor::GlyphSet& set) override;
  void setParams(const FrameParams& p, const FrameParams* old) override;
  void setColorWindow(glm::dvec2 window) override;
  void uploadColorScalars(std::span<const float> byRecord) override;
  void drawView(const Camera& cam, const FrameParams& p, const GBuffer& target) override;
  std::pair<glm::dvec3, glm::dvec3> castersBoxWC(const FrameParams& p) const override;
  void drawShadowCasters(const Camera& light, const FrameParams& p, ShadowPass& shadow) override;
  std::size_t gpuBytes() const override;
  GLuint recordBuffer() const override { return buffer_; }
  std::uint64_t drawnGlyphs() const override { return drawn_; }

 private:
  // The shadow map: the casts from `light`, depth only.
  void castShadowMap(const Camera& light, const FrameParams& p, ShadowPass& shadow);

  const gl::Api& gl_;
  CastTargets targets_;
  tensor::GlyphSet set_;  // bounds and counts; the records only where records_ is not the mapped buffer
  std::span<const tensor::GlyphRecord> records_;  // what the casts read: buffer_ mapped, or set_'s
  CpuCasts casts_;
  // The last centre frame's records and view, whose silhouettes an
  // anti-aliasing sample of the same view casts alone.
  std::vector<std::uint32_t> centreRecord_;
  glm::dmat4 centreView_{0.0};
  std::vector<BlobCandidate> blobs_;  // blob frames' set-up, kept between frames
  std::vector<PixelRect> runs_;       // the last frame's tiles that glyphs reach (tileRuns)
  GLuint buffer_ = 0, scalars_ = 0;  // scalars_: ColorMode::Array's values, by record
  int threads_;
  std::uint64_t drawn_ = 0;
};

}  // namespace tg::render
