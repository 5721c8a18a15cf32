#pragma once
// Symmetric 3x3 eigensystems.
#include <array>
#include <cstddef>
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
// (1e30) tensors stay out of under/overflow: an exact path for diagonal
// tensors; the closed-form cubic (Smith 1961, solved without trigonometry)
// with cross-product eigenvectors where all three eigenvalues are well
// separated and none is near zero (4x faster); else cyclic Jacobi (Golub & Van Loan, "Matrix
// Computations", §8.5), which is exact for repeated eigenvalues and
// orthonormal by construction. Precondition: all components finite.
Eigensystem eigensolve(const SymTensor& t);

// A block of eigensystems in structure-of-arrays form, for loaders that
// decompose millions of tensors: values[i][k] is eigenvalue i of tensor k,
// vectors[i][c][k] component c of its eigenvector i.
inline constexpr std::size_t kEigenBlock = 64;
struct EigenBlock {
  double values[3][kEigenBlock];
  double vectors[3][3][kEigenBlock];
};

// eigensolve() of the first n <= kEigenBlock tensors at t (six floats each,
// xx xy xz yy yz zz), with the same results: the closed form runs on all
// lanes at once (vectorised), and the lanes it declines take the scalar
// paths afterwards.
void eigensolveBlock(const float* t, std::size_t n, EigenBlock& out);

}  // namespace tg::tensor
