#include "tensor/fibre_coherence.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "tensor/eigen.h"

namespace tg::tensor {

double fractionalAnisotropy(const float t[6]) {
  const double xx = t[0], xy = t[1], xz = t[2], yy = t[3], yz = t[4], zz = t[5];
  const double norm2 = xx * xx + yy * yy + zz * zz + 2 * (xy * xy + xz * xz + yz * yz);
  if (!(norm2 > 0)) return 0;
  const double tr = xx + yy + zz;
  return std::sqrt(std::max(0.0, 1.5 * (norm2 - tr * tr / 3) / norm2));
}

double otsuThreshold(std::span<const double> values) {
  constexpr int kBins = 64;
  if (values.empty()) return 0;
  double hist[kBins] = {};
  for (double v : values) hist[std::clamp(int(v * kBins), 0, kBins - 1)] += 1;
  const double total = double(values.size());
  double sumAll = 0;
  for (int b = 0; b < kBins; ++b) sumAll += (b + 0.5) * hist[b];
  double w0 = 0, sum0 = 0, best = -1;
  int cut = 0;
  for (int b = 0; b < kBins - 1; ++b) {
    w0 += hist[b];
    sum0 += (b + 0.5) * hist[b];
    const double w1 = total - w0;
    if (w0 == 0 || w1 == 0) continue;
    const double d = sum0 / w0 - (sumAll - sum0) / w1;
    const double between = w0 * w1 * d * d;
    if (between > best) best = between, cut = b + 1;
  }
  return double(cut) / kBins;
}

namespace {

constexpr std::uint32_t kNoSample = std::numeric_limits<std::uint32_t>::max();

struct V {
  double x, y, z;
};
double dot(const V& a, const V& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V times(const Mat3& m, const V& v) {
  return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[3] * v.x + m[4] * v.y + m[5] * v.z,
          m[6] * v.x + m[7] * v.y + m[8] * v.z};
}
std::optional<Mat3> inverse(const Mat3& a) {
  const double det = a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
                     a[2] * (a[3] * a[7] - a[4] * a[6]);
  if (!(std::abs(det) > 0) || !std::isfinite(det)) return std::nullopt;
  const double k = 1 / det;
  return Mat3{k * (a[4] * a[8] - a[5] * a[7]), k * (a[2] * a[7] - a[1] * a[8]), k * (a[1] * a[5] - a[2] * a[4]),
              k * (a[5] * a[6] - a[3] * a[8]), k * (a[0] * a[8] - a[2] * a[6]), k * (a[2] * a[3] - a[0] * a[5]),
              k * (a[3] * a[7] - a[4] * a[6]), k * (a[1] * a[6] - a[0] * a[7]), k * (a[0] * a[4] - a[1] * a[3])};
}

// A fibre voxel's principal axis, exact.
V principalAxis(const float t[6]) {
  const Eigensystem e = eigensolve({t[0], t[1], t[2], t[3], t[4], t[5]});
  return {e.vectors[0].x, e.vectors[0].y, e.vectors[0].z};
}

// A neighbour's principal axis by power iteration from its voxel's: an
// aligned neighbour is already near it, and a misaligned one moves away by
// (l2/l1)^k, which at the fibre FA leaves it outside the angle.
V powerAxis(const float t[6], V v) {
  for (int k = 0; k < 6; ++k) {
    const V w{t[0] * v.x + t[1] * v.y + t[2] * v.z, t[1] * v.x + t[3] * v.y + t[4] * v.z,
              t[2] * v.x + t[4] * v.y + t[5] * v.z};
    const double n = std::sqrt(dot(w, w));
    if (!(n > 0)) return {0, 0, 0};
    v = {w.x / n, w.y / n, w.z / n};
  }
  return v;
}

// The neighbour step r voxels out nearest index-space direction u: u scaled
// so that its largest component is r, rounded. Coded 0..124 (5^3), 62
// being none.
int stepCode(const V& u, int r) {
  const double m = std::max({std::abs(u.x), std::abs(u.y), std::abs(u.z)});
  const double k = r / m;
  const auto step = [&](double c) { return int(std::floor(k * c + 0.5)); };
  return (step(u.x) + 2) + 5 * (step(u.y) + 2) + 25 * (step(u.z) + 2);
}

// Seeds grouped by blocks of `side`^3 voxels: per block, per candidate, the
// sum of the seeds' score differences from as read, then the seed count.
class Clusters {
 public:
  Clusters(const std::array<int, 3>& d, int side, std::size_t candidates)
      : side_(side), nc_(candidates), bx_((d[0] + side - 1) / side), by_((d[1] + side - 1) / side) {}
  double* add(std::int64_t i, std::int64_t j, std::int64_t k) {
    const auto [at, fresh] = index_.try_emplace(i / side_ + bx_ * (j / side_ + by_ * (k / side_)), sums_.size());
    if (fresh) sums_.resize(sums_.size() + nc_ + 1, 0.0);
    double* b = &sums_[at->second];
    b[nc_] += 1;
    return b;
  }
  std::size_t count() const { return index_.size(); }
  // The standard error of the mean difference `mean` of candidate c, with
  // the blocks as the samples (the ratio estimator's); 0 under two blocks.
  double standardError(std::size_t c, double mean) const {
    const std::size_t g = count();
    if (g < 2) return 0;
    double seeds = 0;
    for (std::size_t b = 0; b < g; ++b) seeds += sums_[b * (nc_ + 1) + nc_];
    const double perBlock = seeds / double(g);
    double ss = 0;
    for (std::size_t b = 0; b < g; ++b) {
      const double r = (sums_[b * (nc_ + 1) + c] - mean * sums_[b * (nc_ + 1) + nc_]) / perBlock;
      ss += r * r;
    }
    return std::sqrt(ss / (double(g) * double(g - 1)));
  }

 private:
  std::int64_t side_;
  std::size_t nc_;
  std::int64_t bx_, by_;
  std::unordered_map<std::int64_t, std::size_t> index_;
  std::vector<double> sums_;
};

}  // namespace

CoherenceScores fibreCoherence(const CoherenceGrid& grid, std::span<const float> tensors,
                               std::span<const std::uint32_t> ids, std::span<const Mat3> candidates,
                               const CoherenceParams& p) {
  CoherenceScores out;
  out.scores.assign(candidates.size(), 0.0);
  const std::size_t n = ids.size();
  const auto& d = grid.dims;
  const std::uint64_t voxels = std::uint64_t(std::max(d[0], 0)) * std::uint64_t(std::max(d[1], 0)) *
                               std::uint64_t(std::max(d[2], 0));
  const std::optional<Mat3> toIndex = inverse(grid.axesWC);
  if (n == 0 || tensors.size() < 6 * n || !toIndex || voxels == 0 || voxels > kNoSample) return out;

  // Examined samples, evenly spread, and their FA.
  const std::size_t step = std::max<std::size_t>(1, n / std::max<std::size_t>(1, p.maxExamined));
  std::vector<std::size_t> examined;
  std::vector<double> fa, nonZeroFa;
  for (std::size_t s = 0; s < n; s += step) {
    const double a = fractionalAnisotropy(&tensors[6 * s]);
    examined.push_back(s);
    fa.push_back(a);
    const float* t = &tensors[6 * s];
    if (t[0] != 0 || t[1] != 0 || t[2] != 0 || t[3] != 0 || t[4] != 0 || t[5] != 0) nonZeroFa.push_back(a);
  }
  out.faMin = p.faMin > 0 ? p.faMin : std::max(kFaFloor, otsuThreshold(nonZeroFa));
  const double cosMax = std::cos(p.maxAngleDeg * 3.14159265358979323846 / 180);

  // Voxel index -> sample: the identity when every voxel is a sample.
  std::vector<std::uint32_t> sampleOf;
  if (n != voxels) {
    sampleOf.assign(std::size_t(voxels), kNoSample);
    for (std::size_t s = 0; s < n; ++s)
      if (ids[s] < voxels) sampleOf[ids[s]] = std::uint32_t(s);
  }
  const auto sampleAt = [&](std::int64_t v) { return sampleOf.empty() ? std::uint32_t(v) : sampleOf[std::size_t(v)]; };

  std::vector<Mat3> toStep;  // WC axis -> index-space direction, per candidate
  for (const Mat3& m : candidates) toStep.push_back(multiply(*toIndex, m));
  std::vector<double> sums(candidates.size(), 0.0);
  const std::size_t nc = candidates.size();
  Clusters fine(d, kBlock, nc), coarse(d, 2 * kBlock, nc);
  std::vector<std::size_t> fibres;
  for (std::size_t k = 0; k < examined.size(); ++k)
    if (fa[k] >= out.faMin && fa[k] <= 1) fibres.push_back(examined[k]);
  out.fibreVoxelsFound = fibres.size();
  const std::size_t every = std::max<std::size_t>(1, (fibres.size() + p.maxSeeds - 1) / std::max<std::size_t>(1, p.maxSeeds));
  for (std::size_t k = 0; k < fibres.size(); k += every) {
    const std::size_t s = fibres[k];
    const std::int64_t v = ids[s];
    const std::int64_t i = v % d[0], j = (v / d[0]) % d[1], kk = v / (std::int64_t(d[0]) * d[1]);
    const V e = principalAxis(&tensors[6 * s]);
    ++out.fibreVoxels;
    float coherent[125];
    std::fill(coherent, coherent + 125, -1.0f);
    const auto neighbour = [&](int code) -> double {
      if (coherent[code] >= 0) return coherent[code];
      const std::int64_t ni = i + code % 5 - 2, nj = j + (code / 5) % 5 - 2, nk = kk + code / 25 - 2;
      double ok = 0;
      if (ni >= 0 && nj >= 0 && nk >= 0 && ni < d[0] && nj < d[1] && nk < d[2]) {
        const std::uint32_t ns = sampleAt(ni + d[0] * (nj + std::int64_t(d[1]) * nk));
        if (ns != kNoSample) {
          const float* t = &tensors[6 * std::size_t(ns)];
          const double nfa = fractionalAnisotropy(t);
          ok = nfa >= out.faMin && nfa <= 1 && std::abs(dot(powerAxis(t, e), e)) >= cosMax;
        }
      }
      coherent[code] = float(ok);
      return ok;
    };
    double* inFine = fine.add(i, j, kk);
    double* inCoarse = coarse.add(i, j, kk);
    double first = 0;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      const V u = times(toStep[c], e);
      double sum = 0;
      for (int r = 1; r <= p.reach; ++r) {
        const int code = stepCode(u, r);
        sum += neighbour(code) + neighbour(124 - code);
      }
      sum /= 2.0 * p.reach;
      if (c == 0) first = sum;
      sums[c] += sum;
      inFine[c] += sum - first;
      inCoarse[c] += sum - first;
    }
  }
  // Neighbouring voxels share neighbours and bundles, so they are not
  // independent samples: the error is the larger of the blocks' at two block
  // sizes, as the blocking method takes the error where it stops growing
  // with the block. A per-voxel error made DIPY's 6x10x10 small_101D, and
  // smooth random fields with no mirror, look decisive.
  out.pairedSe.assign(nc, 0.0);
  out.blocks = fine.count();
  out.coarseBlocks = coarse.count();
  for (std::size_t c = 0; c < nc; ++c) {
    const double mean = (sums[c] - sums[0]) / double(std::max<std::size_t>(1, out.fibreVoxels));
    out.pairedSe[c] = std::max(fine.standardError(c, mean), coarse.standardError(c, mean));
  }
  if (out.fibreVoxels)
    for (std::size_t c = 0; c < candidates.size(); ++c) out.scores[c] = sums[c] / double(out.fibreVoxels);
  return out;
}

}  // namespace tg::tensor
