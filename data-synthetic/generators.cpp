#include "data-synthetic/generators.h"

#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

#include "data-synthetic/random_tensors.h"

namespace tg::synth {
namespace {

void addSym(io::TensorField& f, std::uint32_t id, const glm::dvec3& p, const glm::dmat3& d) {
  const double pos[3] = {p.x, p.y, p.z};
  double t[9];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) t[r * 3 + c] = d[c][r];
  f.addFull(id, pos, t);
}

glm::dmat3 fromEigen(const glm::dvec3& l, const glm::dmat3& r) {
  return r * glm::dmat3(l.x, 0, 0, 0, l.y, 0, 0, 0, l.z) * glm::transpose(r);
}

glm::dmat3 rotation(double angleDeg, const glm::dvec3& axis) {
  return glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(angleDeg), glm::normalize(axis)));
}

}  // namespace

Helix helixPhantom(int nx, int ny, int nz) {
  Helix h;
  io::GridInfo g;
  g.dims[0] = nx;
  g.dims[1] = ny;
  g.dims[2] = nz;
  const glm::dmat3 dir = rotation(25.0, {0.3, 0.2, 1.0});
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) g.directions[r * 3 + c] = dir[c][r];
  for (int k = 0; k < 3; ++k) g.spacing[k] = 1.0;
  g.spacing[2] = 1.5;  // anisotropic voxels, as in most DWI
  const glm::dvec3 origin(-0.5 * (nx - 1), -0.5 * (ny - 1), -0.5 * 1.5 * (nz - 1));
  const glm::dvec3 originWC = dir * origin;
  for (int k = 0; k < 3; ++k) g.origin[k] = originWC[k];
  h.field.grid = g;
  h.field.sampleSpacing = 1.0;
  h.field.description = "helix phantom";
  const glm::dmat3 mf = rotation(-40.0, {1.0, -0.5, 0.3});
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) h.measurementFrame[r * 3 + c] = mf[c][r];

  const double radius = 0.3 * std::min(nx, ny), tube = 0.07 * std::min(nx, ny);
  const double height = 1.5 * (nz - 1), turns = 2.0;
  const int samples = 720;
  // The curve's samples and tangents, computed once (not per voxel).
  std::vector<glm::dvec3> curve, tangents;
  for (int s = 0; s <= samples; ++s) {
    const double th = 2.0 * std::numbers::pi * turns * s / samples;
    curve.emplace_back(radius * std::cos(th), radius * std::sin(th), -0.45 * height + 0.9 * height * s / samples);
    tangents.push_back(glm::normalize(glm::dvec3(-radius * std::sin(th), radius * std::cos(th),
                                                 0.9 * height / (2.0 * std::numbers::pi * turns))));
  }
  std::uint32_t id = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i, ++id) {
        const glm::dvec3 pGrid = origin + glm::dvec3(i, j, 1.5 * k);
        // The helix lives in grid coordinates, so it follows the rotated grid.
        double best = INFINITY;
        glm::dvec3 tangent(0, 0, 1);
        for (std::size_t s = 0; s < curve.size(); ++s) {
          const double d = glm::length(pGrid - curve[s]);
          if (d < best) {
            best = d;
            tangent = tangents[s];
          }
        }
        glm::dmat3 d(0.0);
        if (best < tube) {
          const glm::dvec3 t = dir * tangent;  // to WC
          d = 1.6e-3 * glm::outerProduct(t, t) + 0.3e-3 * (glm::dmat3(1.0) - glm::outerProduct(t, t));
        } else {
          d = glm::dmat3(0.7e-3);
        }
        addSym(h.field, id, dir * pGrid, d);
      }
  return h;
}

void boussinesqStress(double x, double y, double z, double nu, double s[9]) {
  // Off the load axis the closed form is finite; nudge a sample that sits on it.
  if (x * x + y * y < 1e-24 * z * z) x = 1e-12 * z;
  const double r2 = x * x + y * y, R = std::sqrt(r2 + z * z), R3 = R * R * R, R5 = R3 * R * R;
  const double k = 1.0 / (2.0 * std::numbers::pi), a = 1.0 - 2.0 * nu;
  const double q = (1.0 - z / R) / r2;
  const double sxx = k * (a * (q * (x * x - y * y) / r2 + z * y * y / (R3 * r2)) - 3.0 * z * x * x / R5);
  const double syy = k * (a * (q * (y * y - x * x) / r2 + z * x * x / (R3 * r2)) - 3.0 * z * y * y / R5);
  // (sigma_r - sigma_theta) xy / r^2 from the cylindrical form (Johnson, "Contact Mechanics", eq. 3.21).
  const double sxy = k * (a * (2.0 * q * x * y / r2 - x * y * z / (R3 * r2)) - 3.0 * x * y * z / R5);
  const double szz = -3.0 * k * z * z * z / R5;
  const double sxz = -3.0 * k * x * z * z / R5;
  const double syz = -3.0 * k * y * z * z / R5;
  const double m[9] = {sxx, sxy, sxz, sxy, syy, syz, sxz, syz, szz};
  for (int i = 0; i < 9; ++i) s[i] = m[i];
}

io::TensorField boussinesq(int n, double nu) {
  io::TensorField f;
  io::GridInfo g;
  g.dims[0] = g.dims[1] = g.dims[2] = n;
  const double h = 2.0 / n;
  for (int k = 0; k < 3; ++k) g.spacing[k] = h;
  // Cell-centred, so no sample sits on the singular load point.
  g.origin[0] = g.origin[1] = -1.0 + 0.5 * h;
  g.origin[2] = -2.0 + 0.5 * h;
  f.grid = g;
  f.sampleSpacing = h;
  f.description = "Boussinesq point load";
  std::uint32_t id = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i, ++id) {
        const double p[3] = {g.origin[0] + i * h, g.origin[1] + j * h, g.origin[2] + k * h};
        double s[9];
        boussinesqStress(p[0], p[1], -p[2], nu, s);  // depth is -z: the load sits at z = 0 on top
        // Depth axis flipped: sxz and syz change sign.
        s[2] = s[6] = -s[2];
        s[5] = s[7] = -s[5];
        f.addFull(id, p, s);
      }
  return f;
}

void kirschStress(double x, double y, double s6[6]) {
  constexpr double S = 100.0, a = 1.0;
  const double r2 = x * x + y * y, q2 = a * a / r2, q4 = q2 * q2;
  const double th = std::atan2(y, x), c2 = std::cos(2.0 * th), s2 = std::sin(2.0 * th);
  const double srr = 0.5 * S * (1.0 - q2) + 0.5 * S * (1.0 - 4.0 * q2 + 3.0 * q4) * c2;
  const double stt = 0.5 * S * (1.0 + q2) - 0.5 * S * (1.0 + 3.0 * q4) * c2;
  const double srt = -0.5 * S * (1.0 + 2.0 * q2 - 3.0 * q4) * s2;
  const double c = std::cos(th), s = std::sin(th);
  const double sxx = srr * c * c + stt * s * s - 2.0 * srt * s * c;
  const double syy = srr * s * s + stt * c * c + 2.0 * srt * s * c;
  const double sxy = (srr - stt) * s * c + srt * (c * c - s * s);
  const double out[6] = {sxx, sxy, 0.0, syy, 0.0, 0.0};
  for (int k = 0; k < 6; ++k) s6[k] = out[k];
}

io::TensorField kirschPlate(int n) {
  io::TensorField f;
  io::GridInfo g;
  g.dims[0] = g.dims[1] = n;
  g.dims[2] = 1;
  const double h = 8.0 / n;
  for (int k = 0; k < 3; ++k) g.spacing[k] = h;
  g.origin[0] = g.origin[1] = -4.0 + 0.5 * h;
  f.grid = g;
  f.sampleSpacing = h;
  f.description = "Kirsch plate with a hole";
  std::uint32_t id = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i, ++id) {
      const double p[3] = {g.origin[0] + i * h, g.origin[1] + j * h, 0.0};
      double s[6] = {0, 0, 0, 0, 0, 0};
      if (p[0] * p[0] + p[1] * p[1] >= 1.0) kirschStress(p[0], p[1], s);
      f.addSym(id, p, s);
    }
  return f;
}

io::TensorField extremesGallery(double eigenScale, double positionScale) {
  io::TensorField f;
  f.description = "extremes gallery";
  const glm::dvec3 shapes[] = {
      {1, 1e-3, 1e-3}, {1, 0.02, 0.01},  {1, 1, 1e-3},    {1, 0.98, 0.02}, {1, 1, 1},       {0.5, 0.5, 0.5},
      {1, 1e-1, 1e-1}, {1, 1e-2, 1e-2},  {1, 1e-4, 1e-4}, {1, 1e-6, 1e-6}, {1, 1, 1e-6},    {1, 0.5, 0},
      {1, 0, 0},       {1, -0.5, 0.25},  {0.8, 0.3, -0.6}, {-0.2, -0.5, -1}, {-1, -1, -1},   {0, 0, 0}};
  const glm::dvec3 axes[] = {{0, 0, 1}, {1, 1, 0}, {0.3, -1, 0.6}};
  std::uint32_t id = 0;
  int row = 0;
  for (const glm::dvec3& axis : axes) {
    int col = 0;
    for (const glm::dvec3& l : shapes) {
      const glm::dvec3 p = positionScale * glm::dvec3(2.5 * col - 2.5 * 8.5, 2.5 * row - 2.5, 0.0);
      addSym(f, id++, p, fromEigen(eigenScale * l, rotation(20.0 + 35.0 * row, axis)));
      ++col;
    }
    ++row;
  }
  f.sampleSpacing = 2.5 * positionScale;
  return f;
}

io::TensorField randomField(std::size_t n, std::uint64_t seed) {
  io::TensorField f;
  const GridDims dims = gridDims(n);
  f.description = "random field";
  f.sampleSpacing = 1.0;
  RandomTensorStream rs(seed);
  float t6[6];
  for (std::size_t i = 0; i < n; ++i) {
    rs.next(t6);
    const double p[3] = {double(i % dims.x), double((i / dims.x) % dims.y), double(i / (dims.x * dims.y))};
    const double t[9] = {t6[0], t6[1], t6[2], t6[1], t6[3], t6[4], t6[2], t6[4], t6[5]};
    f.addFull(std::uint32_t(i), p, t);
  }
  return f;
}

}  // namespace tg::synth
