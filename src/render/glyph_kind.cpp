#include "render/glyph_kind.h"

#include <array>
#include <stdexcept>

#include "ref/blob_ref.h"
#include "ref/ellipsoid_ref.h"
#include "ref/prism_ref.h"
#include "ref/superquadric_ref.h"

namespace tg::render {
namespace {

using Glyphs = std::span<const tensor::GlyphRecord>;

constexpr std::array<GlyphKindInfo, kGlyphKindCount> kKinds = {{
    {GlyphKind::Ellipsoid, "ellipsoid", "exact ray-cast ellipsoids", KindDraw::Ellipsoid, "ellipsoid.vert",
     "ellipsoid.frag", "", GlyphRecordKind::EigenQuat, false,
     [](const Camera& c, Glyphs g, const ref::RefParams& p, double) { return ref::renderEllipsoids(c, g, p); },
     kRasterPath | kCpuPath | kComputePath},
    {GlyphKind::Superquadric, "superquadric", "Kindlmann's superquadrics, sharpened by gamma",
     KindDraw::Superquadric, "superquadric.vert", "superquadric.frag", "", GlyphRecordKind::EigenQuat, true,
     [](const Camera& c, Glyphs g, const ref::RefParams& p, double gamma) {
       return ref::renderSuperquadrics(c, g, p, gamma);
     },
     kRasterPath | kCpuPath | kComputePath},
    {GlyphKind::Cylinder, "cylinder", "Teem's cylinders", KindDraw::ClosedForm, "prism.vert", "prism.frag",
     "TG_CYLINDER", GlyphRecordKind::EigenQuat, false,
     [](const Camera& c, Glyphs g, const ref::RefParams& p, double) { return ref::renderCylinders(c, g, p); },
     kRasterPath | kCpuPath | kComputePath},
    {GlyphKind::Box, "box", "Teem's boxes", KindDraw::ClosedForm, "prism.vert", "prism.frag", "",
     GlyphRecordKind::EigenQuat, false,
     [](const Camera& c, Glyphs g, const ref::RefParams& p, double) { return ref::renderBoxes(c, g, p); },
     kRasterPath | kCpuPath | kComputePath},
    {GlyphKind::Blob, "blob", "Blinn's blobs: the glyphs' bumps summed into one surface", KindDraw::Blob, "", "", "",
     GlyphRecordKind::EigenQuat, true,
     [](const Camera& c, Glyphs g, const ref::RefParams& p, double gamma) { return ref::renderBlobs(c, g, p, gamma); },
     kCpuPath},
}};

constexpr bool rowsInEnumOrder() {
  for (std::size_t k = 0; k < kKinds.size(); ++k)
    if (std::size_t(kKinds[k].kind) != k) return false;
  return true;
}
static_assert(rowsInEnumOrder(), "glyph kind rows must follow the GlyphKind enum");

}  // namespace

std::span<const GlyphKindInfo> glyphKinds() { return kKinds; }

const GlyphKindInfo& glyphKind(GlyphKind k) {
  if (std::size_t(k) >= kKinds.size()) throw std::invalid_argument("glyphKind: no such kind");
  return kKinds[std::size_t(k)];
}

std::optional<GlyphKind> glyphKindNamed(std::string_view name) {
  for (const GlyphKindInfo& k : kKinds)
    if (k.name == name) return k.kind;
  return std::nullopt;
}

bool pathDraws(std::string_view path, GlyphKind k) {
  const unsigned mask = path == "raster" ? kRasterPath : path == "cpu" ? kCpuPath : path == "compute" ? kComputePath : 0u;
  return (glyphKind(k).paths & mask) != 0;
}

std::string glyphKindNames() {
  std::string s;
  for (std::size_t k = 0; k < kKinds.size(); ++k)
    s.append(k == 0 ? "" : k + 1 == kKinds.size() ? " or " : ", ").append(kKinds[k].name);
  return s;
}

}  // namespace tg::render
