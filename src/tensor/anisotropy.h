#pragma once
// Scalar invariants of a tensor's eigenvalues (sorted descending).
#include <glm/vec3.hpp>

namespace tg::tensor {

struct Anisotropy {
  double fa = 0, md = 0, cl = 0, cp = 0, cs = 0;
};

// FA: Basser & Pierpaoli 1996, sqrt(3/2)|D - MD·I| / |D|; 0 for the zero tensor.
// It exceeds 1 for indefinite tensors and is reported unclamped.
// cl, cp, cs: Westin et al. 1997, normalised by the trace:
//   cl = (l1-l2)/tr, cp = 2(l2-l3)/tr, cs = 3 l3/tr, so cl+cp+cs = 1.
// They are defined for positive trace only; otherwise all three are 0.
Anisotropy anisotropy(const glm::dvec3& sortedEigenvalues);

}  // namespace tg::tensor
