#pragma once
// Signed permutations of a tensor's stored axes: --tensor-axes, and the
// readings the frame check scores (tensor/fibre_coherence.h). Header-only:
// the readers (position-independent) compose them too.
#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tg::tensor {

using Mat3 = std::array<double, 9>;  // row-major

// A signed permutation of a tensor's stored axes: axis r of the reading is
// sign[r] times stored axis from[r]. As a matrix P (D read = P D Pᵀ), row r
// is sign[r] e_from[r]. Named as --tensor-axes takes it: "-x,y,z" negates x
// (its xy and xz components), "y,x,z" swaps x and y.
struct AxisMap {
  std::array<int, 3> from{0, 1, 2};
  std::array<int, 3> sign{1, 1, 1};
  bool operator==(const AxisMap&) const = default;
};

// "-x,y,z": three comma-separated axes x, y, z, each once, each with an
// optional sign.
inline std::optional<AxisMap> axisMapNamed(std::string_view text) {
  AxisMap m;
  bool seen[3] = {false, false, false};
  std::size_t at = 0;
  for (int r = 0; r < 3; ++r) {
    if (r > 0) {
      if (at >= text.size() || text[at] != ',') return std::nullopt;
      ++at;
    }
    m.sign[std::size_t(r)] = 1;
    if (at < text.size() && (text[at] == '-' || text[at] == '+')) m.sign[std::size_t(r)] = text[at++] == '-' ? -1 : 1;
    if (at >= text.size() || text[at] < 'x' || text[at] > 'z') return std::nullopt;
    const int axis = text[at++] - 'x';
    if (seen[axis]) return std::nullopt;
    seen[axis] = true;
    m.from[std::size_t(r)] = axis;
  }
  if (at != text.size()) return std::nullopt;
  return m;
}

inline std::string axisMapName(const AxisMap& m) {
  std::string s;
  for (std::size_t r = 0; r < 3; ++r) {
    if (r) s += ',';
    if (m.sign[r] < 0) s += '-';
    s += char('x' + m.from[r]);
  }
  return s;
}

// The matrix product a b.
inline Mat3 multiply(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t k = 0; k < 3; ++k)
      for (std::size_t j = 0; j < 3; ++j) c[3 * r + k] += a[3 * r + j] * b[3 * j + k];
  return c;
}

inline Mat3 axisMatrix(const AxisMap& m) {
  Mat3 p{};
  for (std::size_t r = 0; r < 3; ++r) p[3 * r + std::size_t(m.from[r])] = m.sign[r];
  return p;
}

// a then b: the map whose matrix is axisMatrix(b) · axisMatrix(a).
inline AxisMap compose(const AxisMap& a, const AxisMap& b) {
  AxisMap c;
  for (std::size_t r = 0; r < 3; ++r) {
    const std::size_t via = std::size_t(b.from[r]);
    c.from[r] = a.from[via];
    c.sign[r] = b.sign[r] * a.sign[via];
  }
  return c;
}

// The 24 readings that differ for principal axes (v and -v are one axis, so
// negating two axes is negating the third): the 6 permutations, each with
// no axis or one of the three negated; the identity first.
inline std::vector<AxisMap> distinctAxisMaps() {
  std::vector<AxisMap> out;
  std::array<int, 3> perm{0, 1, 2};
  do {
    for (int negated = -1; negated < 3; ++negated) {
      AxisMap m;
      m.from = perm;
      if (negated >= 0) m.sign[std::size_t(negated)] = -1;
      out.push_back(m);
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  return out;  // std::next_permutation starts at the identity, unnegated first
}

}  // namespace tg::tensor
