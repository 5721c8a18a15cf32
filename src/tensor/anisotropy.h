#pragma once
// Scalar invariants of a tensor's eigenvalues (sorted descending).
#include <glm/vec3.hpp>

#include "tensor/lanes.h"

namespace tg::tensor {

template <class T>
struct AnisotropyOf {
  T fa{}, md{}, cl{}, cp{}, cs{};
};
using Anisotropy = AnisotropyOf<double>;

// FA: Basser & Pierpaoli 1996, sqrt(3/2)|D - MD·I| / |D|; 0 for the zero tensor.
// It exceeds 1 for indefinite tensors and is reported unclamped.
// cl, cp, cs: Westin et al. 1997, normalised by the trace:
//   cl = (l1-l2)/tr, cp = 2(l2-l3)/tr, cs = 3 l3/tr, so cl+cp+cs = 1.
// They are defined for positive trace only; otherwise all three are 0.
// Branch-free on T = double or Lanes4 (lanes.h), so that the glyph builder
// runs it on four tensors at once.
template <class T>
[[gnu::always_inline]] inline AnisotropyOf<T> anisotropy(T l1, T l2, T l3) {
  AnisotropyOf<T> a;
  const T tr = l1 + l2 + l3;
  a.md = tr * (1.0 / 3.0);
  const T norm2 = l1 * l1 + l2 * l2 + l3 * l3;
  const T dx = l1 - a.md, dy = l2 - a.md, dz = l3 - a.md;
  const T zero = splat<T>(0.0), one = splat<T>(1.0);
  const auto some = norm2 > zero;
  a.fa = some ? lsqrt(1.5 * (dx * dx + dy * dy + dz * dz) / (some ? norm2 : one)) : zero;
  // Relative guard: a trace that cancels to rounding noise has no meaningful shape.
  const auto shaped = tr > 1e-12 * lsqrt(norm2);
  const T inv = one / (shaped ? tr : one);
  a.cl = shaped ? (l1 - l2) * inv : zero;
  a.cp = shaped ? 2.0 * (l2 - l3) * inv : zero;
  a.cs = shaped ? 3.0 * l3 * inv : zero;
  return a;
}

inline Anisotropy anisotropy(const glm::dvec3& sortedEigenvalues) {
  return anisotropy(sortedEigenvalues.x, sortedEigenvalues.y, sortedEigenvalues.z);
}

}  // namespace tg::tensor
