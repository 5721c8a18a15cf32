// Tier 2: the GPU-against-reference diff on hand-made images, so that the
// thresholds of the GL tests and the figures of `bench accuracy` rest on a
// checked measure.
#include <gtest/gtest.h>

#include <cmath>

#include "ref/image_diff.h"

using namespace tg;

namespace {

// A 12x12 frame pair: glyph 7 covers the block [2, 10) x [2, 10) in both, at
// depth 4 with normal +z, so interior pixels are [3, 9) x [3, 9).
struct Pair {
  render::FrameImage g;
  ref::RefImage r;
  render::Camera cam;
  static constexpr int kSize = 12;
  Pair() {
    const std::size_t n = kSize * kSize;
    g.width = r.width = kSize;
    g.height = r.height = kSize;
    g.rgba.assign(4 * n, 0.5f);
    g.depth.assign(n, INFINITY);
    g.normalWC.assign(3 * n, 0.0f);
    g.id.assign(n, ref::kNoGlyph);
    r.depth.assign(n, INFINITY);
    r.normalWC.assign(n, glm::dvec3(0.0));
    r.id.assign(n, ref::kNoGlyph);
    for (int j = 2; j < 10; ++j)
      for (int i = 2; i < 10; ++i) {
        set(i, j, 7, 4.0, glm::dvec3(0, 0, 1));
        r.id[at(i, j)] = 7;
        r.depth[at(i, j)] = 4.0;
        r.normalWC[at(i, j)] = glm::dvec3(0, 0, 1);
      }
    cam.width = cam.height = kSize;
  }
  static std::size_t at(int i, int j) { return std::size_t(j) * kSize + i; }
  void set(int i, int j, std::uint32_t id, double depth, glm::dvec3 n) {
    g.id[at(i, j)] = id;
    g.depth[at(i, j)] = float(depth);
    for (int k = 0; k < 3; ++k) g.normalWC[3 * at(i, j) + k] = float(n[k]);
  }
};

}  // namespace

TEST(ImageDiff, IdenticalImagesDifferNowhere) {
  const Pair p;
  const auto d = ref::diffImages(p.g, p.r, p.cam);
  EXPECT_EQ(d.refCovered, 64u);
  EXPECT_EQ(d.gpuCovered, 64u);
  EXPECT_EQ(d.coverageMismatch + d.interiorMismatch + d.idMismatch + d.nonFinite, 0u);
  EXPECT_EQ(d.depth.count, 36u);  // interior only by default
  EXPECT_EQ(d.depth.max, 0.0);
  EXPECT_EQ(d.normalDeg.max, 0.0);
}

TEST(ImageDiff, CoverageIsSplitIntoSilhouetteAndInterior) {
  Pair p;
  p.g.id[Pair::at(5, 5)] = ref::kNoGlyph;  // a hole inside
  p.g.id[Pair::at(2, 2)] = ref::kNoGlyph;  // a corner lost
  p.set(1, 5, 7, 4.0, {0, 0, 1});          // one pixel too many outside
  const auto d = ref::diffImages(p.g, p.r, p.cam);
  EXPECT_EQ(d.coverageMismatch, 3u);
  EXPECT_EQ(d.interiorMismatch, 1u);
}

TEST(ImageDiff, OtherGlyphsCountUnlessTheyTie) {
  Pair p;
  p.set(4, 4, 9, 3.0, {0, 0, 1});        // another glyph in front: an error
  p.set(6, 6, 9, 4.0 + 1e-7, {1, 0, 0});  // another glyph at the same depth: a tie
  p.set(2, 5, 9, 3.0, {0, 0, 1});        // on the silhouette: not counted
  const auto d = ref::diffImages(p.g, p.r, p.cam);
  EXPECT_EQ(d.idMismatch, 1u);
  EXPECT_EQ(d.coverageMismatch, 0u);
}

TEST(ImageDiff, DepthAndNormalErrorsAreSummarised) {
  Pair p;
  p.set(4, 4, 7, 4.4, glm::normalize(glm::dvec3(1, 0, 1)));  // 10% deeper, 45 degrees off
  p.set(5, 4, 7, 4.04, {0, 0, 1});                           // 1% deeper
  auto d = ref::diffImages(p.g, p.r, p.cam);
  EXPECT_NEAR(d.depth.max, 0.1, 1e-6);  // relative to the reference depth
  EXPECT_NEAR(d.depth.p99, 0.1, 1e-6);  // nearest rank: of 36 samples, the 36th
  EXPECT_EQ(d.depth.median, 0.0);
  EXPECT_NEAR(d.normalDeg.max, 45.0, 1e-3);
  ref::DiffOptions opt;
  opt.depthUnit = [](std::uint32_t id, double) { return id == 7 ? 0.2 : 1.0; };  // in glyph sizes
  opt.includeSilhouettes = true;
  d = ref::diffImages(p.g, p.r, p.cam, opt);
  EXPECT_NEAR(d.depth.max, 2.0, 1e-5);
  EXPECT_EQ(d.depth.count, 64u);
}

TEST(ImageDiff, NonFiniteGpuValuesAreCounted) {
  Pair p;
  p.g.normalWC[3 * Pair::at(4, 4)] = NAN;
  p.g.rgba[0] = INFINITY;
  EXPECT_EQ(ref::diffImages(p.g, p.r, p.cam).nonFinite, 2u);
}

TEST(ImageDiff, MismatchedSizesAreRejected) {
  Pair p;
  p.g.depth.pop_back();
  EXPECT_THROW(ref::diffImages(p.g, p.r, p.cam), std::invalid_argument);
}
