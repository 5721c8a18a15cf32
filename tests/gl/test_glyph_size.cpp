// Tier 3: the magnitude mappings and the clamp (tensor/glyph_scale.h) on the
// GPU: the shaders' glyph sizes match the double-precision reference's, a
// change of mapping is uniforms only, and frustum culling keeps every glyph
// a mapping enlarges.
#include "render/raster_glyphs.h"
#include "render_fixture.h"

#include <algorithm>

using namespace tg;
using test::compare;
using test::GlFixture;
using test::glyphsOf;

namespace {

// The tolerances of test_render.cpp (ellipsoids) and test_superquadric.cpp
// (a tight march), for the same reasons: only silhouette pixels may differ,
// depth within float rounding, normals within RGBA16F's precision.
const test::Tolerance kEllipsoid{0.0, 0.01, 0.0, 2e-5, 0.1, 2.0};
const test::Tolerance kSuperquadric{0.0, 0.01, 0.0, 1e-5, 0.05, 0.5};

struct Sized {
  tensor::GlyphSet set;
  double scale;
  std::vector<std::pair<const char*, tensor::SizeMapping>> mappings;
};

// The point load: magnitudes over three decades, all tensors indefinite.
Sized pointLoad(int n) {
  const io::TensorField f = synth::boussinesq(n, 0.3);
  Sized s{glyphsOf(f), 0.0, {}};
  const auto sample = tensor::sampleMagnitudes(s.set, f.sampleSpacing);
  const double median = sample.sorted[sample.sorted.size() / 2];
  s.scale = 0.5 * f.sampleSpacing / median;
  const double clampWC = 0.6 * f.sampleSpacing;
  s.mappings = {{"linear, clamped", {tensor::Magnitude::Linear, 1.0, clampWC}},
                {"log", {tensor::Magnitude::Log, median, 0.0}},
                {"log, clamped", {tensor::Magnitude::Log, 0.1 * median, clampWC}},
                {"shape", {tensor::Magnitude::Shape, median, 0.0}}};
  return s;
}

std::size_t differing(const render::FrameImage& a, const render::FrameImage& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.id.size(); ++i)
    n += a.id[i] != b.id[i] || !std::equal(&a.rgba[4 * i], &a.rgba[4 * i + 4], &b.rgba[4 * i]);
  return n;
}

}  // namespace

TEST_F(GlFixture, MappedAndClampedGlyphsMatchTheReference) {
  const Sized s = pointLoad(6);
  for (const auto& [name, sizing] : s.mappings) {
    const auto [lo, hi] = tensor::glyphBoxWC(s.set, s.scale, sizing);
    const auto cam = render::makeCamera(test::oblique(s.set, 3.0 * glm::length(hi - lo), render::Projection::Perspective),
                                        240, 180, lo, hi);
    render::FrameParams p;
    p.scale = s.scale;
    p.sizing = sizing;
    const ref::RefParams rp{s.scale, 0.0, sizing};
    test::expectWithin(compare(draw(s.set, cam, p), ref::renderEllipsoids(cam, s.set.glyphs, rp), cam), kEllipsoid,
                       std::string(name) + ", ellipsoids");
    p.glyph = render::GlyphKind::Superquadric;
    p.march = {30, 1e-6};
    test::expectWithin(compare(draw(s.set, cam, p), ref::renderSuperquadrics(cam, s.set.glyphs, rp, 3.0), cam),
                       kSuperquadric, std::string(name) + ", superquadrics");
  }
}

TEST_F(GlFixture, ChangingTheMappingIsUniformsOnly) {
  const Sized s = pointLoad(6);
  const auto [lo, hi] = tensor::glyphBoxWC(s.set, s.scale, s.mappings[1].second);
  const auto cam = render::makeCamera(test::oblique(s.set, 3.0 * glm::length(hi - lo), render::Projection::Perspective),
                                      160, 120, lo, hi);
  render::FrameParams linear, log;
  linear.scale = log.scale = s.scale;
  log.sizing = s.mappings[1].second;
  ctx_->makeCurrent();
  render::GlyphRenderer r(ctx_->api(), *lib_);
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  r.upload(s.set);
  const std::size_t bytes = r.gpuBytes();
  r.render(cam, linear, target);
  const render::FrameImage before = r.readback(cam, target);
  r.render(cam, log, target);  // no upload in between
  const render::FrameImage after = r.readback(cam, target);
  EXPECT_EQ(r.gpuBytes(), bytes);
  EXPECT_GT(differing(before, after), 100u);  // the mapping changed the picture
  EXPECT_EQ(differing(after, draw(s.set, cam, log)), 0u);  // as a fresh upload draws it
}

TEST_F(GlFixture, FrustumCullingKeepsTheGlyphsAMappingEnlarges) {
  // Shape mapping at the largest magnitude: the smallest glyphs grow by
  // orders of magnitude, beyond what their ranges' eigenvalues alone allow.
  const io::TensorField f = synth::boussinesq(16, 0.3);
  const auto set = glyphsOf(f);
  const tensor::SizeMapping shape{tensor::Magnitude::Shape, set.maxAbsEigenvalue, 0.0};
  const double scale = 0.6 * f.sampleSpacing / set.maxAbsEigenvalue;
  const auto [lo, hi] = tensor::glyphBoxWC(set, scale, shape);
  render::CameraDesc d;  // close to one corner, so that most ranges are outside
  d.lookAtWC = set.boundsMinWC + 0.2 * (set.boundsMaxWC - set.boundsMinWC);
  d.eyeWC = d.lookAtWC + glm::dvec3(0.0, 0.0, 0.6);
  d.fovYDeg = 40.0;
  const auto cam = render::makeCamera(d, 160, 120, lo, hi);
  render::FrameParams culled, whole;
  culled.scale = whole.scale = scale;
  culled.sizing = whole.sizing = shape;
  whole.frustumCulling = false;
  ctx_->makeCurrent();
  render::GlyphRenderer r(ctx_->api(), *lib_);
  render::GBuffer target(ctx_->api(), cam.width, cam.height);
  r.upload(set);
  r.render(cam, culled, target);
  const std::uint64_t drawn = r.drawnGlyphs();
  const render::FrameImage a = r.readback(cam, target);
  EXPECT_TRUE(render::asRaster(r.glyphPath()).culling().indirect());
  EXPECT_LT(drawn, set.glyphs.size());  // culling did drop ranges
  const render::FrameImage b = draw(set, cam, whole);
  EXPECT_EQ(differing(a, b), 0u);
  EXPECT_GT(std::count_if(a.id.begin(), a.id.end(), [](std::uint32_t v) { return v != ref::kNoGlyph; }), 1000);
}
