// Tier 2 (GL-free): the FA order the renderer uploads (render/fa_order.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "data-synthetic/generators.h"
#include "render/fa_order.h"

using namespace tg;

TEST(FaOrder, BinsAreMonotonicAndCoverEveryValue) {
  EXPECT_EQ(render::faBin(0.0f), 0);
  EXPECT_EQ(render::faBin(-1.0f), 0);
  EXPECT_EQ(render::faBin(std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(render::faBin(1.0f), render::kFaBins - 1);
  EXPECT_EQ(render::faBin(7.5f), render::kFaBins - 1);  // indefinite tensors
  EXPECT_EQ(render::faBin(std::nextafter(1.0f, 0.0f)), render::kFaBins - 2);
  int last = 0;
  for (float fa = 0.0f; fa < 1.2f; fa += 1e-4f) {
    const int b = render::faBin(fa);
    ASSERT_GE(b, last) << fa;
    last = b;
  }
}

TEST(FaOrder, PermutesWithinGroupsAndMakesThresholdsPrefixes) {
  // All three groups: random definite tensors, isotropic ones, and random
  // symmetric ones, mostly indefinite, whose FA reaches past 1.
  io::TensorField f = synth::randomField(600, 3);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < 400; ++i) {
    const double p[3] = {double(i), 0, 0};
    const double iso[6] = {2, 0, 0, 2, 0, 2}, any[6] = {u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
    f.addSym(std::uint32_t(f.size()), p, i % 10 == 0 ? iso : any);
  }
  const tensor::GlyphSet set = tensor::buildGlyphs(f.positions, f.tensors, f.ids, 1);
  ASSERT_GT(set.sphereCount, 0u);
  ASSERT_GT(set.definiteCount, 0u);
  ASSERT_LT(set.sphereCount + set.definiteCount, set.glyphs.size());
  std::vector<tensor::GlyphRecord> out(set.glyphs.size());
  const render::FaOrder o = render::orderByFa(set, out);

  const std::size_t end[3] = {set.sphereCount, set.sphereCount + set.definiteCount, set.glyphs.size()};
  for (int g = 0; g < 3; ++g) {
    const std::size_t b = o.groupStart[std::size_t(g)], e = end[g];
    // The same records (by id) as the group had, FA bins non-increasing.
    std::vector<std::uint32_t> before, after;
    for (std::size_t i = b; i < e; ++i) {
      before.push_back(set.glyphs[i].id);
      after.push_back(out[i].id);
      if (i > b) {
        EXPECT_LE(render::faBin(out[i].fa), render::faBin(out[i - 1].fa)) << i;
      }
    }
    std::sort(before.begin(), before.end());
    std::sort(after.begin(), after.end());
    EXPECT_EQ(before, after) << "group " << g;
    for (float t : {0.0f, 0.1f, 0.3333f, 0.5f, 0.9f, 0.999f, 1.0f, 1.5f}) {
      const std::size_t n = o.drawCount(g, t);
      ASSERT_LE(b + n, e);
      // Every glyph at or above t is inside the prefix; anything drawn
      // below t shares t's bin.
      for (std::size_t i = b; i < e; ++i) {
        if (i >= b + n) {
          EXPECT_LT(out[i].fa, t) << "group " << g << " t " << t;
        } else if (out[i].fa < t) {
          EXPECT_EQ(render::faBin(out[i].fa), render::faBin(t));
        }
      }
    }
    EXPECT_EQ(o.drawCount(g, 0.0f), e - b);
  }
}
