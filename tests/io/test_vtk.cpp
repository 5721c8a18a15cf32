// Tier 2: VTK input through VTK's readers, round trips and bad input.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <filesystem>
#include <fstream>

#include "data-synthetic/generators.h"
#include "io/core/readers.h"
#include "io/io_test_util.h"
#include "io/core/writers.h"

using namespace tg;
namespace fs = std::filesystem;

namespace {

fs::path tmpDir() { return test::scratchDir("vtk"); }

std::string errorOf(const fs::path& p, const io::ReadOptions& o = {}) { return test::readError(p, o); }

}  // namespace

TEST(Vtk, RoundTripEveryFormat) {
  const auto h = synth::helixPhantom(6, 5, 4);
  for (const char* ext : {".vtk", ".vti", ".vtu", ".vtp"}) {
    const fs::path p = tmpDir() / (std::string("helix") + ext);
    io::writeVtk(h.field, p.string());
    const io::TensorField f = io::readTensorField(p.string(), {});
    ASSERT_EQ(f.size(), h.field.size()) << ext;
    for (std::size_t i = 0; i < f.size(); ++i) {
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(f.positions[3 * i + k], h.field.positions[3 * i + k], 1e-4) << ext;
      for (int k = 0; k < 6; ++k) ASSERT_EQ(f.tensors[6 * i + k], h.field.tensors[6 * i + k]) << ext;
    }
    if (std::string(ext) == ".vti") {
      ASSERT_TRUE(f.grid);
      EXPECT_NEAR(f.grid->directions[1], h.field.grid->directions[1], 1e-12);  // Direction survives
      EXPECT_DOUBLE_EQ(f.sampleSpacing, 1.0);
    }
  }
}

// A binary legacy file's arrays can hold bytes that read as a header line
// ("\nA\x01 -5 -5 float\n" here, four big-endian floats of the positions):
// the header checks skip them, and the file reads back exactly. Before, such
// bytes in a 2-million-point file from `synth random` were refused as
// "negative count".
TEST(Vtk, BinaryArraysThatSpellAHeaderLineRead) {
  io::TensorField src = synth::randomField(4, 3);
  const unsigned char spell[16] = {'\n', 'A', 0x01, ' ', '-', '5', ' ', '-', '5', ' ', 'f', 'l', 'o', 'a', 't', '\n'};
  for (int k = 0; k < 4; ++k) {
    const std::uint32_t bits = std::uint32_t(spell[4 * k]) << 24 | std::uint32_t(spell[4 * k + 1]) << 16 |
                               std::uint32_t(spell[4 * k + 2]) << 8 | std::uint32_t(spell[4 * k + 3]);
    float f;
    std::memcpy(&f, &bits, 4);
    src.positions[std::size_t(k)] = f;
  }
  const fs::path p = tmpDir() / "spelled.vtk";
  io::writeVtk(src, p.string());
  const io::TensorField f = io::readTensorField(p.string(), {});
  ASSERT_EQ(f.size(), src.size());
  for (std::size_t i = 0; i < 3 * f.size(); ++i) EXPECT_EQ(f.positions[i], src.positions[i]) << i;
}

TEST(Vtk, NaNTensorsAreSkippedAndCounted) {
  io::TensorField src = synth::randomField(5, 2);
  src.tensors[6 * 1 + 2] = std::numeric_limits<float>::quiet_NaN();
  src.tensors[6 * 3 + 0] = std::numeric_limits<float>::infinity();
  const fs::path p = tmpDir() / "nan.vtu";
  io::writeVtk(src, p.string());
  const io::TensorField f = io::readTensorField(p.string(), {});
  EXPECT_EQ(f.size(), 3u);
  EXPECT_EQ(f.skippedNonFinite, 2u);
  EXPECT_EQ(f.ids[1], 2u);
}

// VTK's ASCII writer prints NaN and Inf as "nan" and "inf", which its own
// reader cannot parse. Such files read, with those tensors skipped, and every
// other value exactly as written, in float and double arrays, including a
// value equal to the first sentinel the reader would otherwise use.
TEST(Vtk, LegacyAsciiWithNanAndInfReads) {
  for (const char* type : {"float", "double"}) {
    const fs::path p = tmpDir() / (std::string("nan-ascii-") + type + ".vtk");
    test::writeFile(p, std::string("# vtk DataFile Version 3.0\nnan\nASCII\nDATASET POLYDATA\nPOINTS 5 float\n"
                                   "0 0 0 1 0 0 2 0 0 3 0 0 nan 0 0\nPOINT_DATA 5\nTENSORS t ") + type +
                           "\n1.17549435e-37 0 0 0 1 0 0 0 1\n-inf 0 0 0 1 0 0 0 1\n2 0 0 0 1 0 0 0 3\n"
                           "NaN 0 0 0 1 0 0 0 1\n1 0 0 0 1 0 0 0 1\n");
    const io::TensorField f = io::readTensorField(p.string(), {});
    ASSERT_EQ(f.size(), 2u) << type;
    EXPECT_EQ(f.skippedNonFinite, 3u) << type;
    EXPECT_EQ(f.ids[0], 0u);
    EXPECT_EQ(f.ids[1], 2u);
    EXPECT_EQ(f.tensors[0], 1.17549435e-37f) << type;
    EXPECT_EQ(f.tensors[6 + 0], 2.0f);
    EXPECT_EQ(f.tensors[6 + 5], 3.0f);
    EXPECT_EQ(f.positions[3], 2.0f) << "the third point: its own x, not a sentinel";
  }
}

TEST(Vtk, SixComponentsInVtkOrder) {
  const fs::path p = tmpDir() / "six.vtk";
  test::writeFile(p,
            "# vtk DataFile Version 3.0\nsix\nASCII\nDATASET POLYDATA\nPOINTS 2 float\n0 0 0 1 0 0\n"
            "POINT_DATA 2\nFIELD f 1\nsym 6 2 float\n1 2 3 4 5 6\n1 1 1 0 0 0\n");
  const io::TensorField f = io::readTensorField(p.string(), {});
  ASSERT_EQ(f.size(), 2u);
  // XX YY ZZ XY YZ XZ -> xx xy xz yy yz zz
  const float expect[6] = {1, 4, 6, 2, 5, 3};
  for (int k = 0; k < 6; ++k) EXPECT_EQ(f.tensors[k], expect[k]);
}

TEST(Vtk, FullTensorsAreSymmetrised) {
  const fs::path p = tmpDir() / "full.vtk";
  test::writeFile(p, "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 1 float\n0 0 0\n"
               "POINT_DATA 1\nTENSORS t float\n1 2 0\n4 1 0\n0 0 1\n");
  const io::TensorField f = io::readTensorField(p.string(), {});
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f.tensors[1], 3.0f);
}

TEST(Vtk, BadInputGetsOneLineNamingFileAndProblem) {
  const fs::path d = tmpDir();
  test::writeFile(d / "empty.vtk", "");
  test::writeFile(d / "garbage.vtk", "this is not a vtk file at all\n");
  test::writeFile(d / "fourcomp.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 1 float\n0 0 0\n"
                                "POINT_DATA 1\nFIELD f 1\nq 4 1 float\n1 2 3 4\n");
  test::writeFile(d / "huge.vtk", "# vtk DataFile Version 3.0\nx\nBINARY\nDATASET POLYDATA\nPOINTS 99999999999 float\n");
  test::writeFile(d / "hugexml.vtu",
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n<UnstructuredGrid>\n"
            "<Piece NumberOfPoints=\"999999999999\" NumberOfCells=\"0\">\n<Points><DataArray type=\"Float32\" "
            "NumberOfComponents=\"3\" format=\"ascii\">0 0 0</DataArray></Points>\n<Cells>"
            "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\"></DataArray>"
            "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\"></DataArray>"
            "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\"></DataArray></Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
  test::writeFile(d / "data.xyz", "1 2 3\n");
  // A valid binary file cut in half.
  io::writeVtk(synth::helixPhantom(6, 6, 6).field, (d / "whole.vtk").string());
  {
    const auto size = fs::file_size(d / "whole.vtk");
    fs::copy_file(d / "whole.vtk", d / "truncated.vtk", fs::copy_options::overwrite_existing);
    fs::resize_file(d / "truncated.vtk", size / 2);
  }
  const std::pair<const char*, const char*> cases[] = {
      {"missing.vtk", "no such file"}, {"empty.vtk", "empty"},           {"garbage.vtk", "garbage.vtk"},
      {"fourcomp.vtk", "4 components"}, {"huge.vtk", "exceeds the file size"}, {"hugexml.vtu", "points"},
      {"data.xyz", "unknown extension"}, {"truncated.vtk", "truncated.vtk"}, {"", "is a directory"}};
  for (const auto& [name, what] : cases) {
    const std::string msg = errorOf(d / name);
    EXPECT_NE(msg.find(what), std::string::npos) << name << ": \"" << msg << "\"";
    EXPECT_EQ(msg.find('\n'), std::string::npos) << name << ": " << msg;
    EXPECT_NE(msg.find((d / name).string()), std::string::npos) << "message names the file: " << msg;
  }
}

// Array names longer than VTK's legacy reader takes (255 bytes) get one
// line that says so: the name was cut and its tail read as the data type,
// reported as "no point tensors". 255 bytes still read.
TEST(Vtk, LegacyNamesBeyondVtksLimitAreNamedAsTheProblem) {
  const fs::path d = tmpDir();
  const auto file = [](const std::string& attribute) {
    return "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 1 float\n0 0 0\nPOINT_DATA 1\n" +
           attribute + "3 0 0 0 1 0 0 0 0.5\n";
  };
  test::writeFile(d / "t256.vtk", file("TENSORS " + std::string(256, 't') + " float\n"));
  test::writeFile(d / "f300.vtk", file("FIELD f 1\n" + std::string(300, 'q') + " 9 1 float\n"));
  test::writeFile(d / "field300.vtk", file("FIELD " + std::string(300, 'g') + " 1\nq 9 1 float\n"));
  for (const char* name : {"t256.vtk", "f300.vtk", "field300.vtk"}) {
    const std::string msg = errorOf(d / name);
    EXPECT_NE(msg.find("VTK's legacy reader takes at most 255"), std::string::npos) << name << ": " << msg;
    EXPECT_NE(msg.find((d / name).string()), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
  test::writeFile(d / "t255.vtk", file("TENSORS " + std::string(255, 't') + " float\n"));
  io::ReadOptions o;
  o.arrayName = std::string(255, 't');
  EXPECT_EQ(io::readTensorField((d / "t255.vtk").string(), o).tensors.size(), 6u);
}

// VTK's ASCII reader never returns from a run of 256 spaces between numbers
// and the next keyword or the end: such a file fails at once, in one line
// that says where, not after the 3 s limit. Runs it reads past still read.
TEST(Vtk, LegacySpaceRunsVtkCannotPassFailAtOnce) {
  const fs::path d = tmpDir();
  const std::string head = "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 2 float\n0 0 0\n1 0 0";
  const std::string data = "\nPOINT_DATA 2\nTENSORS t float\n3 0 0 0 1 0 0 0 0.5\n3 0 0 0 1 0 0 0 0.5";
  const std::string run(300, ' ');
  const std::pair<const char*, std::string> stuck[] = {{"trailing.vtk", head + run + data + "\n"},
                                                       {"blank.vtk", head + "\n" + run + data + "\n"},
                                                       {"leading.vtk", head + "\n" + run + data.substr(1) + "\n"},
                                                       {"atend.vtk", head + data + "\n" + run + "\n"}};
  for (const auto& [name, text] : stuck) {
    test::writeFile(d / name, text);
    const auto t0 = std::chrono::steady_clock::now();
    const std::string msg = errorOf(d / name);
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(2)) << name;
    EXPECT_NE(msg.find("a run of 256 or more spaces"), std::string::npos) << name << ": " << msg;
    EXPECT_NE(msg.find((d / name).string()), std::string::npos) << msg;
  }
  const std::pair<const char*, std::string> fine[] = {
      {"split.vtk", head + std::string(100, ' ') + "\n" + std::string(200, ' ') + data + "\n"},
      {"inside.vtk", head + data.substr(0, data.rfind('\n')) + run + data.substr(data.rfind('\n')) + "\n"},
      {"tabs.vtk", head + std::string(300, '\t') + data + "\n"},
      {"short.vtk", head + std::string(255, ' ') + data + "\n"}};
  for (const auto& [name, text] : fine) {
    SCOPED_TRACE(name);
    test::writeFile(d / name, text);
    EXPECT_EQ(io::readTensorField((d / name).string(), {}).tensors.size(), 12u);
  }
}

// 3D-TSV's trailer rows are Sxx Syy Szz Syz Szx Sxy; a row with a seventh
// number (or anything else after the sixth) is another layout, refused
// rather than read by its first six.
TEST(Vtk, TsvTrailerRowsHoldSixNumbers) {
  const std::string head = "# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 2 float\n"
                           "0 0 0 1 0 0\nCELLS 1 3\n2 0 1\nCELL_TYPES 1\n3\nPOINT_DATA 2\nSCALARS fixed int\n"
                           "LOOKUP_TABLE default\n0\n1\nCartesian Stress: 2\n";
  const fs::path d = tmpDir();
  test::writeFile(d / "tsv.vtk", head + "1 2 3 0.4 0.5 0.6 \t\r\n-1 -2 -3 0 0 0\n");
  const io::TensorField f = io::readTensorField((d / "tsv.vtk").string(), {});
  ASSERT_EQ(f.size(), 2u);
  // xx xy xz yy yz zz from Sxx=1 Syy=2 Szz=3 Syz=0.4 Szx=0.5 Sxy=0.6.
  const float expect[6] = {1, 0.6f, 0.5f, 2, 0.4f, 3};
  for (int k = 0; k < 6; ++k) EXPECT_FLOAT_EQ(f.tensors[std::size_t(k)], expect[k]) << k;
  for (const char* row : {"1 2 3 0.4 0.5 0.6 0.7", "1 2 3 0.4 0.5 0.6x"}) {
    test::writeFile(d / "tsv7.vtk", head + row + "\n-1 -2 -3 0 0 0\n");
    const std::string msg = errorOf(d / "tsv7.vtk");
    // A number with more after it is not read by its prefix either (issue 30).
    EXPECT_NE(msg.find(row[17] == 'x' ? "row 0: \"0.6x\" is not a number" : "row 0 holds more than six numbers"),
              std::string::npos)
        << row << ": " << msg;
    EXPECT_NE(msg.find((d / "tsv7.vtk").string()), std::string::npos) << msg;
  }
}

// VTK reads a piece's points times an array's components and ignores what
// else the array holds: nine-component tensors declared as six were read as
// six-value tensors from the wrong offsets, and drawn. Each point array must
// hold exactly what its piece needs, in every encoding.
TEST(Vtk, PointArraysHoldingOtherThanTheirPointsNeedAreRefused) {
  const auto h = synth::helixPhantom(3, 2, 2);
  const std::size_t n = h.field.size();
  const std::string need = "not the " + std::to_string(6 * n) + " of " + std::to_string(n) + " points with 6";
  for (const char* ext : {".vti", ".vtu", ".vtp"}) {  // appended, zlib, base64: our writer's choice
    const fs::path p = tmpDir() / (std::string("ncomp") + ext);
    io::writeVtk(h.field, p.string());
    ASSERT_EQ(io::readTensorField(p.string(), {}).size(), n) << ext;
    std::ifstream in(p, std::ios::binary);
    std::string xml{std::istreambuf_iterator<char>(in), {}};
    const std::size_t at = xml.find("NumberOfComponents=\"9\"");
    ASSERT_NE(at, std::string::npos) << ext;
    xml.replace(at, 22, "NumberOfComponents=\"6\"");
    test::writeFile(p, xml);
    const std::string msg = errorOf(p);
    EXPECT_NE(msg.find("holds " + std::to_string(9 * n) + " values, " + need), std::string::npos) << ext << ": " << msg;
  }
  // ASCII and raw appended data, two points.
  const std::string head = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">"
                           "<PolyData><Piece NumberOfPoints=\"2\"><Points><DataArray type=\"Float32\" "
                           "NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0</DataArray></Points><PointData "
                           "Tensors=\"t\"><DataArray type=\"Float32\" Name=\"t\" NumberOfComponents=\"6\" ";
  const std::string tail = "</PointData></Piece></PolyData>";
  std::string nine;
  for (int k = 0; k < 2; ++k) nine += "3 0.5 0.2 0.5 2 0.1 0.2 0.1 1 ";
  test::writeFile(tmpDir() / "ascii9.vtp", head + "format=\"ascii\">" + nine + "</DataArray>" + tail + "</VTKFile>");
  std::string raw(4, '\0');
  const std::uint32_t bytes = 18 * 4;
  std::memcpy(raw.data(), &bytes, 4);
  for (int k = 0; k < 18; ++k) {
    const float v = float(k + 1);
    raw.append(reinterpret_cast<const char*>(&v), 4);
  }
  test::writeFile(tmpDir() / "raw9.vtp", head + "format=\"appended\" offset=\"0\"/>" + tail +
                                             "<AppendedData encoding=\"raw\">_" + raw + "</AppendedData></VTKFile>");
  for (const char* name : {"ascii9.vtp", "raw9.vtp"}) {
    const std::string msg = errorOf(tmpDir() / name);
    EXPECT_NE(msg.find("array \"t\" holds 18 values, not the 12 of 2 points with 6 components each"), std::string::npos)
        << name << ": " << msg;
  }
}

// VTK sizes a structured dataset by its WholeExtent and fills it piece by
// piece: points no piece covers kept whatever the memory held, and were
// drawn (as zeros, in a fresh process). Pieces that overlap, as VTK's own
// writer makes them, and together cover the whole, read.
TEST(Vtk, StructuredPiecesMustCoverTheWholeExtent) {
  auto image = [](const std::vector<std::pair<int, int>>& pieces) {
    std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"0.1\">\n<ImageData "
                      "WholeExtent=\"0 3 0 0 0 0\" Origin=\"0 0 0\" Spacing=\"1 1 1\">\n";
    for (const auto& [lo, hi] : pieces) {
      xml += "<Piece Extent=\"" + std::to_string(lo) + " " + std::to_string(hi) + " 0 0 0 0\"><PointData "
             "Tensors=\"t\"><DataArray type=\"Float32\" Name=\"t\" NumberOfComponents=\"9\" format=\"ascii\">";
      for (int i = lo; i <= hi; ++i) xml += "1 0 0 0 2 0 0 0 3 ";
      xml += "</DataArray></PointData></Piece>\n";
    }
    return xml + "</ImageData>\n</VTKFile>\n";
  };
  const fs::path d = tmpDir();
  test::writeFile(d / "tiled.vti", image({{0, 1}, {1, 3}}));
  const io::TensorField f = io::readTensorField((d / "tiled.vti").string(), {});
  ASSERT_EQ(f.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(f.tensors[6 * i + 5], 3.0f) << i;
  for (const auto& pieces : {std::vector<std::pair<int, int>>{{0, 1}}, {{0, 1}, {3, 3}}}) {
    test::writeFile(d / "holes.vti", image(pieces));
    const std::string msg = errorOf(d / "holes.vti");
    EXPECT_NE(msg.find("its pieces leave part of the WholeExtent uncovered"), std::string::npos) << msg;
  }
}

TEST(Vtk, ACorruptBodyThatCrashesVtkIsReportedNotFatal) {
  // Found by fuzz_vtk: VTK 9.1's legacy reader dereferences null on this
  // binary body after every header check passes. The child-process guard
  // must turn that into an InputError.
  const fs::path p = tmpDir() / "body-crash.vtk";
  fs::copy_file(fs::path(TG_SOURCE_DIR) / "tests/fuzz/vtk-body-crashes/binary-5.1-cells", p,
                fs::copy_options::overwrite_existing);
  const std::string e = errorOf(p);
  EXPECT_NE(e.find("corrupt file"), std::string::npos) << e;
  EXPECT_NE(e.find(p.string()), std::string::npos) << e;
}
