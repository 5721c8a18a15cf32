#include "io/field/tensor_field.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numeric>
#include <tuple>

#include "tensor/axis_map.h"

namespace tg::io {

void TensorField::addFull(std::uint32_t id, const double p[3], const double t[9]) {
  double sym[6];
  symmetricPart(t, sym);
  for (int k = 0; k < 9; ++k)
    if (!std::isfinite(t[k])) {
      ++totalPoints;
      ++skippedNonFinite;
      return;
    }
  addSym(id, p, sym);
}

void symmetricPart(const double t[9], double s[6]) {
  s[0] = t[0], s[1] = 0.5 * (t[1] + t[3]), s[2] = 0.5 * (t[2] + t[6]);
  s[3] = t[4], s[4] = 0.5 * (t[5] + t[7]), s[5] = t[8];
}

double asymmetry(const double t[9]) {
  double s[6];
  symmetricPart(t, s);
  const double asym = std::max({std::abs(t[1] - t[3]), std::abs(t[2] - t[6]), std::abs(t[5] - t[7])});
  const double norm = std::max({std::abs(s[0]), std::abs(s[1]), std::abs(s[2]), std::abs(s[3]), std::abs(s[4]),
                                std::abs(s[5])});
  return asym > 0 && norm > 0 ? asym / norm : 0.0;
}

std::string asymmetryWarning(const std::string& what, double maxAsymmetry) {
  if (!(maxAsymmetry > 1e-3)) return "";
  return what + " are asymmetric (max |D - Dᵀ| / |D| = " + std::to_string(maxAsymmetry) +
         "); drawn symmetrised, (D + Dᵀ)/2";
}

void congruence(const double t[9], const double s[6], double out[6]) {
  const double d[9] = {s[0], s[1], s[2], s[1], s[3], s[4], s[2], s[4], s[5]};
  double td[9];  // T D
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) td[3 * r + c] = t[3 * r] * d[c] + t[3 * r + 1] * d[3 + c] + t[3 * r + 2] * d[6 + c];
  auto tdt = [&](int r, int c) { return td[3 * r] * t[3 * c] + td[3 * r + 1] * t[3 * c + 1] + td[3 * r + 2] * t[3 * c + 2]; };
  const double w[6] = {tdt(0, 0), tdt(0, 1), tdt(0, 2), tdt(1, 1), tdt(1, 2), tdt(2, 2)};
  std::copy(w, w + 6, out);
}

void applyTensorAxes(TensorField& f, const std::string& axes) {
  const std::optional<tensor::AxisMap> map = axes.empty() ? std::nullopt : tensor::axisMapNamed(axes);
  if (!map || *map == tensor::AxisMap{}) return;
  // D_WC = T P D Pᵀ Tᵀ = M D_WC Mᵀ with M = T P Tᵀ, for the orthogonal T the
  // readers apply (none: the identity).
  const std::array<double, 9> p = tensor::axisMatrix(*map);
  const std::array<double, 9> t = f.tensorToWC.value_or(std::array<double, 9>{1, 0, 0, 0, 1, 0, 0, 0, 1});
  std::array<double, 9> tp{}, m{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) tp[std::size_t(3 * r + c)] += t[std::size_t(3 * r + k)] * p[std::size_t(3 * k + c)];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) m[std::size_t(3 * r + c)] += tp[std::size_t(3 * r + k)] * t[std::size_t(3 * c + k)];
  for (std::size_t s = 0; s < f.size(); ++s) {
    float* x = &f.tensors[6 * s];
    double d[6] = {x[0], x[1], x[2], x[3], x[4], x[5]};
    congruence(m.data(), d, d);
    for (int k = 0; k < 6; ++k) x[k] = float(d[k]);
  }
  f.tensorToWC = tp;
  for (FrameChoice& c : f.otherFrames) {
    std::array<double, 9> cp{};
    const std::array<double, 9> ct = c.tensorToWC.value_or(std::array<double, 9>{1, 0, 0, 0, 1, 0, 0, 0, 1});
    for (int r = 0; r < 3; ++r)
      for (int cc = 0; cc < 3; ++cc)
        for (int k = 0; k < 3; ++k) cp[std::size_t(3 * r + cc)] += ct[std::size_t(3 * r + k)] * p[std::size_t(3 * k + cc)];
    c.tensorToWC = cp;
  }
  f.frame += (f.frame.empty() ? "" : "; ") + std::string("stored axes read as ") + axes + " (--tensor-axes)";
}

bool tensorLikeArray(int nc, const std::string& name) {
  return nc == 9 || nc == 6 || (nc == 4 && (name == "sigma" || name == "epsilon"));
}

void planarTensor(int nc, const double* t, double full[9]) {
  for (int k = 0; k < 9; ++k) full[k] = 0.0;
  const double xy = nc == 4 ? t[3] : t[2];
  full[0] = t[0], full[1] = full[3] = xy, full[4] = t[1], full[8] = nc == 4 ? t[2] : 0.0;
}

double estimateSampleSpacing(std::span<const float> pos) {
  const std::size_t n = pos.size() / 3;
  if (n < 2) return 0.0;
  // Points sorted by x; a query scans outwards until x alone exceeds its best.
  // Ties in x are ordered by y and z, so that the queries (every n/512-th
  // point of this order) and the estimate do not depend on the points'
  // order: the same points in another order (a file written otherwise, the
  // ranks of a distributed run gathered) are the same field.
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) {
    return std::tie(pos[3 * a], pos[3 * a + 1], pos[3 * a + 2]) < std::tie(pos[3 * b], pos[3 * b + 1], pos[3 * b + 2]);
  });
  const std::size_t samples = std::min<std::size_t>(n, 512);
  std::vector<double> nn;
  for (std::size_t s = 0; s < samples; ++s) {
    const std::size_t r = s * n / samples;
    const float* q = &pos[3 * order[r]];
    double best = INFINITY;
    auto visit = [&](std::size_t k) {
      const float* p = &pos[3 * order[k]];
      const double dx = p[0] - q[0];
      if (dx * dx >= best) return false;
      const double d2 = dx * dx + double(p[1] - q[1]) * (p[1] - q[1]) + double(p[2] - q[2]) * (p[2] - q[2]);
      if (d2 > 0.0) best = std::min(best, d2);
      return true;
    };
    for (std::size_t k = r + 1; k < n && visit(k);) ++k;
    for (std::size_t k = r; k-- > 0 && visit(k);) {}
    if (std::isfinite(best)) nn.push_back(std::sqrt(best));
  }
  if (nn.empty()) return 0.0;
  std::nth_element(nn.begin(), nn.begin() + nn.size() / 2, nn.end());
  return nn[nn.size() / 2];
}

}  // namespace tg::io
