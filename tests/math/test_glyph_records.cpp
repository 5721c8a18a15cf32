// Tier 1: glyph records built on SIMD lanes (tensor/glyph.cpp) against the
// scalar definitions: eigensolve(), glm::quat_cast, anisotropy().
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include "tensor/anisotropy.h"
#include "tensor/eigen.h"
#include "tensor/glyph.h"

using namespace tg::tensor;

namespace {

// Random symmetric tensors, with a few diagonal and isotropic ones mixed in,
// 1000 + 3 so that the last block is partial.
std::vector<float> sampleTensors(std::size_t n) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<float> t;
  for (std::size_t i = 0; i < n; ++i) {
    if (i % 97 == 0) t.insert(t.end(), {2, 0, 0, 2, 0, 2});
    else if (i % 89 == 0) t.insert(t.end(), {1, 0, 0, 3, 0, -2});
    else for (int c = 0; c < 6; ++c) t.push_back(u(rng));
  }
  return t;
}

}  // namespace

TEST(GlyphRecords, MatchTheScalarDefinitions) {
  const std::size_t n = 1003;
  const std::vector<float> ten = sampleTensors(n);
  std::vector<float> pos(3 * n);
  for (std::size_t i = 0; i < 3 * n; ++i) pos[i] = float(i);
  const GlyphSet set = buildGlyphs(pos, ten, {}, 1);
  ASSERT_EQ(set.glyphs.size(), n);
  int shepperdCase[4] = {};  // which quaternion component was largest
  for (const GlyphRecord& g : set.glyphs) {
    const std::size_t i = g.id;
    ASSERT_LT(i, n);
    const float* t = &ten[6 * i];
    const Eigensystem es = eigensolve({t[0], t[1], t[2], t[3], t[4], t[5]});
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(g.posWC[k], pos[3 * i + std::size_t(k)]);
      EXPECT_EQ(g.eigenvalues[k], float(es.values[k])) << i;
    }
    EXPECT_NEAR(g.fa, anisotropy(es.values).fa, 1e-6) << i;
    const glm::dquat ref = glm::normalize(glm::quat_cast(glm::dmat3(es.vectors[0], es.vectors[1], es.vectors[2])));
    const double r[4] = {ref.x, ref.y, ref.z, ref.w};
    // q and -q are the same rotation; the builder picks glm's sign.
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(g.frameWC[k], r[k], 2e-7) << i << " component " << k;
    int big = 0;
    for (int k = 1; k < 4; ++k)
      if (std::abs(r[k]) > std::abs(r[big])) big = k;
    ++shepperdCase[big];
  }
  for (int k = 0; k < 4; ++k) EXPECT_GT(shepperdCase[k], 0) << "case " << k << " never exercised";
}

TEST(GlyphRecords, ClampAndShapeFilterApplyPerLane) {
  const std::size_t n = 301;
  const std::vector<float> ten = sampleTensors(n);
  const std::vector<float> pos(3 * n, 0.0f);
  GlyphOptions opt;
  opt.clMin = 0.2;
  opt.minEigenvalue = 0.05;
  const GlyphSet set = buildGlyphs(pos, ten, {}, 1, opt);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const float* t = &ten[6 * i];
    if (anisotropy(eigensolve({t[0], t[1], t[2], t[3], t[4], t[5]}).values).cl >= 0.2) ++kept;
  }
  ASSERT_GT(kept, 0u);
  ASSERT_LT(kept, n);
  EXPECT_EQ(set.glyphs.size(), kept);
  EXPECT_EQ(set.droppedByShape, n - kept);
  for (const GlyphRecord& g : set.glyphs) {
    const float* t = &ten[6 * g.id];
    const Eigensystem es = eigensolve({t[0], t[1], t[2], t[3], t[4], t[5]});
    for (int k = 0; k < 3; ++k) EXPECT_EQ(g.eigenvalues[k], float(std::max(es.values[k], 0.05)));
  }
}

// Kindlmann's dt-helix has one MD (0.5) everywhere, stored in floats: rotated
// tensors' traces differ by rounding alone. --color md mapped that spread
// (about 1e-7) onto viridis, so glyphs of one MD came out yellow and purple.
TEST(GlyphRecords, AnMdSpreadBelowSinglePrecisionIsOneMd) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g;
  const std::size_t n = 2000;
  auto rotated = [&](glm::dvec3 lambda) {
    std::vector<float> ten;
    for (std::size_t i = 0; i < n; ++i) {
      const glm::dmat3 r = glm::mat3_cast(glm::normalize(glm::dquat(g(rng), g(rng), g(rng), g(rng))));
      const glm::dmat3 d = r * glm::dmat3(lambda.x, 0, 0, 0, lambda.y, 0, 0, 0, lambda.z) * glm::transpose(r);
      ten.insert(ten.end(), {float(d[0][0]), float(d[0][1]), float(d[0][2]), float(d[1][1]), float(d[1][2]),
                             float(d[2][2])});
    }
    return ten;
  };
  const std::vector<float> pos(3 * n, 0.0f);
  for (const glm::dvec3 lambda : {glm::dvec3(0.9, 0.4, 0.2), glm::dvec3(300, 0, -300)}) {
    const GlyphSet set = buildGlyphs(pos, rotated(lambda), {}, 1);
    EXPECT_EQ(float(set.mdMin), float(set.mdMax)) << set.mdMin << " " << set.mdMax;
    EXPECT_NEAR(set.mdMin, (lambda.x + lambda.y + lambda.z) / 3, 1e-6 * lambda.x);
  }
  // A real spread, however small against the mean, is kept.
  std::vector<float> ten = rotated(glm::dvec3(0.9, 0.4, 0.2));
  for (std::size_t i = 0; i < n; i += 2)
    for (int c : {0, 3, 5}) ten[6 * i + std::size_t(c)] *= 1.0001f;
  const GlyphSet varied = buildGlyphs(pos, ten, {}, 1);
  EXPECT_GT(varied.mdMax - varied.mdMin, 4e-5);
}

// Slicer's estimated helix is 95% zero tensors (background), which draw
// nothing; --color md spread the drawn glyphs over [0, max], half the bar.
TEST(GlyphRecords, MdRangeLeavesOutZeroTensors) {
  std::vector<float> ten, pos;
  for (int i = 0; i < 13; ++i) {
    const float s = i % 3 == 0 ? 1.0f : i % 3 == 1 ? 2.0f : 0.0f;
    ten.insert(ten.end(), {3 * s, 0, 0, 2 * s, 0, s});
    pos.insert(pos.end(), {float(i), 0, 0});
  }
  const GlyphSet set = buildGlyphs(pos, ten, {}, 1);
  EXPECT_DOUBLE_EQ(set.mdMin, 2.0);
  EXPECT_DOUBLE_EQ(set.mdMax, 4.0);
  EXPECT_EQ(set.glyphs.size(), 13u);  // the zero tensors are still records (they are counted as drawn)
}
