// Tier 3: the march's convex variant (shaders/lib/superquadric_march.glsl),
// which draws definite glyphs without the grid search, changes what a frame
// costs, never what it shows: byte for byte the general march's frame.
#include "render_fixture.h"

#include <array>
#include <cstring>
#include <random>

using namespace tg;
using test::GlFixture;

namespace {

// Spheres, definite and mixed-sign glyphs in turn, in a block seen from close
// by, so that some of each group lies in front.
io::TensorField threeGroups(int n) {
  io::TensorField f;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uint32_t id = 0;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x, ++id) {
        const int kind = int(id % 3);
        const double shift = kind == 2 ? 0.0 : 2.2, off = kind == 0 ? 0.0 : 0.6;
        const double d = kind == 0 ? 1.5 : 0.0;
        double t[9] = {shift + d + u(rng), off * u(rng), off * u(rng), 0, shift + u(rng), off * u(rng), 0, 0,
                       shift + u(rng)};
        if (kind == 0) t[4] = t[8] = t[0];
        t[3] = t[1], t[6] = t[2], t[7] = t[5];
        const double p[3] = {double(x), double(y), double(z)};
        f.addFull(id, p, t);
      }
  return f;
}

class MarchVariants : public GlFixture {
 protected:
  struct Frame {
    render::FrameImage img;
    render::IterationStats stats;
    std::array<std::uint64_t, 2> draws;
  };
  Frame frame(const tensor::GlyphSet& set, const render::Camera& cam, render::FrameParams p) {
    ctx_->makeCurrent();
    render::GlyphRenderer r(ctx_->api(), *lib_);
    render::GBuffer target(ctx_->api(), cam.width, cam.height);
    r.upload(set);
    p.iterationStats = true;
    r.render(cam, p, target);
    return {r.readback(cam, target), r.iterationStats(),
            {r.marchDraws(render::MarchVariant::General), r.marchDraws(render::MarchVariant::Convex)}};
  }
};

}  // namespace

TEST_F(MarchVariants, GroupVariantsDrawTheGeneralMarchsFrame) {
  const auto set = test::glyphsOf(threeGroups(9));
  ASSERT_GT(set.sphereCount, 0u);
  ASSERT_GT(set.definiteCount, 0u);
  ASSERT_LT(set.sphereCount + set.definiteCount, set.glyphs.size());
  const double scale = 0.5 / set.maxAbsEigenvalue;
  render::CameraDesc d;
  d.lookAtWC = 0.5 * (set.boundsMinWC + set.boundsMaxWC);
  d.eyeWC = d.lookAtWC + glm::dvec3(0.4, -0.6, 1.0) * 7.0;
  d.upWC = {0, 1, 0};
  d.fovYDeg = 50;
  const auto cam = test::cameraFor(set, scale, d, 220, 160);
  for (const double gamma : {1.0, 3.0, 8.0}) {
    SCOPED_TRACE(::testing::Message() << "gamma " << gamma);
    render::FrameParams p;
    p.scale = scale;
    p.glyph = render::GlyphKind::Superquadric;
    p.gamma = gamma;
    p.marchVariants = false;
    const Frame general = frame(set, cam, p);
    p.marchVariants = true;
    const Frame variants = frame(set, cam, p);
    ASSERT_EQ(general.img.id.size(), variants.img.id.size());
    std::size_t covered = 0, differing = 0;
    for (std::size_t i = 0; i < general.img.id.size(); ++i) {
      covered += general.img.id[i] != ref::kNoGlyph;
      differing += general.img.id[i] != variants.img.id[i] ||
                   std::memcmp(&general.img.depth[i], &variants.img.depth[i], sizeof(float)) != 0 ||
                   std::memcmp(&general.img.rgba[4 * i], &variants.img.rgba[4 * i], 4 * sizeof(float)) != 0 ||
                   std::memcmp(&general.img.normalWC[3 * i], &variants.img.normalWC[3 * i], 3 * sizeof(float)) != 0;
    }
    EXPECT_GT(covered, general.img.id.size() / 3);
    EXPECT_EQ(differing, 0u);
    // The same marches ran, to the same iteration counts.
    EXPECT_GT(general.stats.pixels, 0u);
    EXPECT_EQ(general.stats.pixels, variants.stats.pixels);
    EXPECT_EQ(general.stats.mean, variants.stats.mean);
    EXPECT_EQ(general.stats.max, variants.stats.max);
    // Which programs drew: the general one alone, or the convex one for
    // the definite glyphs and the general one for the mixed-sign rest.
    EXPECT_EQ(general.draws, (std::array<std::uint64_t, 2>{1, 0}));
    EXPECT_EQ(variants.draws, (std::array<std::uint64_t, 2>{1, 1}));
  }
}
