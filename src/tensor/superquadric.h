#pragma once
// Superquadric tensor glyph shapes, as Teem's tenGlyphGen assigns them
// (teem/src/ten/glyph.c, "find axis, and superquad exponents"):
//   - all eigenvalues positive: Kindlmann 2004, from Westin's cl1/cp1
//     clamped to 0.99 and the sharpness gamma;
//   - all negative: the same rule on the mirrored |eigenvalues|, with the
//     symmetry axis swapped;
//   - mixed signs or zeros: Schultz & Kindlmann 2010 (TVCG 16(6)), a
//     spherical-barycentric blend of four base shapes on the sphere of
//     normalised eigenvalues (independent of gamma).
// The unit glyph in GC, with the symmetry axis taken as z, is
//   g(p) = (s^(2/b) + |z|^(2/c))^(b/2) = 1,  s = (|x|^(2/a) + |y|^(2/a))^(a/2),
// a superquadric in Barr's form; c differs from b only in the mixed case.
// The GLSL twin is shaders/lib/superquadric_shape.glsl.
#include <glm/vec3.hpp>

namespace tg::tensor {

// Exponents below this are raised to it, so that 2/a, 2/b, 2/c stay <= 1000:
// at larger exponents the shape differs from its box limit by less than
// 0.07% of its size (2^(1/1000)), and float powers stay finite.
inline constexpr double kMinShapeExponent = 2e-3;

struct SuperquadricShape {
  double a = 1, b = 1, c = 1;  // 1, 1, 1 is the ellipsoid
  int axis = 2;                // eigenvector index (0: major, 2: minor) that GC z follows
};

// Shape of a glyph with descending signed eigenvalues at sharpness gamma >= 0.
SuperquadricShape superquadricShape(const glm::dvec3& sortedEigenvalues, double gamma);

// Whether a shape is drawn exactly as an ellipsoid (a = b = c = 1).
bool isEllipsoid(const SuperquadricShape& s);

// Spherical barycentric coordinates of unit vector v inside the spherical
// triangle (p0, p1, p2): the areas of the sub-triangles opposite each vertex,
// normalised to sum 1, as Teem's ell_3v_barycentric_spherical_d.
glm::dvec3 sphericalBarycentric(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2,
                                const glm::dvec3& v);

// The glyph's implicit function g (above) in GC, with symmetry axis z, and its
// gradient. Stable for exponents up to 1000 and at coordinates 0.
double superquadricGauge(const SuperquadricShape& s, const glm::dvec3& pGC, glm::dvec3* gradGC = nullptr);

}  // namespace tg::tensor
