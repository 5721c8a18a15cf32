// Grids the readers refuse or warn about: singular NRRD and VTK image grids,
// a VTK image's non-finite SPACING or ORIGIN, and asymmetric 9-component
// VTK tensors (warned about as NRRD's 3D-matrix ones are).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "io/io_test_util.h"
#include "io/core/readers.h"

using namespace tg;
namespace fs = std::filesystem;

namespace {

fs::path tmpDir() { return test::scratchDir("grid-checks"); }

std::string nrrd(const std::string& sizes, const std::string& geometry, int voxels) {
  std::string s = "NRRD0005\ntype: float\ndimension: 4\nsizes: " + sizes +
                  "\nencoding: raw\nendian: little\nkinds: 3D-symmetric-matrix domain domain domain\n" + geometry + "\n\n";
  const std::vector<float> v(std::size_t(6 * voxels), 1.0f);
  return s + std::string(reinterpret_cast<const char*>(v.data()), 4 * v.size());
}

std::string structuredPoints(const std::string& dims, const std::string& spacing, const std::string& origin,
                             int points) {
  std::string s = "# vtk DataFile Version 3.0\ng\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS " + dims +
                  "\nSPACING " + spacing + "\nORIGIN " + origin + "\nPOINT_DATA " + std::to_string(points) +
                  "\nTENSORS t float\n";
  for (int i = 0; i < points; ++i) s += "1 0 0 0 1 0 0 0 1\n";
  return s;
}

void expectRefused(const fs::path& p, const std::string& what) {
  const std::string e = test::readError(p);
  EXPECT_NE(e.find(what), std::string::npos) << p << ": " << e;
  EXPECT_NE(e.find(p.string()), std::string::npos) << p << ": " << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << p << ": " << e;
}

}  // namespace

TEST(GridChecks, SingularNrrdGridsAreRefused) {
  const fs::path d = tmpDir();
  const std::string space = "space: RAS\n";
  const struct {
    const char* file;
    std::string bytes;
    std::string expect;
  } cases[] = {
      {"zero-dir.nrrd", nrrd("6 2 2 2", space + "space directions: none (1,0,0) (0,0,0) (0,0,1)", 8),
       "readNrrd: " + (d / "zero-dir.nrrd").string() + ": the space directions are singular"},
      {"parallel.nrrd", nrrd("6 2 2 2", space + "space directions: none (1,0,0) (0,1,0) (0.1,0.2,0)", 8),
       "the space directions are singular"},
      // Teem refuses a spacing of 0 itself.
      {"spacing0.nrrd", nrrd("6 2 2 2", "spacings: NaN 1 0 1", 8), "spacing (0) invalid"},
      {"minmax.nrrd", nrrd("6 2 2 2", "axis mins: NaN 0 0 5\naxis maxs: NaN 1 1 5", 8), "the axis spacings are singular"},
  };
  for (const auto& c : cases) {
    test::writeFile(d / c.file, c.bytes);
    expectRefused(d / c.file, c.expect);
  }
}

// A slice's one-sample axis is never stepped along: its direction may be zero.
TEST(GridChecks, NrrdSliceWithAZeroSingletonDirectionReads) {
  const fs::path p = tmpDir() / "slice.nrrd";
  test::writeFile(p, nrrd("6 2 2 1", "space: RAS\nspace directions: none (1,0,0) (0,1,0) (0,0,0)", 4));
  EXPECT_EQ(io::readTensorField(p.string(), {}).size(), 4u);
}

TEST(GridChecks, VtkImageWithAZeroSpacingIsRefused) {
  const fs::path d = tmpDir();
  test::writeFile(d / "spacing0.vtk", structuredPoints("2 2 2", "1 0 1", "0 0 0", 8));
  expectRefused(d / "spacing0.vtk", "readVtk: " + (d / "spacing0.vtk").string() + ": the image spacing is singular");
  test::writeFile(d / "spacing0.vti",
                  "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"0.1\">\n"
                  "<ImageData WholeExtent=\"0 1 0 1 0 1\" Origin=\"0 0 0\" Spacing=\"1 1 0\">\n"
                  "<Piece Extent=\"0 1 0 1 0 1\"><PointData Tensors=\"t\">"
                  "<DataArray type=\"Float32\" Name=\"t\" NumberOfComponents=\"9\" format=\"ascii\">" +
                      [] {
                        std::string s;
                        for (int i = 0; i < 8; ++i) s += "1 0 0 0 1 0 0 0 1 ";
                        return s;
                      }() +
                      "</DataArray></PointData></Piece>\n</ImageData>\n</VTKFile>\n");
  expectRefused(d / "spacing0.vti", "the image spacing is singular");
  // A 2-D image's single plane may have spacing 0 along its normal.
  test::writeFile(d / "flat.vtk", structuredPoints("2 2 1", "1 1 0", "0 0 0", 4));
  EXPECT_EQ(io::readTensorField((d / "flat.vtk").string(), {}).size(), 4u);
}

// VTK stops reading at the word and finds no arrays: the message was "no
// point tensors".
TEST(GridChecks, VtkNonFiniteSpacingOrOriginIsSaidSo) {
  const fs::path d = tmpDir();
  const struct {
    const char* file;
    std::string bytes;
    const char* expect;
  } cases[] = {
      {"spacing-nan.vtk", structuredPoints("2 1 1", "nan 1 1", "0 0 0", 2), "SPACING: nan is not finite"},
      {"origin-inf.vtk", structuredPoints("2 1 1", "1 1 1", "inf 0 0", 2), "ORIGIN: inf is not finite"},
      {"origin-big.vtk", structuredPoints("2 1 1", "1 1 1", "0 -1e999 0", 2), "ORIGIN: -1e999 is not finite"},
  };
  for (const auto& c : cases) {
    test::writeFile(d / c.file, c.bytes);
    expectRefused(d / c.file, c.expect);
  }
}

// As NRRD's 3D-matrix tensors: drawn symmetrised, with one warning saying so.
TEST(GridChecks, AsymmetricVtkTensorsAreSymmetrisedWithAWarning) {
  const fs::path d = tmpDir();
  const std::string legacy = "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 2 float\n0 0 0 1 0 0\n"
                             "POINT_DATA 2\nTENSORS t float\n1 0 0 0 1 0 0 0 1\n1 0.2 0 0.4 2 0 0 0 3\n";
  test::writeFile(d / "asym.vtk", legacy);
  test::writeFile(d / "asym.vtp",
                  "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\">\n<PolyData>\n"
                  "<Piece NumberOfPoints=\"2\"><Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" "
                  "format=\"ascii\">0 0 0 1 0 0</DataArray></Points><PointData Tensors=\"t\">"
                  "<DataArray type=\"Float32\" Name=\"t\" NumberOfComponents=\"9\" format=\"ascii\">"
                  "1 0 0 0 1 0 0 0 1 1 0.2 0 0.4 2 0 0 0 3</DataArray></PointData></Piece>\n</PolyData>\n</VTKFile>\n");
  for (const char* name : {"asym.vtk", "asym.vtp"}) {
    const io::TensorField f = io::readTensorField((d / name).string(), {});
    ASSERT_EQ(f.size(), 2u) << name;
    EXPECT_FLOAT_EQ(f.tensors[6 + 1], 0.3f) << name;
    ASSERT_EQ(f.warnings.size(), 1u) << name;
    EXPECT_NE(f.warnings[0].find("9-component tensors are asymmetric (max |D - Dᵀ| / |D| = 0.066667"), std::string::npos)
        << f.warnings[0];
  }
  // Asymmetry within 1e-3 (a writer's rounding) is no news.
  std::string slight = legacy;
  slight.replace(slight.find("0.4 2"), 5, "0.2002 2");
  test::writeFile(d / "slight.vtk", slight);
  EXPECT_TRUE(io::readTensorField((d / "slight.vtk").string(), {}).warnings.empty());
}
