// The glyph kind table (render/glyph_kind.h): what the CLI, the viewer and
// `info` read from it, and each row's CPU reference, without GL.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "ref/ellipsoid_ref.h"
#include "view/camera.h"
#include "render/glyph_kind.h"
#include "tensor/glyph.h"

using namespace tg;

TEST(GlyphKinds, NamesAreUniqueAndFindTheirRow) {
  std::set<std::string_view> names;
  const std::string listed = render::glyphKindNames();
  for (const render::GlyphKindInfo& k : render::glyphKinds()) {
    EXPECT_TRUE(names.insert(k.name).second) << k.name;
    EXPECT_EQ(render::glyphKindNamed(k.name), k.kind) << k.name;
    EXPECT_EQ(&render::glyphKind(k.kind), &k) << k.name;
    EXPECT_NE(listed.find(k.name), std::string::npos) << listed;
    EXPECT_FALSE(k.help.empty()) << k.name;
    // A raster kind names its programs; the cpu path's casts need none.
    EXPECT_EQ(k.vertex.empty() || k.fragment.empty(), !render::pathDraws("raster", k.kind)) << k.name;
    EXPECT_TRUE(render::pathDraws("raster", k.kind) || render::pathDraws("cpu", k.kind)) << k.name << " has no path";
    EXPECT_FALSE(render::pathDraws("tiles", k.kind)) << k.name;
    EXPECT_NE(k.reference, nullptr) << k.name;
  }
  EXPECT_EQ(render::glyphKindNamed("tube"), std::nullopt);
  EXPECT_EQ(render::glyphKindNamed(""), std::nullopt);
}

// Gamma shapes the marched superquadrics and the blobs' bumps, nothing else.
TEST(GlyphKinds, GammaAppliesToTheMarchedKindAndBlobsAlone) {
  for (const render::GlyphKindInfo& k : render::glyphKinds())
    EXPECT_EQ(k.gamma, k.draw == render::KindDraw::Superquadric || k.draw == render::KindDraw::Blob) << k.name;
}

// Each row's reference draws a glyph where it stands, and its gamma is read
// only by the kinds it applies to: a cube-like gamma changes a superquadric's
// silhouette and leaves every other kind's picture alone.
TEST(GlyphKinds, EachReferenceDrawsItsGlyphAndReadsGammaOnlyWhereItApplies) {
  const float pos[3] = {0, 0, 0};
  const float ten[6] = {1.0f, 0.1f, 0.0f, 0.6f, 0.0f, 0.3f};
  const tensor::GlyphSet set = tensor::buildGlyphs(std::span(pos, 3), std::span(ten, 6), {});
  render::CameraDesc d;
  d.eyeWC = {0.4, -0.5, 4.0};
  d.lookAtWC = {0, 0, 0};
  d.upWC = {0, 1, 0};
  const render::Camera cam = render::makeCamera(d, 64, 48, glm::dvec3(-1.2), glm::dvec3(1.2));
  for (const render::GlyphKindInfo& k : render::glyphKinds()) {
    const ref::RefImage soft = k.reference(cam, set.glyphs, {1.0, 0.0}, 0.5);
    const ref::RefImage sharp = k.reference(cam, set.glyphs, {1.0, 0.0}, 20.0);
    const std::size_t centre = std::size_t(cam.height / 2) * std::size_t(cam.width) + std::size_t(cam.width / 2);
    EXPECT_EQ(soft.id[centre], 0u) << k.name;
    EXPECT_EQ(soft.id != sharp.id, k.gamma) << k.name;
  }
}
