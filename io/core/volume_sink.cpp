#include "io/core/volume_sink.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace tg::io {

void positionWC(const VolumeGeometry& g, const int ijk[3], double p[3]) {
  for (int r = 0; r < 3; ++r)
    p[r] = g.originWC[r] + g.axesWC[3 * r] * ijk[0] + g.axesWC[3 * r + 1] * ijk[1] + g.axesWC[3 * r + 2] * ijk[2];
}

VolumeSink::VolumeSink(TensorField& f, const VolumeGeometry& g, const ComponentLayout& layout, const Selector& sel,
                       double confidenceMin)
    : f_(f), g_(g), layout_(layout), sel_(sel), confidenceMin_(confidenceMin) {}

// Inlined: a call per voxel was 3% of a raw load.
[[gnu::always_inline]] inline void VolumeSink::nextPosition(double p[3]) {
  positionWC(g_, ijk_, p);
  if (++ijk_[0] == g_.dims[0]) {
    ijk_[0] = 0;
    if (++ijk_[1] == g_.dims[1]) {
      ijk_[1] = 0;
      ++ijk_[2];
    }
  }
}

void VolumeSink::push(const double* v) {
  const std::uint64_t index = next_++;
  double p[3];
  nextPosition(p);
  if (sel_.admit(index, p, f_)) emit(index, p, v);
}

void VolumeSink::pushVoxels(const double* v, std::size_t values) {
  const std::size_t step = std::size_t(layout_.count);
  if (!sel_.selectsAll() || layout_.confidence >= 0 || layout_.full) {
    for (std::size_t i = 0; i < values; i += step) push(v + i);
    return;
  }
  // Every voxel kept as it is (the usual load): one capacity check for the
  // whole chunk and no call per voxel, which halved a raw load's decode time.
  const std::size_t m = values / step, before = f_.ids.size();
  float* posWC = f_.positions.extend(3 * m);
  float* ten = f_.tensors.extend(6 * m);
  std::uint32_t* ids = f_.ids.extend(m);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < m; ++i, v += step) {
    double p[3], s[6];
    nextPosition(p);
    for (int k = 0; k < 6; ++k) s[k] = v[layout_.sym[std::size_t(k)]];
    if (g_.tensorToWC) congruence(g_.tensorToWC->data(), s, s);
    ++f_.totalPoints;
    const std::uint64_t index = next_++;
    if (!f_.admits(p, s)) continue;
    TensorField::storeSample(p, s, posWC + 3 * kept, ten + 6 * kept);
    ids[kept++] = std::uint32_t(index);
  }
  f_.positions.resize(3 * (before + kept));
  f_.tensors.resize(6 * (before + kept));
  f_.ids.resize(before + kept);
}

void VolumeSink::positionOf(std::uint64_t index, double p[3]) const {
  const std::uint64_t nx = std::uint64_t(g_.dims[0]), ny = std::uint64_t(g_.dims[1]);
  const int ijk[3] = {int(index % nx), int(index / nx % ny), int(index / (nx * ny))};
  positionWC(g_, ijk, p);
}

bool VolumeSink::accept(std::uint64_t index) {
  if (sel_.selectsAll()) return true;
  double p[3];
  positionOf(index, p);
  return sel_.admit(index, p, f_);
}

void VolumeSink::pushAccepted(std::uint64_t index, const double* v) {
  double p[3];
  positionOf(index, p);
  emit(index, p, v);
}

void VolumeSink::emit(std::uint64_t index, const double p[3], const double* v) {
  // A NaN confidence is not >= the threshold either: masked.
  if (layout_.confidence >= 0 && !(v[layout_.confidence] >= confidenceMin_)) {
    ++f_.totalPoints;
    ++f_.masked;
    return;
  }
  double s[6];
  if (layout_.full) {
    symmetricPart(v, s);
    maxAsym_ = std::max(maxAsym_, asymmetry(v));
  } else {
    for (int k = 0; k < 6; ++k) s[k] = v[layout_.sym[k]];
  }
  if (g_.tensorToWC) congruence(g_.tensorToWC->data(), s, s);
  f_.addSym(std::uint32_t(index), p, s);
}

void VolumeSink::finish() {
  GridInfo gi;
  for (int k = 0; k < 3; ++k) {
    gi.dims[k] = g_.dims[k];
    gi.origin[k] = g_.originWC[k];
    const double len = std::hypot(g_.axesWC[k], g_.axesWC[3 + k], g_.axesWC[6 + k]);
    gi.spacing[k] = len;
    for (int r = 0; r < 3; ++r) gi.directions[3 * r + k] = len > 0 ? g_.axesWC[3 * r + k] / len : (r == k);
  }
  // The kept samples' spacing: a stride thins them, a slice drops its own axis.
  const double minSpacing = sel_.keptSpacing(gi.spacing);
  f_.grid = gi;
  f_.sampleSpacing = std::isfinite(minSpacing) ? minSpacing : estimateSampleSpacing(f_.positions);
}

void VolumeSink::warnIfAsymmetric() {
  if (const std::string w = asymmetryWarning("3D-matrix tensors", maxAsym_); layout_.full && !w.empty())
    f_.warnings.push_back(w);
}

GridPlacement placementOf(const VolumeGeometry& g) {
  GridPlacement p;
  std::copy(g.originWC, g.originWC + 3, p.originWC);
  std::copy(g.axesWC, g.axesWC + 9, p.axesWC);
  return p;
}

double determinant3(const double a[9]) {
  return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) + a[2] * (a[3] * a[7] - a[4] * a[6]);
}

bool gridIsSingular(const int dims[3], const double axes[9]) {
  // A singleton axis's step is never taken: a coordinate axis stands in for
  // it, whichever of them best completes the others (all 27 choices tried).
  double lengths = 1;
  int stepped = 0;
  for (int k = 0; k < 3; ++k) {
    const double len = std::hypot(axes[k], axes[3 + k], axes[6 + k]);
    if (dims[k] > 1) {
      if (!std::isfinite(len) || !(len > 0)) return true;
      lengths *= len;
      ++stepped;
    }
  }
  double a[9], best = 0;
  for (int pick = 0; pick < 27; ++pick) {
    const int choice[3] = {pick % 3, pick / 3 % 3, pick / 9};
    for (int k = 0; k < 3; ++k)
      for (int r = 0; r < 3; ++r) a[3 * r + k] = dims[k] > 1 ? axes[3 * r + k] : (r == choice[k] ? 1.0 : 0.0);
    best = std::max(best, std::abs(determinant3(a)));
  }
  return stepped > 0 && !(best > 1e-6 * lengths);
}

std::array<double, 9> orthogonalPart(const double m[9]) {
  std::array<double, 9> q;
  std::copy(m, m + 9, q.begin());
  // Scaled to |det| = 1 first: unscaled, each step only halves a scale far
  // from 1, and 100 steps left an affine of 1e30 mm voxels unconverged.
  if (const double d = std::abs(determinant3(m)); d > 0 && std::isfinite(d))
    for (double& x : q) x /= std::cbrt(d);
  for (int iter = 0; iter < 100; ++iter) {
    // Q <- (Q + Q^-T) / 2
    const double* a = q.data();
    const double det = determinant3(a);
    if (!(std::abs(det) > 0)) break;
    // Inverse-transpose = cofactor matrix / det.
    const double cof[9] = {a[4] * a[8] - a[5] * a[7], a[5] * a[6] - a[3] * a[8], a[3] * a[7] - a[4] * a[6],
                           a[2] * a[7] - a[1] * a[8], a[0] * a[8] - a[2] * a[6], a[1] * a[6] - a[0] * a[7],
                           a[1] * a[5] - a[2] * a[4], a[2] * a[3] - a[0] * a[5], a[0] * a[4] - a[1] * a[3]};
    double change = 0;
    std::array<double, 9> n;
    for (int k = 0; k < 9; ++k) {
      n[k] = 0.5 * (a[k] + cof[k] / det);
      change = std::max(change, std::abs(n[k] - a[k]));
    }
    q = n;
    if (change < 1e-15) break;
  }
  return q;
}

}  // namespace tg::io
