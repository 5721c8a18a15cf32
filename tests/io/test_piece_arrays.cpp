// Tier 2: XML VTK files whose pieces list their arrays differently (issue
// 30). VTK's readers fill a piece's arrays by position in the first
// piece's list: piece 2's "s" was drawn as the tensors "t", and a piece
// without "t" left its points' tensors as memory VTK never filled. Arrays
// are matched by name; a piece lacking the tensors is refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "io/io_test_util.h"
#include "io/core/readers.h"

using namespace tg;
namespace fs = std::filesystem;

namespace {

fs::path tmpDir() { return test::scratchDir("piece_arrays"); }

struct Array {
  std::string name;
  int components;
  double value;  // every component of every point
};

std::string dataArray(const Array& a, int points) {
  std::string s = "<DataArray type=\"Float64\" Name=\"" + a.name + "\" NumberOfComponents=\"" +
                  std::to_string(a.components) + "\" format=\"ascii\">";
  for (int i = 0; i < points * a.components; ++i) s += std::to_string(a.value + i / a.components) + " ";
  return s + "</DataArray>";
}

std::string pointData(const std::vector<Array>& arrays, int points, const std::string& tensors = "t") {
  std::string s = "<PointData" + (tensors.empty() ? std::string() : " Tensors=\"" + tensors + "\"") + ">";
  for (const Array& a : arrays) s += dataArray(a, points);
  return s + "</PointData>";
}

std::string points(int n, double x0) {
  std::string s = "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">";
  for (int i = 0; i < n; ++i) s += std::to_string(x0 + i) + " 0 0 ";
  return s + "</DataArray></Points>";
}

// Two points a piece, one vertex cell each.
std::string vtu(const std::vector<std::vector<Array>>& pieces, const std::vector<std::string>& tensors = {}) {
  std::string x = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n<UnstructuredGrid>\n";
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    x += "<Piece NumberOfPoints=\"2\" NumberOfCells=\"2\">" + points(2, 10.0 * double(p)) +
         pointData(pieces[p], 2, p < tensors.size() ? tensors[p] : "t") +
         "<Cells><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1</DataArray>"
         "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">1 2</DataArray>"
         "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">1 1</DataArray></Cells></Piece>\n";
  }
  return x + "</UnstructuredGrid>\n</VTKFile>\n";
}

std::string vtp(const std::vector<std::vector<Array>>& pieces) {
  std::string x = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\">\n<PolyData>\n";
  for (std::size_t p = 0; p < pieces.size(); ++p)
    x += "<Piece NumberOfPoints=\"2\">" + points(2, 10.0 * double(p)) + pointData(pieces[p], 2) + "</Piece>\n";
  return x + "</PolyData>\n</VTKFile>\n";
}

// Pieces of two points along x: 0..1, 2..3, ...
std::string structured(const char* type, const std::vector<std::vector<Array>>& pieces) {
  const std::string hi = std::to_string(2 * pieces.size() - 1);
  std::string x = std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"") + type + "\" version=\"0.1\">\n<" + type +
                  " WholeExtent=\"0 " + hi + " 0 0 0 0\"" +
                  (std::string(type) == "ImageData" ? " Origin=\"0 0 0\" Spacing=\"1 1 1\"" : "") + ">\n";
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    x += "<Piece Extent=\"" + std::to_string(2 * p) + " " + std::to_string(2 * p + 1) + " 0 0 0 0\">" +
         pointData(pieces[p], 2);
    if (std::string(type) == "StructuredGrid") x += points(2, 2.0 * double(p));
    x += "</Piece>\n";
  }
  return x + "</" + type + ">\n</VTKFile>\n";
}

// Piece p's tensors are diag-free 9-vectors of p + 1 (and + 1 for its second point).
void expectTensorsOfPieces(const io::TensorField& f, std::size_t pieces, const std::string& what) {
  ASSERT_EQ(f.size(), 2 * pieces) << what;
  for (std::size_t i = 0; i < f.size(); ++i)
    EXPECT_FLOAT_EQ(f.tensors[6 * i], float(i / 2 + 1 + i % 2)) << what << " point " << i;
}

}  // namespace

TEST(PieceArrays, ArraysInADifferentOrderInEachPieceAreMatchedByName) {
  const fs::path d = tmpDir();
  // s is tensor-shaped too, so that VTK's positional fill drew it silently.
  const std::vector<std::vector<Array>> pieces = {{{"t", 9, 1}, {"s", 9, 100}}, {{"s", 9, 200}, {"t", 9, 2}}};
  test::writeFile(d / "order.vtu", vtu(pieces));
  test::writeFile(d / "order.vtp", vtp(pieces));
  test::writeFile(d / "order.vti", structured("ImageData", pieces));
  test::writeFile(d / "order.vts", structured("StructuredGrid", pieces));
  for (const char* f : {"order.vtu", "order.vtp", "order.vti", "order.vts"})
    expectTensorsOfPieces(io::readTensorField((d / f).string(), {}), 2, f);
  io::ReadOptions s;
  s.arrayName = "s";
  const io::TensorField f = io::readTensorField((d / "order.vtu").string(), s);
  ASSERT_EQ(f.size(), 4u);
  EXPECT_FLOAT_EQ(f.tensors[6 * 2], 200.0f);
}

TEST(PieceArrays, IdenticalOrdersAndThreePiecesStillRead) {
  const fs::path d = tmpDir();
  const std::vector<std::vector<Array>> same = {
      {{"t", 9, 1}, {"s", 1, 5}}, {{"t", 9, 2}, {"s", 1, 6}}, {{"t", 9, 3}, {"s", 1, 7}}};
  test::writeFile(d / "same.vtu", vtu(same));
  expectTensorsOfPieces(io::readTensorField((d / "same.vtu").string(), {}), 3, "same.vtu");
  test::writeFile(d / "same.vti", structured("ImageData", same));
  expectTensorsOfPieces(io::readTensorField((d / "same.vti").string(), {}), 3, "same.vti");
}

TEST(PieceArrays, APieceWithoutTheTensorsIsRefusedInOneLine) {
  const fs::path d = tmpDir();
  test::writeFile(d / "missing.vtu", vtu({{{"t", 9, 1}, {"s", 1, 5}}, {{"s", 1, 6}}}));
  EXPECT_EQ(test::readError(d / "missing.vtu"),
            "readVtk: " + (d / "missing.vtu").string() +
                ": piece 2 of 2 has no point array \"t\" (piece 1 has it): VTK would leave its points' values unset");
  test::writeFile(d / "missing.vti", structured("ImageData", {{{"t", 9, 1}}, {{"u", 1, 1}}}));
  EXPECT_NE(test::readError(d / "missing.vti").find("piece 2 of 2 has no point array \"t\""), std::string::npos);
  // Only the last piece has it: VTK made no array of it at all.
  test::writeFile(d / "late.vtu", vtu({{{"s", 1, 5}}, {{"s", 1, 6}, {"t", 9, 2}}}));
  EXPECT_EQ(test::readError(d / "late.vtu"),
            "readVtk: " + (d / "late.vtu").string() + ": piece 1 of 2 has no point array \"t\" (piece 2 has it)");
}

// An array that is not the tensors may be missing from a piece: it is left
// unread, and the tensors read from every piece.
TEST(PieceArrays, APieceWithoutAnotherArrayReads) {
  const fs::path d = tmpDir();
  test::writeFile(d / "other.vtu", vtu({{{"s", 1, 5}, {"t", 9, 1}}, {{"t", 9, 2}}}));
  expectTensorsOfPieces(io::readTensorField((d / "other.vtu").string(), {}), 2, "other.vtu");
  test::writeFile(d / "extra.vtu", vtu({{{"t", 9, 1}}, {{"u", 1, 9}, {"t", 9, 2}}}));
  expectTensorsOfPieces(io::readTensorField((d / "extra.vtu").string(), {}), 2, "extra.vtu");
}

TEST(PieceArrays, PiecesThatDisagreeAboutAnArrayAreRefused) {
  const fs::path d = tmpDir();
  test::writeFile(d / "dup.vtu", vtu({{{"t", 9, 1}, {"t", 9, 5}}, {{"t", 9, 2}}}));
  EXPECT_EQ(test::readError(d / "dup.vtu"),
            "readVtk: " + (d / "dup.vtu").string() + ": piece 1 has two point arrays named \"t\"");
  test::writeFile(d / "comps.vtu", vtu({{{"t", 9, 1}}, {{"t", 6, 2}}}));
  EXPECT_EQ(test::readError(d / "comps.vtu"),
            "readVtk: " + (d / "comps.vtu").string() +
                ": piece 2's point array \"t\" has 6 components of type Float64, piece 1's has 9 of type Float64");
  test::writeFile(d / "active.vtu", vtu({{{"t", 9, 1}, {"s", 9, 1}}, {{"t", 9, 2}, {"s", 9, 2}}}, {"t", "s"}));
  EXPECT_EQ(test::readError(d / "active.vtu"),
            "readVtk: " + (d / "active.vtu").string() + ": pieces 1 and 2 name different point tensors (\"t\" and \"s\")");
}
