#pragma once
// Symmetric 3x3 eigensystems.
#include <array>
#include <glm/vec3.hpp>

namespace tg::tensor {

// Six unique components of a symmetric tensor, row-major upper triangle.
struct SymTensor {
  double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
};

struct Eigensystem {
  glm::dvec3 values{0.0};               // descending, signed
  std::array<glm::dvec3, 3> vectors{};  // unit, orthonormal, right-handed; vectors[i] ↔ values[i]
};

// On the tensor scaled by its largest entry, so that tiny (1e-30) and huge
// (1e30) tensors stay out of under/overflow: the closed-form cubic (Smith
// 1961) with cross-product eigenvectors where all three eigenvalues are well
// separated (5-10x faster), else cyclic Jacobi (Golub & Van Loan, "Matrix
// Computations", §8.5), which is exact for repeated eigenvalues and
// orthonormal by construction. Precondition: all components finite.
Eigensystem eigensolve(const SymTensor& t);

}  // namespace tg::tensor
