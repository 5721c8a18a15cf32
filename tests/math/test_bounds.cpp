// Tier 1: Sigg et al.'s bounding rectangle (eq. 5) against the exact CPU ray
// caster: every covered pixel lies inside it, and it is tight.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <random>

#include <glm/geometric.hpp>

#include "ref/ellipsoid_ref.h"
#include "ref/pixel_loop.h"
#include "view/camera.h"
#include "tensor/glyph.h"

using namespace tg;

namespace {

struct Case {
  tensor::GlyphSet set;
  render::Camera cam;
};

// One random glyph (eigenvalue ratios up to 1e6, random orientation) and a
// random camera at a random distance (from inside the glyph to far away).
Case randomCase(std::mt19937_64& rng, int size, double decades = 6.0) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double r1 = 1.0, r2 = std::pow(10.0, -decades * u(rng)), r3 = r2 * std::pow(10.0, -0.5 * decades * u(rng));
  const double a = 6.28 * u(rng), b = 6.28 * u(rng);
  const glm::dvec3 e1(std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b));
  glm::dvec3 e2 = glm::normalize(glm::cross(e1, glm::dvec3(0.3, 0.5, 0.8)));
  const glm::dvec3 e3 = glm::cross(e1, e2);
  auto m = [&](int i, int j) { return r1 * e1[i] * e1[j] + r2 * e2[i] * e2[j] + std::max(r3, 1e-7) * e3[i] * e3[j]; };
  const float pos[3] = {float(u(rng) - 0.5), float(u(rng) - 0.5), float(u(rng) - 0.5)};
  const float ten[6] = {float(m(0, 0)), float(m(0, 1)), float(m(0, 2)), float(m(1, 1)), float(m(1, 2)), float(m(2, 2))};
  Case c;
  c.set = tensor::buildGlyphs(std::span(pos, 3), std::span(ten, 6), {}, 1);
  render::CameraDesc d;
  const double dist = std::pow(10.0, -0.5 + 2.0 * u(rng));
  const double th = 6.28 * u(rng), ph = 0.2 + 2.7 * u(rng);
  const glm::dvec3 centre(pos[0], pos[1], pos[2]);
  d.lookAtWC = centre + 0.3 * glm::dvec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
  d.eyeWC = centre + dist * glm::dvec3(std::cos(th) * std::sin(ph), std::sin(th) * std::sin(ph), std::cos(ph));
  d.upWC = {0, 0, 1};
  d.projection = u(rng) < 0.25 ? render::Projection::Orthographic : render::Projection::Perspective;
  d.fovYDeg = 20.0 + 60.0 * u(rng);
  d.orthoHeight = 0.5 + 3.0 * u(rng);
  c.cam = render::makeCamera(d, size, size, centre - 1.0, centre + 1.0);
  return c;
}

}  // namespace

TEST(Bounds, RectangleContainsEveryCoveredPixel) {
  std::mt19937_64 rng(11);
  const int size = 96;
  int withPixels = 0, full = 0;
  for (int k = 0; k < 300; ++k) {
    const Case c = randomCase(rng, size);
    const auto img = ref::renderEllipsoids(c.cam, c.set.glyphs, {1.0, 0.0});
    const ref::RectNDC r = ref::ellipsoidRectNDC(c.cam, c.set.glyphs[0], 1.0);
    full += r.full;
    bool any = false;
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        if (img.id[std::size_t(j) * size + i] == ref::kNoGlyph) continue;
        any = true;
        const double x = 2.0 * (i + 0.5) / size - 1.0, y = 1.0 - 2.0 * (j + 0.5) / size;
        // 1e-9 NDC: far below a pixel; only rounding of the closed form.
        ASSERT_GE(x, r.xmin - 1e-9) << "case " << k;
        ASSERT_LE(x, r.xmax + 1e-9) << "case " << k;
        ASSERT_GE(y, r.ymin - 1e-9) << "case " << k;
        ASSERT_LE(y, r.ymax + 1e-9) << "case " << k;
      }
    withPixels += any;
  }
  EXPECT_GT(withPixels, 150);  // the sample really exercises visible glyphs
  EXPECT_GT(full, 0);          // and cameras inside or beside glyphs
}

TEST(Bounds, RectangleIsTight) {
  std::mt19937_64 rng(5);
  const int size = 128;
  int checked = 0;
  for (int k = 0; k < 200 && checked < 40; ++k) {
    // Fat glyphs only: a needle 1e-6 wide covers pixel centres only where it
    // happens to pass through one, so its pixels need not reach the edges.
    const Case c = randomCase(rng, size, 0.7);
    const ref::RectNDC r = ref::ellipsoidRectNDC(c.cam, c.set.glyphs[0], 1.0);
    if (r.full || r.xmin < -1 || r.xmax > 1 || r.ymin < -1 || r.ymax > 1) continue;
    if ((r.xmax - r.xmin) * size < 8 || (r.ymax - r.ymin) * size < 8) continue;
    const auto img = ref::renderEllipsoids(c.cam, c.set.glyphs, {1.0, 0.0});
    double xmin = 9, xmax = -9, ymin = 9, ymax = -9;
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i)
        if (img.id[std::size_t(j) * size + i] != ref::kNoGlyph) {
          const double x = 2.0 * (i + 0.5) / size - 1.0, y = 1.0 - 2.0 * (j + 0.5) / size;
          xmin = std::min(xmin, x), xmax = std::max(xmax, x), ymin = std::min(ymin, y), ymax = std::max(ymax, y);
        }
    if (xmax < xmin) continue;
    // Covered pixel centres reach to within one pixel (2/size NDC) of each
    // edge; thin glyphs seen edge-on may miss a centre, hence 1.5 pixels.
    const double px = 3.0 / size;
    EXPECT_LT(xmin - r.xmin, px) << "case " << k;
    EXPECT_LT(r.xmax - xmax, px) << "case " << k;
    EXPECT_LT(ymin - r.ymin, px) << "case " << k;
    EXPECT_LT(r.ymax - ymax, px) << "case " << k;
    ++checked;
  }
  EXPECT_GE(checked, 20);
}

// The reference bins glyphs to screen tiles; a tile must list every glyph
// whose bounding sphere some pixel ray of the tile meets beyond the near
// plane, or the oracle would lose glyphs. Random spheres and cameras, eyes
// inside spheres included.
TEST(Bounds, ReferenceTilesListEveryReachableGlyph) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int size = 70;  // not a multiple of the tile size: partial tiles too
  int reached = 0;
  for (int k = 0; k < 60; ++k) {
    const Case c = randomCase(rng, size);
    std::vector<ref::detail::Prepared> prep(40);
    for (auto& q : prep) {
      q.centre = glm::dvec3(u(rng), u(rng), u(rng)) * 3.0 - 1.5;
      q.radius = std::pow(10.0, -2.5 + 2.5 * u(rng));
    }
    const auto tiles = ref::detail::binGlyphs(c.cam, prep);
    const int tilesX = (size + ref::detail::kTile - 1) / ref::detail::kTile;
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const auto ray = c.cam.rayThroughPixel(i + 0.5, j + 0.5);
        const auto& list = tiles[std::size_t(j / ref::detail::kTile) * tilesX + i / ref::detail::kTile];
        for (std::uint32_t g = 0; g < prep.size(); ++g) {
          double t0, t1;
          const glm::dvec3 o = (ray.origin - prep[g].centre) / prep[g].radius;
          if (!ref::detail::unitSphereRoots(o, ray.direction / prep[g].radius, t0, t1) || t1 < c.cam.nearVC) continue;
          ++reached;
          ASSERT_TRUE(std::find(list.begin(), list.end(), g) != list.end()) << "case " << k << " pixel " << i << "," << j;
        }
      }
  }
  EXPECT_GT(reached, 10000);
}
