// Tier 2: legacy VTK ASCII numbers with trailing characters (issue 30).
// VTK's reader streams them: "1,5" read as 1 and ",5" as the next keyword,
// so the file was refused as having no point tensors, or read on with the
// prefix where the rest happened to parse. Each is now refused by its line.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/io_test_util.h"
#include "io/core/readers.h"

using namespace tg;
namespace fs = std::filesystem;

namespace {

fs::path tmpDir() { return test::scratchDir("vtk_text"); }

std::string legacy(const std::string& spacing, const std::string& lastValue) {
  return "# vtk DataFile Version 3.0\nx\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2 1 1\nORIGIN 0 0 0\nSPACING " +
         spacing + "\nPOINT_DATA 2\nTENSORS t float\n1 0 0 0 1 0 0 0 1\n1 0 0 0 1 0 0 0 " + lastValue + "\n";
}

}  // namespace

TEST(VtkText, LegacyNumbersWithTrailingCharactersAreRefusedByLine) {
  const fs::path p = tmpDir() / "t.vtk";
  const struct {
    std::string spacing, last, problem;
  } cases[] = {
      {"1,5 1 1", "1", "line 7: \"1,5\" is not a number"},
      {"1 1 1.5x", "1", "line 7: \"1.5x\" is not a number"},
      {"1 1 1", "3,5", "line 11: \"3,5\" is not a number"},
      {"1 1 1", "1.5abc", "line 11: \"1.5abc\" is not a number"},
      {"1 1 1", "0x10", "line 11: \"0x10\" is not a number"},
  };
  for (const auto& c : cases) {
    test::writeFile(p, legacy(c.spacing, c.last));
    EXPECT_EQ(test::readError(p), "readVtk: " + p.string() + ": " + c.problem) << c.spacing << " / " << c.last;
  }
  test::writeFile(p, legacy("1 1 1", "1") + "FIELD f 1\n2d 1 2 float\n0 1\n");  // a name may begin with a digit
  EXPECT_EQ(test::readError(p), "");
  test::writeFile(p, legacy("+1.5 1E0 1", "-0.5e1"));
  const io::TensorField f = io::readTensorField(p.string(), {});
  ASSERT_EQ(f.size(), 2u);
  EXPECT_FLOAT_EQ(f.positions[3], 1.5f);
  EXPECT_FLOAT_EQ(f.tensors[11], -5.0f);
}

// XML ascii arrays too: VTK's stream read the last value "1.5abc" as 1.5.
TEST(VtkText, XmlAsciiWordsAreReadWhole) {
  auto vtu = [](const std::string& last, const std::string& connectivity) {
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n<UnstructuredGrid>\n"
           "<Piece NumberOfPoints=\"1\" NumberOfCells=\"1\"><Points><DataArray type=\"Float32\" "
           "NumberOfComponents=\"3\" format=\"ascii\">0 0 0</DataArray></Points><PointData Tensors=\"t\">"
           "<DataArray type=\"Float32\" Name=\"t\" NumberOfComponents=\"9\" format=\"ascii\">1 0 0 0 1 0 0 0 " +
           last + "</DataArray></PointData><Cells><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">" +
           connectivity + "</DataArray><DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">1</DataArray>"
           "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">1</DataArray></Cells></Piece>\n"
           "</UnstructuredGrid>\n</VTKFile>\n";
  };
  const fs::path p = tmpDir() / "t.vtu";
  test::writeFile(p, vtu("1.5abc", "0"));
  EXPECT_EQ(test::readError(p), "readVtk: " + p.string() + ": ascii array \"t\" holds \"1.5abc\", which is not a number");
  test::writeFile(p, vtu("1", "0.5"));
  EXPECT_EQ(test::readError(p),
            "readVtk: " + p.string() + ": ascii array \"connectivity\" holds \"0.5\", which is not an integer");
  test::writeFile(p, vtu("+1.5e0", "+0"));
  const io::TensorField f = io::readTensorField(p.string(), {});
  ASSERT_EQ(f.size(), 1u);
  EXPECT_FLOAT_EQ(f.tensors[5], 1.5f);
}

// And XML attributes, which VTK reads with a stream as well: Origin="0 0
// 1,5" placed the grid at z = 1, NumberOfComponents="9x" read as 9.
TEST(VtkText, XmlNumericAttributesAreReadWhole) {
  auto vti = [](const std::string& origin, const std::string& components) {
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"0.1\">\n<ImageData WholeExtent=\"0 1 0 0 0 0\" "
           "Origin=\"" + origin + "\" Spacing=\"1 1 1\">\n<Piece Extent=\"0 1 0 0 0 0\"><PointData Tensors=\"t\">"
           "<DataArray type=\"Float32\" Name=\"t\" NumberOfComponents=\"" + components + "\" format=\"ascii\">"
           "1 0 0 0 1 0 0 0 1 1 0 0 0 1 0 0 0 1</DataArray></PointData></Piece>\n</ImageData>\n</VTKFile>\n";
  };
  const fs::path p = tmpDir() / "t.vti";
  test::writeFile(p, vti("0 0 1,5", "9"));
  EXPECT_EQ(test::readError(p), "readVtk: " + p.string() +
                                    ": ImageData attribute Origin=\"0 0 1,5\" holds \"1,5\", which is not a number");
  test::writeFile(p, vti("0 0 1.5", "9x"));
  EXPECT_EQ(test::readError(p), "readVtk: " + p.string() +
                                    ": DataArray attribute NumberOfComponents=\"9x\" holds \"9x\", which is not an integer");
  test::writeFile(p, vti("+0 -0 1.5e0", "9"));
  const io::TensorField f = io::readTensorField(p.string(), {});
  ASSERT_EQ(f.size(), 2u);
  EXPECT_FLOAT_EQ(f.positions[2], 1.5f);
}
