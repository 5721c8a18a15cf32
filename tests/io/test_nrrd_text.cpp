// Tier 2: NRRD files that parse but were read wrongly (issue 30): hex data
// in the other byte order, numbers with trailing characters in the header
// and in ascii data, and old headers placed by axis mins and maxs. Teem's
// own reader and position functions are the oracle.
#include <gtest/gtest.h>

#include <teem/nrrd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/io_test_util.h"
#include "io/core/readers.h"

using namespace tg;
namespace fs = std::filesystem;

namespace {

fs::path tmpDir() { return test::scratchDir("nrrd_text"); }

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Value k of voxel v: integers that every type holds, or fractions for floats.
double valueAt(int type, int v, int k) { return nrrdTypeIsIntegral[type] ? 1 + (6 * v + k) % 60 : 1 + v + k / 8.0; }

// Teem writes 6 x 2 x 3 x 2 values of `type` in `enc`, in its own byte order;
// `big` swaps the data and says so in the header, as a big-endian machine
// writes it.
void saveWithTeem(const fs::path& p, int type, const NrrdEncoding* enc, bool big) {
  Nrrd* n = nrrdNew();
  const std::size_t sizes[4] = {6, 2, 3, 2};
  ASSERT_EQ(nrrdAlloc_nva(n, type, 4, sizes), 0);
  for (int v = 0; v < 12; ++v)
    for (int k = 0; k < 6; ++k) nrrdDInsert[type](n->data, std::size_t(6 * v + k), valueAt(type, v, k));
  const int kinds[4] = {nrrdKind3DSymMatrix, nrrdKindDomain, nrrdKindDomain, nrrdKindDomain};
  nrrdAxisInfoSet_nva(n, nrrdAxisInfoKind, kinds);
  const bool swap = big && nrrdTypeSize[type] > 1 && enc->endianMatters;
  if (swap) nrrdSwapEndian(n);
  NrrdIoState* nio = nrrdIoStateNew();
  nio->encoding = enc;
  ASSERT_EQ(nrrdSave(p.c_str(), n, nio), 0);
  nrrdIoStateNix(nio);
  nrrdNuke(n);
  if (swap) {
    std::string bytes = slurp(p);
    const auto at = bytes.find("endian: little\n");
    ASSERT_NE(at, std::string::npos) << p;
    bytes.replace(at, 15, "endian: big\n");
    test::writeFile(p, bytes);
  }
}

std::vector<double> teemValues(const fs::path& p) {
  Nrrd* n = nrrdNew();
  std::vector<double> v;
  if (nrrdLoad(n, p.c_str(), nullptr) == 0)
    for (std::size_t i = 0; i < nrrdElementNumber(n); ++i) v.push_back(nrrdDLookup[n->type](n->data, i));
  nrrdNuke(n);
  return v;
}

std::string oldHeader(const std::string& type, const std::string& sizes, const std::string& extra,
                      const std::string& encoding = "ascii") {
  return "NRRD0004\ntype: " + type + "\ndimension: 4\nsizes: " + sizes + "\nencoding: " + encoding + "\n" + extra +
         "\n";
}

}  // namespace

// Every encoding, byte order and type reads the values Teem's own reader
// gives; hex in big-endian order was read unswapped (FA 1.22 from a
// positive-definite field).
TEST(NrrdText, EveryEncodingEndianAndTypeReadsWhatTeemReads) {
  const NrrdEncoding* encodings[] = {nrrdEncodingRaw, nrrdEncodingAscii, nrrdEncodingHex, nrrdEncodingGzip,
                                     nrrdEncodingBzip2};
  const int types[] = {nrrdTypeChar, nrrdTypeUChar, nrrdTypeShort, nrrdTypeUShort, nrrdTypeInt,
                       nrrdTypeUInt, nrrdTypeLLong, nrrdTypeULLong, nrrdTypeFloat, nrrdTypeDouble};
  ASSERT_TRUE(nrrdEncodingHex->endianMatters);
  for (const NrrdEncoding* enc : encodings)
    for (const bool big : {false, true})
      for (const int type : types) {
        const std::string name = std::string(enc->name) + "-" + (big ? "big" : "little") + "-" + airEnumStr(nrrdType, type);
        const fs::path p = tmpDir() / (name + ".nrrd");
        saveWithTeem(p, type, enc, big);
        const std::vector<double> teem = teemValues(p);
        ASSERT_EQ(teem.size(), 72u) << name;
        const io::TensorField f = io::readTensorField(p.string(), {});
        ASSERT_EQ(f.size(), 12u) << name;
        for (int v = 0; v < 12; ++v)
          for (int k = 0; k < 6; ++k) {
            ASSERT_DOUBLE_EQ(teem[std::size_t(6 * v + k)], valueAt(type, v, k)) << name;
            ASSERT_FLOAT_EQ(f.tensors[std::size_t(6 * v + k)], float(teem[std::size_t(6 * v + k)])) << name << " v" << v;
          }
      }
}

// Words Teem's sscanf reads by their prefix are refused, each in one line
// naming the file, the value and its place.
TEST(NrrdText, AsciiValuesWithTrailingCharactersAreRefused) {
  const std::string good = "1 0 0 1 0 1 ";
  for (const char* bad : {"3,5", "3.5x", "1.5abc", "0x10", "1e", "--1", "banana", "inf5"}) {
    const fs::path p = tmpDir() / "ascii-bad.nrrd";
    test::writeFile(p, oldHeader("float", "6 2 1 1", "") + good + "1 0 0 " + bad + " 0 1\n");
    const std::string e = test::readError(p);
    EXPECT_EQ(e, "readNrrd: " + p.string() + ": ascii value \"" + bad + "\" (value 9) is not a number") << bad;
  }
}

// What Teem reads correctly still reads: signs, exponents, '-0', NaN (a
// voxel then left out and counted), and commas between values, which Teem
// passes over.
TEST(NrrdText, AsciiNeighboursStillRead) {
  const fs::path p = tmpDir() / "ascii-good.nrrd";
  test::writeFile(p, oldHeader("double", "6 3 1 1", "") +
                         "+1 -0 0.0 1E0 .0 1.\n2e0, 0, 0, 2, 0 , 2,\n,3 0 0 3 0 nan\n");
  const io::TensorField f = io::readTensorField(p.string(), {});
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f.totalPoints, 3u);
  EXPECT_FLOAT_EQ(f.tensors[0], 1);
  EXPECT_FLOAT_EQ(f.tensors[6], 2);
  EXPECT_FLOAT_EQ(f.tensors[11], 2);
}

TEST(NrrdText, AsciiIntegersKeepTheirTypeRange) {
  const fs::path p = tmpDir() / "ascii-uchar.nrrd";
  test::writeFile(p, oldHeader("uchar", "6 1 1 1", "") + "1 0 0 300 0 1\n");
  EXPECT_EQ(test::readError(p), "readNrrd: " + p.string() + ": ascii value 300 (value 3) is not a unsigned char");
  test::writeFile(p, oldHeader("uchar", "6 1 1 1", "") + "1 0 0 1.5 0 1\n");
  EXPECT_EQ(test::readError(p), "readNrrd: " + p.string() + ": ascii value 1.5 (value 3) is not a unsigned char");
}

// Header numbers Teem reads by their prefix: decimal commas and trailing
// characters in every numeric field, refused with the line and the field.
TEST(NrrdText, HeaderNumbersWithTrailingCharactersAreRefused) {
  const std::string data = "1 0 0 1 0 1 1 0 0 1 0 1\n";
  const struct {
    std::string extra;
    std::string problem;
  } cases[] = {
      {"spacings: NaN 1,5 1 1", "header line 6 (spacings): \"1,5\" is not a number"},
      {"thicknesses: NaN 1.5x 1 1", "header line 6 (thicknesses): \"1.5x\" is not a number"},
      {"axis mins: NaN 0,5 0 0\naxis maxs: NaN 2 1 1", "header line 6 (axis mins): \"0,5\" is not a number"},
      {"axis mins: NaN 0 0 0\naxis maxs: NaN 2,5 1 1", "header line 7 (axis maxs): \"2,5\" is not a number"},
      {"old min: 0,5", "header line 6 (old min): \"0,5\" is not a number"},
      {"space: RAS\nspace origin: (1.5x,0,0)", "header line 7 (space origin): \"(1.5x,0,0)\" holds \"1.5x\", which is not a number"},
      {"space: RAS\nspace directions: none (1,0,0) (0,1,0) (0,0,1abc)",
       "header line 7 (space directions): \"(0,0,1abc)\" holds \"1abc\", which is not a number"},
      {"space: RAS\nspace directions: none (1,0,0) (0,1,0) (0,0,1)x",
       "header line 7 (space directions): \"(0,0,1)\" is followed by \"x\""},
      {"space: RAS\nspace directions: none (1,0,0) (0,1,0) (0,0,1)\nmeasurement frame: (1,0,0) (0,1,0) (0,0,0x1)",
       "header line 8 (measurement frame): \"(0,0,0x1)\" holds \"0x1\", which is not a number"},
  };
  for (const auto& c : cases) {
    const fs::path p = tmpDir() / "header-bad.nrrd";
    test::writeFile(p, oldHeader("float", "6 2 1 1", c.extra + "\n") + data);
    EXPECT_EQ(test::readError(p), "readNrrd: " + p.string() + ": " + c.problem) << c.extra;
  }
  const fs::path p = tmpDir() / "sizes-bad.nrrd";
  test::writeFile(p, oldHeader("float", "6 2 1 1x", "") + data);
  EXPECT_EQ(test::readError(p), "readNrrd: " + p.string() + ": header line 4 (sizes): \"1x\" is not an integer");
}

TEST(NrrdText, HeaderNumberNeighboursStillRead) {
  const fs::path p = tmpDir() / "header-good.nrrd";
  test::writeFile(p, oldHeader("float", "6 2 1 1",
                               "spacings: nan +1.5 1E0 2\n# a comment: 1,5\nkey:=1,5\nthicknesses: NaN -0 1 1\n") +
                         "1 0 0 1 0 1 1 0 0 1 0 1\n");
  const io::TensorField f = io::readTensorField(p.string(), {});
  ASSERT_EQ(f.size(), 2u);
  EXPECT_FLOAT_EQ(f.positions[3], 1.5f);
  const fs::path q = tmpDir() / "vectors-good.nrrd";
  test::writeFile(q, oldHeader("float", "6 2 1 1",
                               "space: RAS\nspace origin: ( 1.5 , -2e0,+3 )\n"
                               "space directions: none (1,0,0) (0,1,0) (0,0,1)\n") +
                         "1 0 0 1 0 1 1 0 0 1 0 1\n");
  const io::TensorField g = io::readTensorField(q.string(), {});
  ASSERT_EQ(g.size(), 2u);
  EXPECT_FLOAT_EQ(g.positions[0], 1.5f);
  EXPECT_FLOAT_EQ(g.positions[1], -2.0f);
  EXPECT_FLOAT_EQ(g.positions[2], 3.0f);
}

// Old headers (no space) are placed as Teem's nrrdAxisInfoPos places them:
// a one-sample axis by its mins and maxs too, cell or node centred.
TEST(NrrdText, AxisMinsAndMaxsPlaceAsTeemDoes) {
  const struct {
    const char* sizes;
    const char* extra;
  } cases[] = {
      {"6 2 3 1", "axis mins: NaN -2 0 5\naxis maxs: NaN 2 3 7\ncenters: ??? cell cell cell"},
      {"6 2 3 1", "axis mins: NaN -2 0 5\naxis maxs: NaN 2 3 7"},
      {"6 2 3 2", "axis mins: NaN -2 0 5\naxis maxs: NaN 2 3 7\ncenters: ??? node node node"},
      {"6 1 3 2", "axis mins: NaN 4 0 5\naxis maxs: NaN 6 3 7\ncenters: ??? cell node cell"},
  };
  for (const auto& c : cases) {
    const fs::path p = tmpDir() / "placed.nrrd";
    std::string data;
    for (int i = 0; i < 12; ++i) data += "1 0 0 1 0 1\n";
    test::writeFile(p, oldHeader("float", c.sizes, std::string(c.extra) + "\n") + data);
    Nrrd* n = nrrdNew();
    ASSERT_EQ(nrrdLoad(n, p.c_str(), nullptr), 0) << c.extra;
    const io::TensorField f = io::readTensorField(p.string(), {});
    const std::size_t nx = n->axis[1].size, ny = n->axis[2].size;
    ASSERT_EQ(f.size(), nx * ny * n->axis[3].size) << c.extra;
    for (std::size_t v = 0; v < f.size(); ++v) {
      const std::size_t ijk[3] = {v % nx, v / nx % ny, v / nx / ny};
      for (unsigned k = 0; k < 3; ++k)
        EXPECT_NEAR(f.positions[3 * v + k], nrrdAxisInfoPos(n, k + 1, double(ijk[k])), 1e-6)
            << c.extra << " voxel " << v << " axis " << k + 1;
    }
    nrrdNuke(n);
  }
}

// Without maxs, the mins still place the grid: sample i at min + (i + 0.5)
// spacing for cells (Teem's default), min + i spacing for nodes, where
// they were dropped and the grid put at the origin.
TEST(NrrdText, AxisMinsAloneStillPlaceTheGrid) {
  std::string data;
  for (int i = 0; i < 4; ++i) data += "1 0 0 1 0 1\n";
  const fs::path p = tmpDir() / "mins.nrrd";
  test::writeFile(p, oldHeader("float", "6 2 2 1", "axis mins: NaN 10 20 30\n") + data);
  io::TensorField f = io::readTensorField(p.string(), {});
  ASSERT_EQ(f.size(), 4u);
  EXPECT_FLOAT_EQ(f.positions[0], 10.5f);
  EXPECT_FLOAT_EQ(f.positions[1], 20.5f);
  EXPECT_FLOAT_EQ(f.positions[2], 30.5f);
  EXPECT_FLOAT_EQ(f.positions[3], 11.5f);
  test::writeFile(p, oldHeader("float", "6 2 2 1", "axis mins: NaN 10 20 30\nspacings: NaN 2 2 2\n"
                                                   "centers: ??? node node node\n") + data);
  f = io::readTensorField(p.string(), {});
  EXPECT_FLOAT_EQ(f.positions[0], 10);
  EXPECT_FLOAT_EQ(f.positions[3], 12);
  EXPECT_FLOAT_EQ(f.positions[2], 30);
}

TEST(NrrdText, OneNodeWithDifferentMinAndMaxIsRefused) {
  std::string data;
  for (int i = 0; i < 2; ++i) data += "1 0 0 1 0 1\n";
  const fs::path p = tmpDir() / "one-node.nrrd";
  test::writeFile(p, oldHeader("float", "6 2 1 1", "axis mins: NaN 0 0 0\naxis maxs: NaN 1 1 2\n"
                                                   "centers: ??? node node node\n") + data);
  EXPECT_EQ(test::readError(p),
            "readNrrd: " + p.string() + ": axis 2 holds one node-centred sample, but its axis min and max differ");
}
