// Tier 3: Teem's cylinder and box glyphs (GlyphKind::Cylinder, Box) on
// OSMesa against the exact double-precision CPU reference (ref/prism_ref.h),
// on coverage, id, depth and normal, and their dispatch.
#include <random>

#include <glm/gtc/quaternion.hpp>

#include "ref/prism_ref.h"
#include "render/raster_glyphs.h"
#include "render_fixture.h"

using namespace tg;
using test::GlFixture;

namespace {

// As the ellipsoid tests (test_render.cpp): coverage may differ only where a
// pixel centre lies within float rounding of a silhouette (1% of glyph
// pixels, none in interiors, no other glyph); depth 2e-5 relative, above
// float rounding through the same chain of ~10 operations, far below a
// wrong root or cap (1e-3 and more). Normals: RGBA16F storage (< 0.03 deg),
// median 0.1 deg; the worst case is the one thing that differs from the
// ellipsoid: a pixel centre within float rounding of an edge between two flat
// faces (box) or between cap and side (cylinder) may take either face's
// normal, up to 90 deg apart, so the bound is on the 99th percentile (2 deg),
// which a wrong face or a normal not transformed as a covector (tens of
// degrees over whole faces) exceeds.
const test::Tolerance kTolerance{0.0, 0.01, 0.0, 2e-5, 0.1, 180.0};

void expectMatch(const test::Comparison& c, const std::string& what) {
  test::expectWithin(c, kTolerance, what);
  EXPECT_LT(c.normalDeg.p99, 2.0) << what;
}

ref::RefImage reference(render::GlyphKind k, const render::Camera& cam, const tensor::GlyphSet& set,
                        const ref::RefParams& p) {
  return k == render::GlyphKind::Cylinder ? ref::renderCylinders(cam, set.glyphs, p)
                                          : ref::renderBoxes(cam, set.glyphs, p);
}

const char* nameOf(render::GlyphKind k) { return k == render::GlyphKind::Cylinder ? "cylinder" : "box"; }

// Linear, planar (Teem draws a disc along e2), spherical, negative and
// mixed-sign tensors in random orientations: every branch of Teem's axis rule.
tensor::GlyphSet branchGallery() {
  const double shapes[][3] = {{1.0, 0.3, 0.2},  {1.0, 0.9, 0.2},   {0.8, 0.8, 0.8},  {-0.2, -0.3, -1.0},
                              {-0.2, -0.9, -1.0}, {1.0, 0.5, -0.7}, {0.6, -0.4, -1.0}, {1.0, 0.0, -0.3}};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<float> pos, ten;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 axis = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)));
    const glm::dmat3 rot = glm::mat3_cast(glm::angleAxis(3.0 * u(rng), axis));
    const glm::dmat3 m = rot * glm::dmat3(glm::dvec3(shapes[i][0], 0, 0), glm::dvec3(0, shapes[i][1], 0),
                                          glm::dvec3(0, 0, shapes[i][2])) * glm::transpose(rot);
    pos.insert(pos.end(), {float(2.6 * (i % 4)), float(2.6 * (i / 4)), 0.0f});
    ten.insert(ten.end(), {float(m[0][0]), float(m[0][1]), float(m[0][2]), float(m[1][1]), float(m[1][2]),
                           float(m[2][2])});
  }
  return tensor::buildGlyphs(pos, ten, {});
}

const render::GlyphKind kKinds[] = {render::GlyphKind::Cylinder, render::GlyphKind::Box};

}  // namespace

TEST(PrismReference, TeemsCylinderAxis) {
  EXPECT_EQ(ref::teemCylinderAxis({1.0, 0.3, 0.2}), 0);    // linear: along e0
  EXPECT_EQ(ref::teemCylinderAxis({1.0, 0.9, 0.2}), 2);    // planar: a disc along e2
  EXPECT_EQ(ref::teemCylinderAxis({0.5, 0.5, 0.5}), 2);    // sphere: cl = cp = 0
  EXPECT_EQ(ref::teemCylinderAxis({-0.2, -0.3, -1.0}), 2); // negative linear: along the largest |l|
  EXPECT_EQ(ref::teemCylinderAxis({-0.2, -0.9, -1.0}), 0); // negative planar: along the smallest |l|
  EXPECT_EQ(ref::teemCylinderAxis({1.0, 0.5, -0.7}), 2);   // mixed, one negative
  EXPECT_EQ(ref::teemCylinderAxis({0.6, -0.4, -1.0}), 0);  // mixed, one positive
  EXPECT_EQ(ref::teemCylinderAxis({0.0, 0.0, 0.0}), 2);
}

TEST(PrismReference, ExactHitsAndNormals) {
  double t;
  glm::dvec3 n;
  // Along the axis into the cap, from outside and from inside (the exit).
  ASSERT_TRUE(ref::cylinderFirstHit({0.3, 0.2, 5.0}, {0, 0, -1}, -1e9, t, n));
  EXPECT_DOUBLE_EQ(t, 4.0);
  EXPECT_EQ(n, glm::dvec3(0, 0, 1));
  ASSERT_TRUE(ref::cylinderFirstHit({0.3, 0.2, 0.0}, {0, 0, -1}, 0.0, t, n));
  EXPECT_DOUBLE_EQ(t, 1.0);
  EXPECT_EQ(n, glm::dvec3(0, 0, -1));
  // Across the side, and past the rim.
  ASSERT_TRUE(ref::cylinderFirstHit({-3.0, 0.0, 0.5}, {1, 0, 0}, -1e9, t, n));
  EXPECT_DOUBLE_EQ(t, 2.0);
  EXPECT_EQ(n, glm::dvec3(-1, 0, 0));
  EXPECT_FALSE(ref::cylinderFirstHit({-3.0, 0.0, 1.01}, {1, 0, 0}, -1e9, t, n));
  EXPECT_FALSE(ref::cylinderFirstHit({0.8, 0.8, 5.0}, {0, 0, -1}, -1e9, t, n));  // inside the square, outside the disc
  ASSERT_TRUE(ref::boxFirstHit({0.8, 0.8, 5.0}, {0, 0, -1}, -1e9, t, n));
  EXPECT_DOUBLE_EQ(t, 4.0);
  EXPECT_EQ(n, glm::dvec3(0, 0, 1));
  ASSERT_TRUE(ref::boxFirstHit({-2.0, 0.5, 0.0}, glm::dvec3(1, 0.1, 0), -1e9, t, n));
  EXPECT_EQ(n, glm::dvec3(-1, 0, 0));
  EXPECT_FALSE(ref::boxFirstHit({-2.0, 1.5, 0.0}, {1, 0, 0}, -1e9, t, n));
}

TEST_F(GlFixture, PrismsMatchTheReferencePerspectiveAndOrtho) {
  const auto set = test::glyphsOf(synth::randomField(216, 3));
  const double scale = 0.6;
  for (auto kind : kKinds)
    for (auto proj : {render::Projection::Perspective, render::Projection::Orthographic}) {
      const auto cam = test::cameraFor(set, scale, test::oblique(set, 12.0, proj), 200, 150);
      render::FrameParams p;
      p.scale = scale;
      p.glyph = kind;
      expectMatch(test::compare(draw(set, cam, p), reference(kind, cam, set, {scale, 0.0}), cam),
                  std::string(nameOf(kind)) + (proj == render::Projection::Perspective ? " perspective" : " ortho"));
    }
}

TEST_F(GlFixture, PrismsOfEverySignMatchTheReference) {
  const auto set = branchGallery();
  const double scale = 1.0;
  for (auto kind : kKinds) {
    const auto cam = test::cameraFor(set, scale, test::oblique(set, 14.0, render::Projection::Perspective), 240, 160);
    render::FrameParams p;
    p.glyph = kind;
    const auto img = draw(set, cam, p);
    const auto c = test::compare(img, reference(kind, cam, set, {scale, 0.0}), cam);
    expectMatch(c, nameOf(kind));
    // Every glyph is seen: a mixed-sign or negative one is drawn by |l|, not lost.
    std::vector<bool> seen(set.glyphs.size(), false);
    for (auto id : img.id)
      if (id < seen.size()) seen[id] = true;
    EXPECT_EQ(std::count(seen.begin(), seen.end(), true), std::ptrdiff_t(seen.size())) << nameOf(kind);
  }
}

TEST_F(GlFixture, PrismsWithTheEyeInsideAndAcrossTheNearPlane) {
  // The full-viewport fallback (a cap or corner behind the eye) and rays
  // that start inside a glyph (its far wall).
  const auto set = test::glyphsAroundTheEye();
  for (auto kind : kKinds)
    for (auto proj : {render::Projection::Perspective, render::Projection::Orthographic}) {
      const auto cam = test::insideCamera(proj);
      render::FrameParams p;
      p.glyph = kind;
      expectMatch(test::compare(draw(set, cam, p), reference(kind, cam, set, {1.0, 0.0}), cam),
                  std::string(nameOf(kind)) + " inside");
    }
}

TEST_F(GlFixture, PrismsFollowSizingAndThreshold) {
  const auto set = test::glyphsOf(synth::randomField(216, 5));
  render::FrameParams p;
  p.scale = 0.5;
  p.faMin = 0.3;
  p.sizing.magnitude = tensor::Magnitude::Log;
  p.sizing.lambda0 = 0.5;
  p.sizing.maxRadiusWC = 0.35;
  const auto cam = test::cameraFor(set, p.scale, test::oblique(set, 12.0, render::Projection::Perspective), 200, 150);
  for (auto kind : kKinds) {
    p.glyph = kind;
    expectMatch(test::compare(draw(set, cam, p), reference(kind, cam, set, {p.scale, p.faMin, p.sizing}), cam),
                std::string(nameOf(kind)) + " sized");
  }
}

TEST_F(GlFixture, PrismKindsRunOnlyTheirOwnProgram) {
  // "Model only what a scene requires": boxes build no cylinder program and
  // run no superquadric pre-pass; an ellipsoid frame builds neither, nor the march.
  const auto set = test::glyphsOf(synth::randomField(64, 2));
  const auto cam = test::cameraFor(set, 0.6, test::oblique(set, 12.0, render::Projection::Perspective), 96, 72);
  ctx_->makeCurrent();
  render::GlyphRenderer r(ctx_->api(), *lib_);
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  r.upload(set);
  render::FrameParams p;
  p.scale = 0.6;
  r.render(cam, p, target);
  EXPECT_FALSE(render::asRaster(r.glyphPath()).kindBuilt(render::GlyphKind::Box));
  EXPECT_FALSE(render::asRaster(r.glyphPath()).kindBuilt(render::GlyphKind::Cylinder));
  p.glyph = render::GlyphKind::Box;
  p.shadow.enabled = true;  // the shadow map draws glyphs too
  r.render(cam, p, target);
  EXPECT_TRUE(render::asRaster(r.glyphPath()).kindBuilt(render::GlyphKind::Box));
  EXPECT_FALSE(render::asRaster(r.glyphPath()).kindBuilt(render::GlyphKind::Cylinder));
  EXPECT_EQ(render::asRaster(r.glyphPath()).occlusionPrepasses(), 0u);
  EXPECT_EQ(r.passRuns("shadow"), 1u);
  const auto img = r.readback(cam, target);
  EXPECT_GT(std::count_if(img.id.begin(), img.id.end(), [](std::uint32_t id) { return id != ref::kNoGlyph; }), 500);
  // Neither the ellipsoid nor the box frames compiled the Newton march; the
  // first superquadric frame does, and draws with it.
  EXPECT_FALSE(render::asRaster(r.glyphPath()).marchProgramBuilt());
  p.glyph = render::GlyphKind::Superquadric;
  r.render(cam, p, target);
  EXPECT_TRUE(render::asRaster(r.glyphPath()).marchProgramBuilt());
}
