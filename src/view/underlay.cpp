#include "view/underlay.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace tg::render {

std::optional<double> UnderlayVolume::sample(const glm::dvec3& pointWC, bool linear) const {
  const glm::dvec3 idx = glm::dvec3(glm::inverse(indexToWC) * glm::dvec4(pointWC, 1.0));
  for (int a = 0; a < 3; ++a)
    if (!(idx[a] >= -0.5 && idx[a] <= dims[a] - 0.5)) return std::nullopt;
  auto at = [&](int i, int j, int k) {
    return double(values[std::size_t(i) + std::size_t(dims[0]) * (std::size_t(j) + std::size_t(dims[1]) * std::size_t(k))]);
  };
  if (!linear) {
    int ijk[3];
    for (int a = 0; a < 3; ++a) ijk[a] = std::clamp(int(std::floor(idx[a] + 0.5)), 0, dims[a] - 1);
    const double v = at(ijk[0], ijk[1], ijk[2]);
    return std::isfinite(v) ? std::optional(v) : std::nullopt;
  }
  // As a GL texture with clamp-to-edge: linear between voxel centres,
  // constant over the outer half cell.
  int lo[3], hi[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    const double x = std::clamp(idx[a], 0.0, double(dims[a] - 1));
    lo[a] = int(std::floor(x));
    hi[a] = std::min(lo[a] + 1, dims[a] - 1);
    f[a] = x - lo[a];
  }
  double sum = 0;
  for (int c = 0; c < 8; ++c) {
    const int i = c & 1 ? hi[0] : lo[0], j = c & 2 ? hi[1] : lo[1], k = c & 4 ? hi[2] : lo[2];
    const double v = at(i, j, k);
    if (!std::isfinite(v)) return sample(pointWC, false);  // next to a hole: the nearest voxel, as the shader
    sum += v * (c & 1 ? f[0] : 1 - f[0]) * (c & 2 ? f[1] : 1 - f[1]) * (c & 4 ? f[2] : 1 - f[2]);
  }
  return sum;
}

namespace {

glm::dvec3 toWC(const glm::dmat4& m, double i, double j, double k) { return glm::dvec3(m * glm::dvec4(i, j, k, 1.0)); }

}  // namespace

std::pair<glm::dvec3, glm::dvec3> UnderlayVolume::boundsWC() const {
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 p = toWC(indexToWC, c & 1 ? dims[0] - 0.5 : -0.5, c & 2 ? dims[1] - 0.5 : -0.5,
                              c & 4 ? dims[2] - 0.5 : -0.5);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return {lo, hi};
}

std::optional<Colormap> colormapNamed(const std::string& name) {
  if (name == "gray" || name == "grey") return Colormap::Gray;
  if (name == "viridis") return Colormap::Viridis;
  if (name == "diverging") return Colormap::Diverging;
  return std::nullopt;
}

std::string PlaneSpec::label() const {
  if (axis >= 0) return std::string("plane ") + "xyz"[axis] + ":" + std::to_string(index);
  auto v = [](const glm::dvec3& p) {
    char b[96];
    std::snprintf(b, sizeof b, "%g,%g,%g", p.x, p.y, p.z);
    return std::string(b);
  };
  return "plane at " + v(pointWC) + " normal " + v(normalWC);
}

PlaneQuad planeQuad(const UnderlayVolume& v, const PlaneSpec& s) {
  PlaneQuad q;
  const glm::dmat4& m = v.indexToWC;
  if (s.axis >= 0) {
    const int a = s.axis, b = (a + 1) % 3, c = (a + 2) % 3;
    if (s.index < 0 || s.index >= v.dims[a])
      throw std::invalid_argument(std::string("plane ") + "xyz"[a] + ":" + std::to_string(s.index) +
                                  " is outside the underlay's grid (0.." + std::to_string(v.dims[a] - 1) + ")");
    const double bs[4] = {-0.5, v.dims[b] - 0.5, v.dims[b] - 0.5, -0.5};
    const double cs[4] = {-0.5, -0.5, v.dims[c] - 0.5, v.dims[c] - 0.5};
    for (int k = 0; k < 4; ++k) {
      double ijk[3];
      ijk[a] = double(s.index);
      ijk[b] = bs[k];
      ijk[c] = cs[k];
      q.cornersWC[k] = toWC(m, ijk[0], ijk[1], ijk[2]);
    }
    q.pointWC = 0.5 * (q.cornersWC[0] + q.cornersWC[2]);
    q.normalWC = glm::normalize(glm::cross(q.cornersWC[1] - q.cornersWC[0], q.cornersWC[3] - q.cornersWC[0]));
    if (!std::isfinite(q.normalWC.x)) throw std::invalid_argument("the underlay's grid is degenerate");
    return q;
  }
  // Scaled by its largest component first, so that a tiny normal (1e-300)
  // does not underflow to length 0.
  const double big = std::max({std::abs(s.normalWC.x), std::abs(s.normalWC.y), std::abs(s.normalWC.z)});
  if (!(big > 0) || !std::isfinite(big)) throw std::invalid_argument("an oblique plane needs a non-zero normal");
  const glm::dvec3 n = glm::normalize(s.normalWC / big);
  glm::dvec3 corners[8];
  bool above = false, below = false;
  for (int c = 0; c < 8; ++c) {
    corners[c] = toWC(m, c & 1 ? v.dims[0] - 0.5 : -0.5, c & 2 ? v.dims[1] - 0.5 : -0.5, c & 4 ? v.dims[2] - 0.5 : -0.5);
    const double d = glm::dot(n, corners[c] - s.pointWC);
    above |= d >= 0;
    below |= d <= 0;
  }
  if (!(above && below)) throw std::invalid_argument(s.label() + " misses the underlay's volume");
  // Any in-plane frame: the quad is the plane's rectangle over the box's shadow on it.
  const glm::dvec3 seed = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(n, seed)), w = glm::cross(n, u);
  double u0 = INFINITY, u1 = -INFINITY, w0 = INFINITY, w1 = -INFINITY;
  for (const glm::dvec3& c : corners) {
    const glm::dvec3 d = c - s.pointWC;
    u0 = std::min(u0, glm::dot(d, u));
    u1 = std::max(u1, glm::dot(d, u));
    w0 = std::min(w0, glm::dot(d, w));
    w1 = std::max(w1, glm::dot(d, w));
  }
  q.cornersWC[0] = s.pointWC + u0 * u + w0 * w;
  q.cornersWC[1] = s.pointWC + u1 * u + w0 * w;
  q.cornersWC[2] = s.pointWC + u1 * u + w1 * w;
  q.cornersWC[3] = s.pointWC + u0 * u + w1 * w;
  q.pointWC = s.pointWC;
  q.normalWC = n;
  return q;
}

std::pair<double, double> percentileWindow(const std::vector<float>& values, double lo, double hi) {
  std::vector<float> finite;
  finite.reserve(values.size());
  for (float x : values)
    if (std::isfinite(x)) finite.push_back(x);
  if (finite.empty()) return {0.0, 1.0};
  auto rank = [&](double pct) {
    const auto k = std::size_t(std::clamp(std::ceil(pct / 100.0 * double(finite.size())) - 1.0, 0.0,
                                          double(finite.size() - 1)));
    std::nth_element(finite.begin(), finite.begin() + std::ptrdiff_t(k), finite.end());
    return double(finite[k]);
  };
  const double a = rank(lo), b = rank(hi);
  // A constant volume still needs a range to map.
  return a < b ? std::pair(a, b) : std::pair(a - 0.5, a + 0.5);
}

}  // namespace tg::render
