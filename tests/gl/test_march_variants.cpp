// Tier 3: the march's variants (shaders/lib/superquadric_march.glsl): the
// convex one, which draws definite glyphs without the grid search, and the
// mixed one, which keeps rays that miss a mixed-sign glyph's double pyramid
// out of the march, change what a frame costs, never what it shows: byte for
// byte the general march's frame.
#include "render/raster_glyphs.h"
#include "render_fixture.h"

#include "app/scene.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <random>
#include <string>
#include <vector>

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

std::size_t coveredPixels(const render::FrameImage& img) {
  return std::size_t(std::count_if(img.id.begin(), img.id.end(), [](std::uint32_t id) { return id != ref::kNoGlyph; }));
}

// Pixels whose id, depth, colour or normal differ in any bit.
std::size_t differingPixels(const render::FrameImage& a, const render::FrameImage& b) {
  EXPECT_EQ(a.id.size(), b.id.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < std::min(a.id.size(), b.id.size()); ++i)
    differing += a.id[i] != b.id[i] || std::memcmp(&a.depth[i], &b.depth[i], sizeof(float)) != 0 ||
                 std::memcmp(&a.rgba[4 * i], &b.rgba[4 * i], 4 * sizeof(float)) != 0 ||
                 std::memcmp(&a.normalWC[3 * i], &b.normalWC[3 * i], 3 * sizeof(float)) != 0;
  return differing;
}

class MarchVariants : public GlFixture {
 protected:
  struct Frame {
    render::FrameImage img;
    render::IterationStats stats;
    std::array<std::uint64_t, 3> draws;
  };
  Frame frame(const tensor::GlyphSet& set, const render::Camera& cam, render::FrameParams p) {
    ctx_->makeCurrent();
    render::GlyphRenderer r(ctx_->api(), *lib_);
    render::GBuffer target(ctx_->api(), cam.width, cam.height);
    r.upload(set);
    p.iterationStats = true;
    r.render(cam, p, target);
    return {r.readback(cam, target), r.iterationStats(),
            {render::asRaster(r.glyphPath()).marchDraws(render::MarchVariant::General), render::asRaster(r.glyphPath()).marchDraws(render::MarchVariant::Convex),
             render::asRaster(r.glyphPath()).marchDraws(render::MarchVariant::Mixed)}};
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
    render::FrameParams p = test::superquadricParams(scale, gamma);
    p.marchVariants = false;
    const Frame general = frame(set, cam, p);
    p.marchVariants = true;
    const Frame variants = frame(set, cam, p);
    EXPECT_GT(coveredPixels(general.img), general.img.id.size() / 3);
    EXPECT_EQ(differingPixels(general.img, variants.img), 0u);
    // The same marches ran, to the same iteration counts.
    EXPECT_GT(general.stats.pixels, 0u);
    EXPECT_EQ(general.stats.pixels, variants.stats.pixels);
    EXPECT_EQ(general.stats.mean, variants.stats.mean);
    EXPECT_EQ(general.stats.max, variants.stats.max);
    // Which programs drew: the general one alone, or the convex one for
    // the definite glyphs and the mixed one for the mixed-sign rest.
    EXPECT_EQ(general.draws, (std::array<std::uint64_t, 3>{1, 0, 0}));
    EXPECT_EQ(variants.draws, (std::array<std::uint64_t, 3>{0, 1, 1}));
  }
}

// Mixed-sign glyphs only (gamma 0 draws the rest as ellipsoids): the mixed
// variant skips rays outside each glyph's double pyramid and confines the
// grid search to the ray's span in it, so the frame costs fewer gauge calls
// and is the same. The point load is the common case; the
// extremes gallery at world scale 1e-6 holds discs 1e-7 as thick as wide,
// whose rays' closest approach in VC lies ~1e6 out in GC, where the march's
// float points are as coarse as the pyramid is narrow there.
TEST_F(MarchVariants, MixedVariantSkipsRaysOutsideThePyramidAndDrawsTheSameFrame) {
  struct Scene {
    std::string name;
    tensor::GlyphSet set;
    double scale;
    render::Camera cam;
  };
  std::vector<Scene> scenes;
  {
    const auto f = synth::boussinesq(8, 0.3);
    auto set = test::glyphsOf(f);
    tensor::ScaleParams sized;
    sized.percentile = 0.9;
    const double scale = tensor::resolveScale(sized, tensor::sampleMagnitudes(set, f.sampleSpacing)).scale;
    const auto cam = test::cameraFor(set, scale, test::oblique(set, 2.0 * glm::length(set.boundsMaxWC - set.boundsMinWC),
                                                                render::Projection::Perspective), 240, 180);
    scenes.push_back({"point load", std::move(set), scale, cam});
  }
  for (const double k : {1e-6, 1e6}) {
    auto [set, scale, cam] = test::scaledExtremes(k);
    scenes.push_back({"extremes at " + std::to_string(k), std::move(set), scale, cam});
  }
  for (const auto& sc : scenes) {
    ASSERT_LT(sc.set.sphereCount + sc.set.definiteCount, sc.set.glyphs.size()) << sc.name;
    for (const double gamma : {0.0, 3.0}) {
      SCOPED_TRACE(::testing::Message() << sc.name << ", gamma " << gamma);
      render::FrameParams p = test::superquadricParams(sc.scale, gamma);
      p.march = {30, 1e-6};
      p.marchVariants = false;
      const Frame general = frame(sc.set, sc.cam, p);
      p.marchVariants = true;
      const Frame variants = frame(sc.set, sc.cam, p);
      EXPECT_GT(coveredPixels(general.img), 0u);
      EXPECT_EQ(differingPixels(general.img, variants.img), 0u);
      EXPECT_EQ(general.stats.pixels, variants.stats.pixels);
      EXPECT_EQ(general.stats.mean, variants.stats.mean);
      EXPECT_EQ(general.stats.max, variants.stats.max);
      if (gamma == 0.0) {
        // The same glyphs marched, by the mixed variant: it must save gauge calls.
        EXPECT_EQ(general.draws, (std::array<std::uint64_t, 3>{1, 0, 0}));
        EXPECT_EQ(variants.draws, (std::array<std::uint64_t, 3>{0, 0, 1}));
        EXPECT_LT(double(variants.stats.gaugeCalls), 0.9 * double(general.stats.gaugeCalls));
        // On the point load the skip alone left 35% of the calls; the grid
        // search confined to each ray's span in the pyramid leaves 19%.
        if (sc.name == "point load") {
          EXPECT_LT(double(variants.stats.gaugeCalls), 0.25 * double(general.stats.gaugeCalls));
        }
      }
    }
  }
}
