// Tier 1: the GL-free halves of culling: frustum planes and glyph ranges.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "view/frustum.h"
#include "render/glyph_ranges.h"

using namespace tg;

namespace {

double signedPlane(const glm::dvec4& p, const glm::dvec3& x) { return p.x * x.x + p.y * x.y + p.z * x.z + p.w; }

bool inside(const render::FrustumWC& f, const glm::dvec3& x) {
  return std::all_of(f.begin(), f.end(), [&](const glm::dvec4& p) { return signedPlane(p, x) >= -1e-9; });
}

}  // namespace

TEST(Frustum, PlanesBoundWhatThePixelsSee) {
  for (auto proj : {render::Projection::Perspective, render::Projection::Orthographic}) {
    render::CameraDesc d;
    d.eyeWC = {3, -4, 2};
    d.lookAtWC = {0.5, 0.2, -0.1};
    d.upWC = {0, 0, 1};
    d.projection = proj;
    d.fovYDeg = 35;
    d.orthoHeight = 2.5;
    const auto cam = render::makeCamera(d, 200, 120, glm::dvec3(-1), glm::dvec3(1));
    const auto f = render::frustumPlanesWC(cam);
    const double far = proj == render::Projection::Perspective ? 40.0 : cam.farVC;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < 500; ++k) {
      const double px = 200 * u(rng), py = 120 * u(rng);
      const double t = cam.nearVC + (far - cam.nearVC) * u(rng);
      const render::RayWC in = cam.rayThroughPixel(px, py);
      EXPECT_TRUE(inside(f, in.origin + t * in.direction)) << px << " " << py << " " << t;
      // Beyond an image edge, or before the near plane: outside.
      const render::RayWC left = cam.rayThroughPixel(-2.0 - 50 * u(rng), py);
      EXPECT_FALSE(inside(f, left.origin + t * left.direction));
      const render::RayWC below = cam.rayThroughPixel(px, 123.0 + 50 * u(rng));
      EXPECT_FALSE(inside(f, below.origin + t * below.direction));
      EXPECT_FALSE(inside(f, in.origin + 0.9 * cam.nearVC * in.direction));
    }
    // Boxes: around the look-at point (inside), behind the eye (outside).
    const glm::dvec3 c = d.lookAtWC, back = d.eyeWC + (d.eyeWC - d.lookAtWC);
    EXPECT_TRUE(render::boxInside(f, c - 0.1, c + 0.1));
    EXPECT_FALSE(render::boxOutside(f, c - 0.1, c + 0.1));
    EXPECT_TRUE(render::boxOutside(f, back - 0.1, back + 0.1));
    EXPECT_FALSE(render::boxInside(f, back - 0.1, back + 0.1));
    // Straddling a side plane: neither wholly in nor wholly out.
    const render::RayWC edge = cam.rayThroughPixel(0.0, 60.0);
    const glm::dvec3 e = edge.origin + 5.0 * edge.direction;
    EXPECT_FALSE(render::boxInside(f, e - 0.2, e + 0.2));
    EXPECT_FALSE(render::boxOutside(f, e - 0.2, e + 0.2));
  }
}

TEST(GlyphRanges, CoverEveryGlyphOnceByGroupAndTile) {
  // 700 glyphs: three tiles, the last partial; groups mixed within tiles.
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<float> pos, ten;
  for (int i = 0; i < 700; ++i) {
    const float shift = i % 3 == 0 ? 2.5f : 0.0f, iso = u(rng);
    const float t[6] = {shift + u(rng), u(rng), u(rng), shift + u(rng), u(rng), shift + u(rng)};
    const float s[6] = {iso, 0, 0, iso, 0, iso};
    ten.insert(ten.end(), i % 7 == 0 ? s : t, (i % 7 == 0 ? s : t) + 6);
    pos.insert(pos.end(), {float(i % 10), float(i / 10 % 10), float(i / 100)});
  }
  const auto set = tensor::buildGlyphs(pos, ten, {}, 1);
  const auto table = render::buildRanges(set);
  std::vector<int> seen(set.glyphs.size(), 0);
  float minFa = 1e30f;
  for (const auto& g : set.glyphs) minFa = std::min(minFa, g.fa);
  EXPECT_EQ(table.minFa, minFa);
  EXPECT_EQ(table.groupStart[0], 0u);
  EXPECT_EQ(table.groupStart[3], table.ranges.size());
  for (int g = 0; g < 3; ++g) {
    ASSERT_LT(table.groupStart[g], table.groupStart[g + 1]) << "every group occurs";
    std::uint32_t lastFirst = 0;
    for (std::uint32_t k = table.groupStart[g]; k < table.groupStart[g + 1]; ++k) {
      const auto& r = table.ranges[k];
      ASSERT_GT(r.count, 0u);
      ASSERT_LE(r.count, tensor::kTileGlyphs);
      EXPECT_EQ(r.first / tensor::kTileGlyphs, (r.first + r.count - 1) / tensor::kTileGlyphs) << "within one tile";
      if (k > table.groupStart[g]) {
        EXPECT_GT(r.first, lastFirst) << "tile order";
      }
      lastFirst = r.first;
      for (std::uint32_t i = r.first; i < r.first + r.count; ++i) {
        const auto& rec = set.glyphs[i];
        ++seen[i];
        EXPECT_EQ(int(tensor::glyphGroup(rec)), g);
        for (int c = 0; c < 3; ++c) {
          EXPECT_GE(rec.posWC[c], r.loWC[c]);
          EXPECT_LE(rec.posWC[c], r.hiWC[c]);
        }
        EXPECT_LE(std::abs(rec.eigenvalues[0]), r.maxAbsEigenvalue);
        EXPECT_LE(std::abs(rec.eigenvalues[2]), r.maxAbsEigenvalue);
      }
    }
  }
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));

  // Direct runs: exactly the glyphs of the groups asked for, merged.
  const auto all = render::groupRuns(set, 0, 3);
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0].count, set.glyphs.size());
  for (auto [g0, g1] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 3}, std::pair{2, 3}}) {
    std::vector<int> in(set.glyphs.size(), 0);
    for (const auto& r : render::groupRuns(set, g0, g1))
      for (std::uint32_t i = r.first; i < r.first + r.count; ++i) ++in[i];
    for (std::size_t i = 0; i < set.glyphs.size(); ++i) {
      const int g = int(tensor::glyphGroup(set.glyphs[i]));
      EXPECT_EQ(in[i], g >= g0 && g < g1 ? 1 : 0) << i;
    }
  }
}
