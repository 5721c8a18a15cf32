#include "tensor/field_stats.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace tg::tensor {
namespace {

// splitmix64's finaliser: a fixed mix, the same on every rank and build.
std::uint64_t mix(std::uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

std::uint64_t hashOf(const GlyphRecord& g) {
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for (float v : {g.posWC[0], g.posWC[1], g.posWC[2], g.eigenvalues[0], g.eigenvalues[1], g.eigenvalues[2]})
    h = mix(h ^ std::bit_cast<std::uint32_t>(v));
  return h;
}

}  // namespace

void FieldStats::add(const GlyphRecord& g) {
  ++tensors;
  const double l[3] = {g.eigenvalues[0], g.eigenvalues[1], g.eigenvalues[2]};
  const double m = std::max(std::abs(l[0]), std::abs(l[2]));
  if (!(m > 0.0)) return;
  ++nonZero;
  indefinite += l[0] > 0.0 && l[2] < 0.0;
  negativeDefinite += l[0] < 0.0;
  notPositive += l[2] <= 0.0;
  maxAbs = std::max(maxAbs, m);
  for (int k = 0; k < 3; ++k) {
    principalMin[k] = std::min(principalMin[k], l[k]);
    principalMax[k] = std::max(principalMax[k], l[k]);
  }
  const double vm = std::sqrt(0.5 * ((l[0] - l[1]) * (l[0] - l[1]) + (l[1] - l[2]) * (l[1] - l[2]) +
                                     (l[2] - l[0]) * (l[2] - l[0])));
  vonMisesMin = std::min(vonMisesMin, vm);
  vonMisesMax = std::max(vonMisesMax, vm);
  const Entry e{hashOf(g), float(m)};
  if (e.hash > threshold_) return;
  sample.push_back(e);
  if (sample.size() >= 2 * kSampleMax) compact();
}

void FieldStats::compact() {
  if (sample.size() <= kSampleMax) return;
  std::nth_element(sample.begin(), sample.begin() + kSampleMax - 1, sample.end());
  sample.resize(kSampleMax);
  threshold_ = std::max_element(sample.begin(), sample.end())->hash;
}

void FieldStats::combine(const FieldStats& o) {
  tensors += o.tensors;
  nonZero += o.nonZero;
  indefinite += o.indefinite;
  negativeDefinite += o.negativeDefinite;
  notPositive += o.notPositive;
  maxAbs = std::max(maxAbs, o.maxAbs);
  for (int k = 0; k < 3; ++k) {
    principalMin[k] = std::min(principalMin[k], o.principalMin[k]);
    principalMax[k] = std::max(principalMax[k], o.principalMax[k]);
  }
  vonMisesMin = std::min(vonMisesMin, o.vonMisesMin);
  vonMisesMax = std::max(vonMisesMax, o.vonMisesMax);
  for (const Entry& e : o.sample)
    if (e.hash <= threshold_) sample.push_back(e);
  compact();
  // Both sketches hold the smallest hashes of their parts, so the smallest
  // kSampleMax of their union are the whole's.
  if (sample.size() >= kSampleMax) threshold_ = std::max_element(sample.begin(), sample.end())->hash;
}

std::vector<double> FieldStats::sortedMagnitudes() const {
  std::vector<Entry> kept = sample;
  if (kept.size() > kSampleMax) {
    std::nth_element(kept.begin(), kept.begin() + kSampleMax - 1, kept.end());
    kept.resize(kSampleMax);
  }
  std::vector<double> m;
  m.reserve(kept.size());
  for (const Entry& e : kept) m.push_back(e.magnitude);
  std::sort(m.begin(), m.end());
  return m;
}

FieldStats fieldStats(const GlyphSet& set) {
  FieldStats s;
  for (const GlyphRecord& g : set.glyphs) s.add(g);
  // The set's own maximum is of the eigenvalues before single-precision
  // rounding: what the glyph box and the max mode always used.
  if (!set.glyphs.empty()) s.maxAbs = set.maxAbsEigenvalue;
  return s;
}

}  // namespace tg::tensor
