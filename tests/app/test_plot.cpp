// Tier 2: benchmark plots (io/core/plot_panels.h, drawn as the OpenImageIO
// module draws them, io/modules/oiio/plot_draw.cpp): a point's label, its
// spread bar and the default's mark each put ink where they belong, beside
// that point and nowhere near the others.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "io/core/plot_panels.h"

using tg::io::PlotPanel;
using tg::io::PlotSeries;

namespace {

constexpr int kW = 640, kH = 480;

std::vector<float> draw(const PlotSeries& s, bool* labelled = nullptr) {
  const PlotPanel p{"t", "x", "y", false, {s}};
  std::vector<float> rgb;
  const bool l = tg::io::drawPlot({p}, kW, kH, rgb);
  if (labelled) *labelled = l;
  return rgb;
}

// Pixels that differ between a and b, with the bounding box of those changes.
struct Change {
  std::size_t count = 0;
  int x0 = kW, y0 = kH, x1 = -1, y1 = -1;
};
Change changed(const std::vector<float>& a, const std::vector<float>& b) {
  Change c;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const std::size_t i = 3 * (std::size_t(y) * kW + std::size_t(x));
      if (a[i] == b[i] && a[i + 1] == b[i + 1] && a[i + 2] == b[i + 2]) continue;
      ++c.count;
      c.x0 = std::min(c.x0, x), c.y0 = std::min(c.y0, y), c.x1 = std::max(c.x1, x), c.y1 = std::max(c.y1, y);
    }
  return c;
}

}  // namespace

TEST(Plot, LabelsSpreadsAndTheMarkDrawBesideTheirPoint) {
  // Three points on a straight line; the middle one gets each addition.
  PlotSeries bare{"s", {0.2f, 0.3f, 0.85f}, {{1, 1}, {2, 2}, {3, 3}}, {}, {}, -1, ""};
  bool fonts = false;
  const std::vector<float> plain = draw(bare, &fonts);
  // The plot area (io/modules/oiio/plot_draw.cpp: 78 px left, 150 right, 36 top, 56
  // below) spans x 1..3 padded by 5%, y 1..3 exactly.
  const double px = 78 + (2 - 0.9) / 2.2 * (kW - 78 - 150), py = kH - 56 - 0.5 * (kH - 56 - 36);

  PlotSeries spread = bare;
  spread.xSpread = {{1, 1}, {1.5, 2.5}, {3, 3}};
  const Change bar = changed(plain, draw(spread));
  ASSERT_GT(bar.count, 0u) << "the spread drew nothing";
  // A horizontal bar through the point, half an x unit each side.
  const double halfUnit = 0.5 / 2.2 * (kW - 78 - 150);
  EXPECT_NEAR(bar.x0, px - halfUnit, 2);
  EXPECT_NEAR(bar.x1, px + halfUnit, 2);
  EXPECT_LE(bar.y1 - bar.y0, 8);
  EXPECT_NEAR(0.5 * (bar.y0 + bar.y1), py, 2);

  PlotSeries marked = bare;
  marked.marked = 1;
  const Change box = changed(plain, draw(marked));
  ASSERT_GT(box.count, 0u) << "the mark drew nothing";
  EXPECT_NEAR(box.x0, px - 6, 2);
  EXPECT_NEAR(box.y0, py - 6, 2);

  if (!fonts) GTEST_SKIP() << "no font: the labels cannot be drawn";
  PlotSeries labelled = bare;
  labelled.pointLabels = {"", "42", ""};
  const Change text = changed(plain, draw(labelled));
  ASSERT_GT(text.count, 0u) << "the label drew nothing";
  // Above and to the right of its point, well short of the next one.
  EXPECT_GE(text.x0, px);
  EXPECT_LT(text.x1, px + 40);
  EXPECT_LE(text.y1, py);
  EXPECT_GT(text.y0, py - 30);
  marked.markLabel = "default";
  const Change word = changed(draw(marked), [&] {
    PlotSeries m = marked;
    m.markLabel.clear();
    return draw(m);
  }());
  EXPECT_GT(word.count, 0u) << "the mark's label drew nothing";
  EXPECT_GE(word.x0, px + 6);
}
