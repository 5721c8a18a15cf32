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

// Cyclic Jacobi on the tensor scaled by its largest entry (Golub & Van Loan,
// "Matrix Computations", §8.5). Chosen over the closed-form cubic because it is
// exact for repeated eigenvalues, returns orthonormal vectors by construction,
// and the scaling keeps tiny (1e-30) and huge (1e30) tensors out of
// under/overflow. Precondition: all components finite.
Eigensystem eigensolve(const SymTensor& t);

}  // namespace tg::tensor
