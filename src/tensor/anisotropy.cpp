#include "tensor/anisotropy.h"

#include <cmath>

namespace tg::tensor {

Anisotropy anisotropy(const glm::dvec3& l) {
  Anisotropy a;
  const double tr = l.x + l.y + l.z;
  a.md = tr / 3.0;
  const double norm2 = l.x * l.x + l.y * l.y + l.z * l.z;
  if (norm2 > 0.0) {
    const double dx = l.x - a.md, dy = l.y - a.md, dz = l.z - a.md;
    a.fa = std::sqrt(1.5 * (dx * dx + dy * dy + dz * dz) / norm2);
  }
  // Relative guard: a trace that cancels to rounding noise has no meaningful shape.
  if (tr > 1e-12 * std::sqrt(norm2)) {
    a.cl = (l.x - l.y) / tr;
    a.cp = 2.0 * (l.y - l.z) / tr;
    a.cs = 3.0 * l.z / tr;
  }
  return a;
}

}  // namespace tg::tensor
