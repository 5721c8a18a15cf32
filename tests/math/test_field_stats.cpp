// FieldStats: the whole field's statistics are the same however the field is
// split (threads, MPI ranks): combine() of the pieces equals the whole, the
// magnitude sketch included; a small field's sketch is every magnitude.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "data-synthetic/generators.h"
#include "tensor/field_stats.h"
#include "tensor/glyph.h"
#include "tensor/glyph_scale.h"

namespace {

using tg::tensor::FieldStats;

void expectSame(const FieldStats& a, const FieldStats& b) {
  EXPECT_EQ(a.tensors, b.tensors);
  EXPECT_EQ(a.nonZero, b.nonZero);
  EXPECT_EQ(a.indefinite, b.indefinite);
  EXPECT_EQ(a.notPositive, b.notPositive);
  EXPECT_EQ(a.maxAbs, b.maxAbs);
  EXPECT_EQ(a.principalMin, b.principalMin);
  EXPECT_EQ(a.principalMax, b.principalMax);
  EXPECT_EQ(a.vonMisesMin, b.vonMisesMin);
  EXPECT_EQ(a.vonMisesMax, b.vonMisesMax);
  EXPECT_EQ(a.sortedMagnitudes(), b.sortedMagnitudes());
}

FieldStats ofRange(const tg::tensor::GlyphSet& set, std::size_t lo, std::size_t hi) {
  FieldStats s;
  for (std::size_t i = lo; i < hi; ++i) s.add(set.glyphs[i]);
  return s;
}

}  // namespace

TEST(FieldStats, PiecesCombineToTheWhole) {
  // 200,000 tensors: past the sketch's 65,536, so that it samples.
  const tg::io::TensorField f = tg::synth::randomField(200000, 7);
  const auto set = tg::tensor::buildGlyphs(f.positions, f.tensors, f.ids, 1);
  const std::size_t n = set.glyphs.size();
  const FieldStats whole = ofRange(set, 0, n);
  EXPECT_EQ(whole.sortedMagnitudes().size(), FieldStats::kSampleMax);
  for (int pieces : {2, 3, 4, 7}) {
    SCOPED_TRACE(pieces);
    // Interleaved pieces, combined in reverse: neither order nor split matters.
    std::vector<FieldStats> part(pieces);
    for (std::size_t i = 0; i < n; ++i) part[i % pieces].add(set.glyphs[i]);
    FieldStats merged;
    for (int k = pieces - 1; k >= 0; --k) merged.combine(part[k]);
    expectSame(merged, whole);
  }
  // The sketch is a fair sample: its median is the field's within a percent.
  std::vector<double> all;
  for (const auto& g : set.glyphs) all.push_back(std::max(std::abs(g.eigenvalues[0]), std::abs(g.eigenvalues[2])));
  std::sort(all.begin(), all.end());
  const auto sketch = whole.sortedMagnitudes();
  EXPECT_NEAR(sketch[sketch.size() / 2], all[all.size() / 2], 0.01 * all[all.size() / 2]);
}

TEST(FieldStats, ASmallFieldKeepsEveryMagnitudeAndItsStressRanges) {
  const tg::io::TensorField f = tg::synth::kirschPlate(40);
  const auto set = tg::tensor::buildGlyphs(f.positions, f.tensors, f.ids, 1);
  const FieldStats s = ofRange(set, 0, set.glyphs.size());
  EXPECT_EQ(tg::tensor::fieldStats(set).maxAbs, set.maxAbsEigenvalue);
  std::size_t nonZero = 0;
  for (const auto& g : set.glyphs) nonZero += g.eigenvalues[0] != 0.0f || g.eigenvalues[2] != 0.0f;
  EXPECT_EQ(s.nonZero, nonZero);
  EXPECT_LT(s.nonZero, s.tensors);  // the hole's zero tensors
  EXPECT_EQ(s.sortedMagnitudes().size(), nonZero);
  FieldStats halves = ofRange(set, 0, set.glyphs.size() / 3);
  halves.combine(ofRange(set, set.glyphs.size() / 3, set.glyphs.size()));
  expectSame(halves, s);
  EXPECT_TRUE(s.mostlyNotPositive());  // plane stress: a zero principal value everywhere
  EXPECT_LE(s.principalMax[0], 300.0 + 1e-3);
  EXPECT_GE(s.principalMin[2], -100.0 - 1e-3);
  EXPECT_GT(s.vonMisesMax, 200.0);
}

TEST(FieldStats, KirschMatchesTheAnalyticExtremes) {
  double s[6];
  tg::synth::kirschStress(0.0, 1.0, s);  // beside the hole, across the load
  EXPECT_NEAR(s[0], 300.0, 1e-9);
  EXPECT_NEAR(s[3], 0.0, 1e-9);
  tg::synth::kirschStress(1.0, 0.0, s);  // on the load axis
  EXPECT_NEAR(s[3], -100.0, 1e-9);
  EXPECT_NEAR(s[0], 0.0, 1e-9);
  tg::synth::kirschStress(1e4, 3e3, s);  // far away: the applied stress
  EXPECT_NEAR(s[0], 100.0, 1e-3);
  EXPECT_NEAR(s[1], 0.0, 1e-3);
  EXPECT_NEAR(s[3], 0.0, 1e-3);
}
