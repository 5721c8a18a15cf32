#pragma once
// Glyph kinds as one table (render/glyph_kind.cpp): each row holds all that
// differs between kinds, so that the renderer, the CLI, the viewer's panel
// and `info` read one home. Adding a kind is its GLSL, its CPU reference in
// src/ref, an enum value and a row here, and its tests.
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace tg::tensor {
struct GlyphRecord;
}
namespace tg::ref {
struct RefImage;
struct RefParams;
}  // namespace tg::ref

namespace tg::render {

struct Camera;

// In the order of the table's rows (and of the viewer's list).
enum class GlyphKind { Ellipsoid, Superquadric, Cylinder, Box, Blob };
inline constexpr std::size_t kGlyphKindCount = 5;

// How the renderer draws a kind's glyphs into the G-buffer.
enum class KindDraw {
  // The exact ellipsoid program, every group (shaders/ellipsoid.*).
  Ellipsoid,
  // Spheres (and at gamma 0 definite glyphs) by the ellipsoid program, the
  // rest by the Newton march's variants, after the occlusion pre-pass.
  Superquadric,
  // One closed-form program of the kind's own for every group: no march, no
  // pre-pass, axis-aligned sprites (Teem's cylinder and box).
  ClosedForm,
  // Blinn's blobs: a surface of the sum of every glyph's bump, which no
  // sprite of one glyph can cast; the cpu path's tiles hold the lists of
  // bumps each pixel needs (render/cpu_blobs.h).
  Blob,
};

// The glyph paths (render/glyph_path.h) that draw a kind.
enum PathMask : unsigned { kRasterPath = 1, kCpuPath = 2, kComputePath = 4 };

// The per-glyph record a kind reads from the glyph buffer.
enum class GlyphRecordKind {
  EigenQuat,  // tensor::GlyphRecord: three signed eigenvalues and a frame quaternion
};

// The CPU oracle the kind's GL tests compare against (src/ref); `gamma`
// is FrameParams::gamma, read only by kinds it applies to.
using RefRenderer = ref::RefImage (*)(const Camera& cam, std::span<const tensor::GlyphRecord> glyphs,
                                      const ref::RefParams& p, double gamma);

struct GlyphKindInfo {
  GlyphKind kind;
  std::string_view name;  // on the command line, in view scripts and the panel
  std::string_view help;  // a phrase for the help texts
  KindDraw draw;
  // Its program's GLSL entry points (shaders/), and the `#pragma tg option`
  // that selects the kind in them (empty: none).
  std::string_view vertex, fragment, option;
  GlyphRecordKind record;
  // Options that apply to the kind alone: the superquadric sharpness (and the
  // march's --iterations and --epsilon, which shape it); blobs take gamma
  // for their bumps' shapes.
  bool gamma;
  RefRenderer reference;
  unsigned paths;  // PathMask
};

// Whether the glyph path named `path` ("raster", "cpu", "compute") draws kind k.
bool pathDraws(std::string_view path, GlyphKind k);

std::span<const GlyphKindInfo> glyphKinds();
const GlyphKindInfo& glyphKind(GlyphKind k);
std::optional<GlyphKind> glyphKindNamed(std::string_view name);
// "ellipsoid, superquadric, cylinder, box or blob": for the messages that list them.
std::string glyphKindNames();

}  // namespace tg::render
