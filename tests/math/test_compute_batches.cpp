// Tier 2 (GL-free): the compute path's batch bounds (render/compute_glyphs.h),
// which its per-frame cull trusts to hold every glyph of a batch.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "render/compute_glyphs.h"

using namespace tg;

TEST(ComputeBatches, BoundsHoldEveryRecordOfTheirBatch) {
  const std::size_t n = 2 * render::kBatchRecords + 5;
  std::vector<tensor::GlyphRecord> records(n);
  for (std::size_t i = 0; i < n; ++i) {
    tensor::GlyphRecord& g = records[i];
    g.posWC[0] = float(i % 97) - 40.0f;
    g.posWC[1] = float(i % 31) * 0.5f;
    g.posWC[2] = -float(i) * 1e-3f;
    g.fa = float(i % 13) / 13.0f;
    g.eigenvalues[0] = 1.0f + float(i % 7);
    g.eigenvalues[1] = 0.0f;
    g.eigenvalues[2] = -2.0f - float(i % 11);  // indefinite: the last has the largest magnitude
  }
  records[3].fa = std::numeric_limits<float>::quiet_NaN();
  const auto bounds = render::batchBoundsOf(records);
  ASSERT_EQ(bounds.size(), 3u);
  for (std::size_t i = 0; i < n; ++i) {
    const render::BatchBounds& b = bounds[i / render::kBatchRecords];
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(b.loWC[k], records[i].posWC[k]);
      EXPECT_GE(b.hiWC[k], records[i].posWC[k]);
    }
    EXPECT_GE(b.maxAbsEigenvalue, std::abs(records[i].eigenvalues[0]));
    EXPECT_GE(b.maxAbsEigenvalue, std::abs(records[i].eigenvalues[2]));
    if (!std::isnan(records[i].fa)) {
      EXPECT_GE(b.maxFA, records[i].fa);
    }
  }
  // Tight: the extremes are attained.
  EXPECT_EQ(bounds[0].maxAbsEigenvalue, 12.0f);
  EXPECT_EQ(bounds[0].loWC[0], -40.0f);
  EXPECT_EQ(bounds[0].hiWC[0], 56.0f);
  EXPECT_FLOAT_EQ(bounds[0].maxFA, 12.0f / 13.0f);
  // The last batch: 5 records, centres 0..-0.004 past 2 batches.
  EXPECT_FLOAT_EQ(bounds[2].hiWC[2], -float(2 * render::kBatchRecords) * 1e-3f);
}

TEST(ComputeBatches, ABatchWithNoNumberForFAIsNeverSelected) {
  std::vector<tensor::GlyphRecord> records(4);
  for (auto& g : records) {
    g = {};
    g.fa = std::numeric_limits<float>::quiet_NaN();
  }
  const auto bounds = render::batchBoundsOf(records);
  ASSERT_EQ(bounds.size(), 1u);
  // -1 fails every threshold lib/selection.glsl accepts ([0, ...]), as NaN does there.
  EXPECT_EQ(bounds[0].maxFA, -1.0f);
  EXPECT_TRUE(render::batchBoundsOf({}).empty());
}
