// Six-component stress arrays in FEM orders (issue 31): Kirsch's plate with
// a hole written as Abaqus writes S (S11 S22 S33 S12 S13 S23) to a VTK file.
// --layout abaqus reads the analytic principal stresses; without it, VTK's
// own order (XX YY ZZ XY YZ XZ) is refused where it is implausible and one
// other reading is plausible, and taken where it reads the same tensors.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "io/io_test_util.h"
#include "io/core/readers.h"
#include "tensor/eigen.h"

namespace fs = std::filesystem;
namespace io = tg::io;
namespace test = tg::test;

namespace {

fs::path dir() { return test::scratchDir("fem_layouts"); }

constexpr double kLoad = 100;  // MPa, uniaxial along the plate's first axis
constexpr double kHole = 1;    // radius

// Kirsch (1898): in-plane stress of an infinite plate under uniaxial tension
// kLoad along u, around a hole of radius kHole, at (u, v); {s_uu, s_vv, s_uv}.
std::array<double, 3> kirsch(double u, double v) {
  const double r = std::hypot(u, v), t = std::atan2(v, u), q = kHole * kHole / (r * r);
  const double c2 = std::cos(2 * t), s2 = std::sin(2 * t);
  const double rr = kLoad / 2 * (1 - q) + kLoad / 2 * (1 - 4 * q + 3 * q * q) * c2;
  const double tt = kLoad / 2 * (1 + q) - kLoad / 2 * (1 + 3 * q * q) * c2;
  const double rt = -kLoad / 2 * (1 + 2 * q - 3 * q * q) * s2;
  const double c = std::cos(t), s = std::sin(t);
  return {rr * c * c + tt * s * s - 2 * rt * s * c, rr * s * s + tt * c * c + 2 * rt * s * c,
          (rr - tt) * s * c + rt * (c * c - s * s)};
}

struct Plate {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<double, 6>> abaqus;  // S11 S22 S33 S12 S13 S23
  std::vector<std::array<double, 3>> principal;  // analytic, descending
};

// Points on rings around the hole in the plane spanned by axes `a` and `b`
// (u along a, v along b), the third coordinate 0.
Plate plate(int a, int b) {
  Plate p;
  for (int ring = 0; ring < 12; ++ring)
    for (int k = 0; k < 48; ++k) {
      const double r = kHole * (1 + 0.25 * ring), t = 2 * M_PI * (k + 0.5) / 48;
      const double u = r * std::cos(t), v = r * std::sin(t);
      const auto [suu, svv, suv] = kirsch(u, v);
      std::array<double, 3> x{0, 0, 0};
      x[std::size_t(a)] = u, x[std::size_t(b)] = v;
      double full[3][3] = {};
      full[a][a] = suu, full[b][b] = svv, full[a][b] = full[b][a] = suv;
      p.points.push_back(x);
      p.abaqus.push_back({full[0][0], full[1][1], full[2][2], full[0][1], full[0][2], full[1][2]});
      const double mean = (suu + svv) / 2, rad = std::hypot((suu - svv) / 2, suv);
      std::array<double, 3> e{mean + rad, mean - rad, 0};
      std::sort(e.begin(), e.end(), std::greater<>());
      p.principal.push_back(e);
    }
  return p;
}

fs::path writeVtu(const std::string& name, const Plate& p) {
  const fs::path f = dir() / name;
  std::ofstream o(f);
  o.precision(17);
  o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
       "<UnstructuredGrid><Piece NumberOfPoints=\""
    << p.points.size() << "\" NumberOfCells=\"0\">\n<PointData>\n"
    << "<DataArray type=\"Float64\" Name=\"S\" NumberOfComponents=\"6\" format=\"ascii\">";
  for (const auto& s : p.abaqus)
    for (double v : s) o << v << " ";
  o << "</DataArray>\n</PointData>\n<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">";
  for (const auto& x : p.points) o << x[0] << " " << x[1] << " " << x[2] << " ";
  o << "</DataArray></Points>\n<Cells><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\"></DataArray>"
       "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\"></DataArray>"
       "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\"></DataArray></Cells>\n"
       "</Piece></UnstructuredGrid></VTKFile>\n";
  return f;
}

io::ReadOptions layout(const std::string& name) {
  io::ReadOptions o;
  o.layout = name;
  return o;
}

// The largest difference between the field's principal stresses and Kirsch's.
double worstPrincipalError(const io::TensorField& f, const Plate& p) {
  EXPECT_EQ(f.size(), p.points.size());
  double worst = 0;
  for (std::size_t i = 0; i < f.size() && i < p.points.size(); ++i) {
    const float* t = &f.tensors[6 * i];
    const auto e = tg::tensor::eigensolve({t[0], t[1], t[2], t[3], t[4], t[5]});
    for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(e.values[k] - p.principal[i][std::size_t(k)]));
  }
  return worst;
}

}  // namespace

TEST(FemLayouts, AnAbaqusPlateReadsItsAnalyticPrincipalStresses) {
  for (const auto& [a, b, name] : {std::tuple{0, 1, "xy"}, std::tuple{0, 2, "xz"}, std::tuple{1, 2, "yz"}}) {
    const Plate p = plate(a, b);
    const fs::path f = writeVtu(std::string("kirsch-") + name + ".vtu", p);
    const io::TensorField read = io::readTensorField(f.string(), layout("abaqus"));
    EXPECT_TRUE(read.warnings.empty()) << name << ": " << read.warnings[0];
    EXPECT_LT(worstPrincipalError(read, p), 1e-4 * kLoad) << name;
    EXPECT_NE(read.layout.find("abaqus: S11 S22 S33 S12 S13 S23"), std::string::npos) << read.layout;
    // The hole's edge at u = ±a is compressed by the load: the third
    // principal stress spans [-kLoad, 0] (Kirsch's concentration factor 3 on the first).
    double third = 0, first = 0;
    for (std::size_t i = 0; i < read.size(); ++i) {
      const float* t = &read.tensors[6 * i];
      const auto e = tg::tensor::eigensolve({t[0], t[1], t[2], t[3], t[4], t[5]});
      third = std::min(third, e.values[2]), first = std::max(first, e.values[0]);
    }
    EXPECT_NEAR(third, -kLoad, 0.02 * kLoad) << name;
    EXPECT_NEAR(first, 3 * kLoad, 0.03 * kLoad) << name;
    // Voigt's order (xx yy zz yz xz xy) swaps xy and yz: on the x-y plate it
    // puts the in-plane shear out of the plane, and says so.
    if (a == 0 && b == 1) {
      const io::TensorField voigt = io::readTensorField(f.string(), layout("voigt"));
      ASSERT_EQ(voigt.warnings.size(), 1u);
      EXPECT_NE(voigt.warnings[0].find("out-of-plane shear"), std::string::npos) << voigt.warnings[0];
      EXPECT_NE(voigt.warnings[0].find("try --layout abaqus (or vtk, paraview: the same tensors here)"), std::string::npos)
          << voigt.warnings[0];
    }
  }
}

TEST(FemLayouts, WithoutALayoutVtksOrderIsTakenOnlyWhereItIsPlausible) {
  // x-y plate: S13 = S23 = 0, so VTK's order reads the same tensors as
  // Abaqus's; nothing to refuse, and the stresses are right.
  const Plate xy = plate(0, 1);
  const io::TensorField same = io::readTensorField(writeVtu("default-xy.vtu", xy).string(), {});
  EXPECT_TRUE(same.warnings.empty());
  EXPECT_LT(worstPrincipalError(same, xy), 1e-4 * kLoad);
  // x-z and y-z plates: VTK's order moves S13 or S23 to an out-of-plane
  // shear, and the principal stresses are no longer Kirsch's. Abaqus's is
  // the one plausible reading (Voigt's agrees with it on the x-z plate):
  // refused, naming the file, the array, the layout and the way to keep VTK's.
  struct Case {
    int a, b;
    const char* name;
    const char* names;
  } cases[] = {{0, 2, "xz", "only --layout abaqus (or voigt: the same tensors here) reads them plausibly"},
               {1, 2, "yz", "only --layout abaqus reads them plausibly"}};
  for (const Case& c : cases) {
    const fs::path f = writeVtu(std::string("default-") + c.name + ".vtu", plate(c.a, c.b));
    const std::string e = test::readError(f);
    EXPECT_NE(e.find(f.string() + ": array \"S\": "), std::string::npos) << e;
    EXPECT_NE(e.find("out-of-plane shear"), std::string::npos) << e;
    EXPECT_NE(e.find(c.names), std::string::npos) << e;
    EXPECT_NE(e.find("or --layout vtk to draw this reading"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    // Named, VTK's order is drawn, with a warning that names Abaqus's.
    const io::TensorField asked = io::readTensorField(f.string(), layout("paraview"));
    ASSERT_EQ(asked.warnings.size(), 1u) << c.name;
    EXPECT_NE(asked.warnings[0].find("try --layout abaqus"), std::string::npos) << asked.warnings[0];
  }
}

TEST(FemLayouts, AThreeDimensionalFieldHasNoCriterionAndIsNotGuessed) {
  // Off a plane nothing tells a stress field's order: read as asked or as
  // VTK's, without a word either way.
  Plate p = plate(0, 1);
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    p.points[i][2] = 0.1 * double(i % 7);
    p.abaqus[i][4] = 5 + double(i % 3);  // S13
  }
  const fs::path f = writeVtu("solid.vtu", p);
  EXPECT_TRUE(io::readTensorField(f.string(), {}).warnings.empty());
  EXPECT_TRUE(io::readTensorField(f.string(), layout("abaqus")).warnings.empty());
}

TEST(FemLayouts, LayoutNamesAreCheckedAgainstTheInput) {
  const fs::path f = writeVtu("names.vtu", plate(0, 1));
  EXPECT_NE(test::readError(f, layout("fsl")).find("--layout fsl does not apply to VTK; choose vtk, paraview, abaqus or "
                                                   "voigt"),
            std::string::npos);
}
