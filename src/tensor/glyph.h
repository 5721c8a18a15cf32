#pragma once
// The one-vertex glyph record shared by CPU and GPU, and its construction.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "util/mapped_array.h"
#include "util/progress.h"

#include <glm/vec3.hpp>

namespace tg::tensor {

// std430 layout; mirrored by shaders/lib/glyph_record.glsl. 48 bytes per glyph.
// Shape-dependent quantities (scale, gamma, thresholds) are not baked in, so
// changing them is a uniform update, never a re-upload.
struct GlyphRecord {
  float posWC[3];
  float fa;              // unclamped; > 1 is possible for indefinite tensors
  float eigenvalues[3];  // signed, descending
  std::uint32_t id;      // index of the tensor in the input
  float frameWC[4];      // unit quaternion (x, y, z, w): GC axes -> eigenvectors in WC
};
static_assert(sizeof(GlyphRecord) == 48);

// What a glyph needs from the dispatch: spheres (equal eigenvalues, the zero
// tensor included) are ellipsoids at every gamma; definite tensors are
// ellipsoids at gamma 0; mixed signs take Schultz-Kindlmann shapes, which do
// not depend on gamma.
enum class GlyphGroup : std::uint8_t { Sphere = 0, Definite = 1, Mixed = 2 };
// Inline: buildRange asks it once a record.
inline GlyphGroup glyphGroup(const GlyphRecord& g) {
  if (g.eigenvalues[0] == g.eigenvalues[2]) return GlyphGroup::Sphere;
  return g.eigenvalues[2] > 0.0f || g.eigenvalues[0] < 0.0f ? GlyphGroup::Definite : GlyphGroup::Mixed;
}

// Glyphs [kTileGlyphs t, kTileGlyphs (t + 1)) form tile t. Tiles keep the
// input order, so that a tile of a volume is a compact block of space (what
// frustum culling tests); within a tile the glyphs are stably ordered
// spheres, then definite, then mixed. 256 is the culling granularity and the
// compaction workgroup (shaders/compact_fa.comp).
inline constexpr std::size_t kTileGlyphs = 256;
struct GlyphTile {
  std::uint16_t sphereEnd, definiteEnd;  // offsets within the tile
};

struct GlyphSet {
  util::MappedArray<GlyphRecord> glyphs;  // untouched until built: no zeroing pass
  std::vector<GlyphTile> tiles;  // ceil(glyphs / kTileGlyphs)
  glm::dvec3 boundsMinWC{0.0}, boundsMaxWC{0.0};  // of glyph centres
  // Of the centres of glyphs that have a size (not every eigenvalue zero):
  // what a view frames, since a DTI volume's zero background draws nothing.
  // Empty (min > max) when no glyph has a size.
  glm::dvec3 sizedBoundsMinWC{0.0}, sizedBoundsMaxWC{0.0};
  double maxAbsEigenvalue = 0;
  double mdMin = 0, mdMax = 0;  // of the non-zero tensors: the colour range of --color md
  double eigenvalueMin = 0, eigenvalueMax = 0;  // signed: a stress field's compression and tension
  // Totals over the tiles: three equal eigenvalues; definite (all positive
  // or all negative); the rest have eigenvalues of mixed sign or zero.
  std::size_t sphereCount = 0, definiteCount = 0;
  std::size_t droppedByShape = 0;  // below GlyphOptions::clMin or cpMin
};

// Load-time choices that change which glyphs exist or their shape; the
// interactive ones (scale, FA threshold, gamma) are uniforms instead.
struct GlyphOptions {
  double clMin = 0, cpMin = 0;  // drop glyphs below these Westin measures
  // Eigenvalues below this are raised to it (Teem's tenGlyphParm clampEval,
  // FURY's eigenvalue floor): it keeps planar and linear glyphs visible.
  // FA, cl and cp are computed before the clamp, from the data.
  std::optional<double> minEigenvalue;
};

// Input: N positions (x y z) and N tensors (xx xy xz yy yz zz), all finite;
// ids[i] is the input index reported for glyph i (empty: 0..N-1).
// Runs on up to `threads` threads (0: hardware concurrency). `progress`
// hears ("eigen", done, N, "tensors") every 64k tensors of the calling thread.
GlyphSet buildGlyphs(std::span<const float> positions, std::span<const float> tensors,
                     std::span<const std::uint32_t> ids, unsigned threads = 0, const GlyphOptions& opt = {},
                     const util::ProgressSink& progress = {});


// Rotation matrix columns from a record's quaternion (the eigenvectors).
void frameAxes(const GlyphRecord& g, glm::dvec3 axes[3]);

}  // namespace tg::tensor

namespace tg::tensor {

// Thinnest axis kept, relative to the glyph's longest: zero eigenvalues give
// a disk or needle of this relative thickness instead of a degenerate quadric
// (whose parameter-space transform would be singular). 1e-7 keeps the 1e6
// eigenvalue ratios of the extremes gallery exact and the inverse finite in float.
inline constexpr double kMinAxisRatio = 1e-7;

// Semi-axes in WC of glyph `g` at `scale` world units per eigenvalue unit:
// S·|λ_i|, floored at kMinAxisRatio of the largest. All zero for a zero tensor.
glm::dvec3 ellipsoidAxes(const GlyphRecord& g, double scale);

}  // namespace tg::tensor

namespace tg::tensor {

// --scale-mode: how --scale becomes world units per eigenvalue unit
// (tensor/glyph_scale.h, ScaleParams, resolves it).
enum class ScaleMode { Absolute, Max, Spacing };

// The glyph centres' bounds widened by kGlyphReach times the largest
// semi-axis at `scale` (scale * max |eigenvalue|): the depth range of linear,
// unclamped glyphs of any kind.
struct BoxWC {
  glm::dvec3 lo, hi;
};
// How far any glyph reaches from its centre, in units of its largest
// semi-axis: a box's corner (and a superquadric's, which its box holds) lies
// sqrt(3) semi-axes out, a cylinder's rim sqrt(2). The depth range must hold
// all of it, or the near plane cuts the glyphs nearest the eye.
inline constexpr double kGlyphReach = 1.7320508075688772;
// A blob's bump keeps its thinnest semi-axis at least this share of its
// longest (a glyph's floor is kMinAxisRatio): a flat tensor's bump is then a
// disc that a single-precision ray samples, not one 1e-7 of it thick, which
// falls between the float depths of its own entry and exit.
inline constexpr double kBlobMinAxisRatio = 1e-3;
BoxWC glyphBoxWC(const GlyphSet& set, double scale);

}  // namespace tg::tensor
