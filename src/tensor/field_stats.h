#pragma once
// What a whole field's sizes and stress measures are worked out from, kept
// apart from any selection: the scale's percentiles, the magnitude mapping's
// knee and the clamp's share come from these, so that one tensor is drawn at
// one size on every slice, ROI or stride of its field.
//
// Mergeable: combine() of the statistics of the pieces of a field (threads,
// MPI ranks) gives exactly the statistics of the whole, whatever the split,
// so a picture sized from them does not depend on the number of ranks. The
// counts add, the ranges take min/max, and the magnitudes are a bottom-k
// sketch: the kSampleMax non-zero magnitudes whose hash (of the glyph's
// position and eigenvalue bits, not of its index or rank) is smallest. A field
// of at most kSampleMax non-zero tensors keeps them all (exact percentiles);
// a larger one keeps a uniform sample that no split changes.
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "tensor/glyph.h"

namespace tg::tensor {

struct FieldStats {
  static constexpr std::size_t kSampleMax = 65536;
  struct Entry {
    std::uint64_t hash = 0;
    float magnitude = 0;  // max |eigenvalue|
    bool operator<(const Entry& o) const { return hash != o.hash ? hash < o.hash : magnitude < o.magnitude; }
  };
  std::uint64_t tensors = 0;           // every glyph added, zero ones included
  std::uint64_t nonZero = 0;           // with a size
  std::uint64_t indefinite = 0;        // eigenvalues of both signs (tension and compression)
  std::uint64_t negativeDefinite = 0;  // every eigenvalue negative
  std::uint64_t notPositive = 0;       // the least eigenvalue <= 0: not positive definite
  double maxAbs = 0;                   // the largest |eigenvalue|
  // Of the non-zero tensors: each principal value (descending) and von Mises
  // sqrt(((s1-s2)^2 + (s2-s3)^2 + (s3-s1)^2) / 2); +inf..-inf when none.
  std::array<double, 3> principalMin{kInf, kInf, kInf}, principalMax{-kInf, -kInf, -kInf};
  double vonMisesMin = kInf, vonMisesMax = -kInf;
  std::vector<Entry> sample;  // the sketch, unordered; at most kSampleMax once compacted

  void add(const GlyphRecord& g);
  void combine(const FieldStats& o);
  // The sketch's magnitudes, sorted ascending (all non-zero).
  std::vector<double> sortedMagnitudes() const;
  // More than half of the non-zero tensors are not positive definite, as a
  // diffusion tensor is: compression, tension with compression, or a zero
  // principal value (plane stress).
  bool mostlyNotPositive() const { return nonZero > 0 && 2 * notPositive > nonZero; }

 private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  void compact();
  std::uint64_t threshold_ = std::numeric_limits<std::uint64_t>::max();  // entries above it cannot be kept
};

// The statistics of every glyph of the set.
FieldStats fieldStats(const GlyphSet& set);

}  // namespace tg::tensor
