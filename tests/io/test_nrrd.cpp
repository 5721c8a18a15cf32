// Tier 2: NRRD input through Teem, in every encoding and orientation form,
// and bad input.
#include <gtest/gtest.h>

#include <teem/nrrd.h>
#include <unistd.h>
#include <zlib.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "data-synthetic/generators.h"
#include "io/core/readers.h"
#include "io/io_test_util.h"
#include "io/core/writers.h"

using namespace tg;
namespace fs = std::filesystem;

namespace {

fs::path tmpDir() { return test::scratchDir("nrrd"); }

std::string errorOf(const fs::path& p, const io::ReadOptions& o = {}) { return test::readError(p, o); }

// A 2x3x2 grid of distinct symmetric tensors; value k of voxel v is 1 + v + k/8.
std::vector<double> sample6(int voxels) {
  std::vector<double> d;
  for (int v = 0; v < voxels; ++v)
    for (int k = 0; k < 6; ++k) d.push_back(1.0 + v + k / 8.0);
  return d;
}

// Saves `data` (6 values per voxel, 2x3x2 voxels, identity geometry) with
// Teem in the given type, encoding and header placement.
void saveWithTeem(const fs::path& p, const std::vector<double>& d, int type, const NrrdEncoding* enc, bool detached) {
  Nrrd* n = nrrdNew();
  const std::size_t sizes[4] = {6, 2, 3, 2};
  ASSERT_EQ(nrrdAlloc_nva(n, type, 4, sizes), 0);
  for (std::size_t i = 0; i < d.size(); ++i) nrrdDInsert[type](n->data, i, d[i]);
  nrrdSpaceSet(n, nrrdSpaceRightAnteriorSuperior);
  const double origin[3] = {10, 20, 30};
  nrrdSpaceOriginSet(n, origin);
  double dirs[NRRD_DIM_MAX][NRRD_SPACE_DIM_MAX];
  for (int a = 0; a < 4; ++a)
    for (int k = 0; k < 3; ++k) dirs[a][k] = a == 0 ? AIR_NAN : (a - 1 == k ? 2.0 : 0.0);
  nrrdAxisInfoSet_nva(n, nrrdAxisInfoSpaceDirection, dirs);
  const int kinds[4] = {nrrdKind3DSymMatrix, nrrdKindSpace, nrrdKindSpace, nrrdKindSpace};
  nrrdAxisInfoSet_nva(n, nrrdAxisInfoKind, kinds);
  NrrdIoState* nio = nrrdIoStateNew();
  nio->encoding = enc;
  nio->detachedHeader = detached;
  ASSERT_EQ(nrrdSave(p.c_str(), n, nio), 0);
  nrrdIoStateNix(nio);
  nrrdNuke(n);
}

std::string header(const std::string& sizes, const std::string& extra) {
  return "NRRD0005\ntype: float\ndimension: 4\nsizes: " + sizes + "\nencoding: raw\nendian: little\n" + extra + "\n\n";
}

std::string floats(const std::vector<float>& v, bool bigEndian = false) {
  std::string s(reinterpret_cast<const char*>(v.data()), 4 * v.size());
  if (bigEndian)
    for (std::size_t i = 0; i < s.size(); i += 4) std::reverse(s.begin() + long(i), s.begin() + long(i) + 4);
  return s;
}

}  // namespace

TEST(Nrrd, EveryEncodingTypeAndHeaderPlacementReadsTheSameTensors) {
  const std::vector<double> d = sample6(12);
  struct Case {
    const char* name;
    int type;
    const NrrdEncoding* enc;
    bool detached;
  } cases[] = {{"raw-float-attached", nrrdTypeFloat, nrrdEncodingRaw, false},
               {"raw-double-detached", nrrdTypeDouble, nrrdEncodingRaw, true},
               {"ascii-float", nrrdTypeFloat, nrrdEncodingAscii, false},
               {"hex-double", nrrdTypeDouble, nrrdEncodingHex, true},
               {"gzip-float-detached", nrrdTypeFloat, nrrdEncodingGzip, true},
               {"gzip-double-attached", nrrdTypeDouble, nrrdEncodingGzip, false},
               {"bzip2-float", nrrdTypeFloat, nrrdEncodingBzip2, false}};
  for (const Case& c : cases) {
    const fs::path p = tmpDir() / (std::string(c.name) + (c.detached ? ".nhdr" : ".nrrd"));
    saveWithTeem(p, d, c.type, c.enc, c.detached);
    const io::TensorField f = io::readTensorField(p.string(), {});
    ASSERT_EQ(f.size(), 12u) << c.name;
    ASSERT_TRUE(f.grid) << c.name;
    EXPECT_EQ(f.space, "RAS") << c.name;
    for (int v = 0; v < 12; ++v) {
      for (int k = 0; k < 6; ++k) ASSERT_FLOAT_EQ(f.tensors[6 * v + k], float(d[6 * v + k])) << c.name << " v" << v;
      const int ijk[3] = {v % 2, v / 2 % 3, v / 6};
      for (int k = 0; k < 3; ++k) ASSERT_FLOAT_EQ(f.positions[3 * v + k], float(10 * (k + 1) + 2 * ijk[k])) << c.name;
    }
    EXPECT_DOUBLE_EQ(f.sampleSpacing, 2.0) << c.name;
  }
}

TEST(Nrrd, BigEndianAndLittleEndianAgree) {
  std::vector<float> v;
  for (double x : sample6(2)) v.push_back(float(x));
  const fs::path le = tmpDir() / "le.nrrd", be = tmpDir() / "be.nrrd";
  test::writeFile(le, header("6 2 1 1", "kinds: 3D-symmetric-matrix domain domain domain") + floats(v));
  std::string h = header("6 2 1 1", "kinds: 3D-symmetric-matrix domain domain domain");
  h.replace(h.find("little"), 6, "big");
  test::writeFile(be, h + floats(v, true));
  const auto a = io::readTensorField(le.string(), {}), b = io::readTensorField(be.string(), {});
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a.tensors, b.tensors);
  EXPECT_FLOAT_EQ(b.tensors[7], 2.125f);
}

// The same through the decoder of compressed data (decode in nrrd_reader.cpp,
// not the raw path), which swaps bytes on its own: gzip of big-endian doubles.
TEST(Nrrd, BigEndianGzipAgreesWithLittleEndianRaw) {
  const std::vector<double> d = sample6(3);
  std::vector<float> v(d.begin(), d.end());
  const fs::path le = tmpDir() / "le3.nrrd", gz = tmpDir() / "be3.raw.gz", be = tmpDir() / "be3.nhdr";
  test::writeFile(le, header("6 3 1 1", "kinds: 3D-symmetric-matrix domain domain domain") + floats(v));
  std::string bytes(reinterpret_cast<const char*>(d.data()), 8 * d.size());
  for (std::size_t i = 0; i < bytes.size(); i += 8) std::reverse(bytes.begin() + long(i), bytes.begin() + long(i) + 8);
  gzFile out = gzopen(gz.c_str(), "wb");
  ASSERT_NE(out, nullptr);
  ASSERT_EQ(gzwrite(out, bytes.data(), unsigned(bytes.size())), int(bytes.size()));
  ASSERT_EQ(gzclose(out), Z_OK);
  test::writeFile(be, "NRRD0005\ntype: double\ndimension: 4\nsizes: 6 3 1 1\nencoding: gzip\nendian: big\n"
                      "kinds: 3D-symmetric-matrix domain domain domain\ndata file: be3.raw.gz\n");
  const auto a = io::readTensorField(le.string(), {}), b = io::readTensorField(be.string(), {});
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(a.tensors, b.tensors);
}

TEST(Nrrd, MeasurementFrameAndRotatedGridRoundTrip) {
  // writeNrrd stores D in a rotated measurement frame; reading must bring
  // every tensor back to the world, and the grid's rotated axes with it.
  const synth::Helix h = synth::helixPhantom(6, 5, 4);
  const fs::path p = tmpDir() / "helix-frame.nrrd";
  io::writeNrrd(h.field, p.string(), h.measurementFrame);
  const io::TensorField f = io::readTensorField(p.string(), {});
  ASSERT_EQ(f.size(), h.field.size());
  ASSERT_TRUE(f.measurementFrame);
  for (int k = 0; k < 9; ++k) EXPECT_NEAR((*f.measurementFrame)[k], h.measurementFrame[k], 1e-12);
  for (std::size_t i = 0; i < f.size(); ++i) {
    for (int k = 0; k < 3; ++k) ASSERT_NEAR(f.positions[3 * i + k], h.field.positions[3 * i + k], 1e-4);
    for (int k = 0; k < 6; ++k) ASSERT_NEAR(f.tensors[6 * i + k], h.field.tensors[6 * i + k], 1e-5) << i;
  }
}

TEST(Nrrd, LpsIsTurnedIntoRas) {
  // One tensor with an xy shear at LPS (1, 2, 3): in RAS the position is
  // (-1, -2, 3) and the xy component keeps its sign (both axes flip), while
  // xz and yz change sign.
  const std::vector<float> t = {1, 0.5f, 0.25f, 2, 0.125f, 3};
  const fs::path p = tmpDir() / "lps.nrrd";
  test::writeFile(p, header("6 1 1 1", "kinds: 3D-symmetric-matrix space space space\nspace: LPS\n"
                                  "space directions: none (1,0,0) (0,1,0) (0,0,1)\nspace origin: (1,2,3)") +
                    floats(t));
  const auto f = io::readTensorField(p.string(), {});
  ASSERT_EQ(f.size(), 1u);
  EXPECT_NE(f.space.find("converted from left-posterior-superior"), std::string::npos) << f.space;
  EXPECT_FLOAT_EQ(f.positions[0], -1);
  EXPECT_FLOAT_EQ(f.positions[1], -2);
  EXPECT_FLOAT_EQ(f.positions[2], 3);
  const float expect[6] = {1, 0.5f, -0.25f, 2, -0.125f, 3};
  for (int k = 0; k < 6; ++k) EXPECT_FLOAT_EQ(f.tensors[k], expect[k]) << k;
}

// A left-handed space drawn as it stands in our right-handed world would be
// the mirror image of its data: x is negated, as for LAS, positions and
// tensors alike. Before, it was drawn unchanged.
TEST(Nrrd, LeftHandedSpaceIsMadeRightHanded) {
  const std::vector<float> t = {1, 0.5f, 0.25f, 2, 0.125f, 3};
  const fs::path p = tmpDir() / "left.nrrd";
  test::writeFile(p, header("6 1 1 1", "kinds: 3D-symmetric-matrix space space space\nspace: 3D-left-handed\n"
                                  "space directions: none (1,0,0) (0,1,0) (0,0,1)\nspace origin: (1,2,3)") +
                    floats(t));
  const auto f = io::readTensorField(p.string(), {});
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f.space, "3D-right-handed (converted from 3D-left-handed)");
  EXPECT_NE(f.frame.find("x negated, 3D-left-handed to 3D-right-handed"), std::string::npos) << f.frame;
  EXPECT_FLOAT_EQ(f.positions[0], -1);
  EXPECT_FLOAT_EQ(f.positions[1], 2);
  EXPECT_FLOAT_EQ(f.positions[2], 3);
  const float expect[6] = {1, -0.5f, -0.25f, 2, 0.125f, 3};
  for (int k = 0; k < 6; ++k) EXPECT_FLOAT_EQ(f.tensors[k], expect[k]) << k;
}

TEST(Nrrd, OldHeadersPlaceByAxisMinsAndMaxs) {
  // Cell centring (Teem's default): sample i of n sits at min + (i + 0.5)(max - min)/n.
  std::vector<float> v(7 * 4, 0.1f);
  for (int i = 0; i < 4; ++i) v[7 * i] = 1;  // confidence
  const fs::path p = tmpDir() / "old.nrrd";
  test::writeFile(p, "NRRD0001\ntype: float\ndimension: 4\nsizes: 7 4 1 1\nencoding: raw\nendian: little\n"
                "axis mins: NaN -2 0 0\naxis maxs: NaN 2 1 1\n\n" +
                    floats(v));
  const auto f = io::readTensorField(p.string(), {});
  ASSERT_EQ(f.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_FLOAT_EQ(f.positions[3 * i], float(-2.0 + (i + 0.5)));
}

TEST(Nrrd, MaskedKindHonoursTheConfidenceThreshold) {
  std::vector<float> v;
  const float conf[4] = {0.0f, 0.49f, 0.5f, 1.0f};
  for (float c : conf) v.insert(v.end(), {c, 1, 0, 0, 1, 0, 1});
  const fs::path p = tmpDir() / "masked.nrrd";
  test::writeFile(p, header("7 4 1 1", "kinds: 3D-masked-symmetric-matrix domain domain domain") + floats(v));
  const auto f = io::readTensorField(p.string(), {});
  EXPECT_EQ(f.size(), 2u);
  EXPECT_EQ(f.masked, 2u);
  EXPECT_EQ(f.ids, (std::vector<std::uint32_t>{2, 3}));
  io::ReadOptions all;
  all.selection.confidenceMin = 0.0;
  EXPECT_EQ(io::readTensorField(p.string(), all).size(), 4u);
}

TEST(Nrrd, AsymmetricMatricesAreSymmetrisedWithAWarning) {
  const std::vector<float> v = {1, 0.2f, 0, 0.4f, 2, 0, 0, 0, 3};
  const fs::path p = tmpDir() / "asym.nrrd";
  test::writeFile(p, header("9 1 1 1", "kinds: 3D-matrix domain domain domain") + floats(v));
  const auto f = io::readTensorField(p.string(), {});
  ASSERT_EQ(f.size(), 1u);
  EXPECT_FLOAT_EQ(f.tensors[1], 0.3f);
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_NE(f.warnings[0].find("asymmetric"), std::string::npos);
}

TEST(Nrrd, BadInputGetsOneLineNamingFileAndProblem) {
  const fs::path d = tmpDir();
  const std::string kinds = "kinds: 3D-symmetric-matrix domain domain domain";
  struct Case {
    const char* file;
    std::string bytes;
    const char* expect;
  } cases[] = {
      {"trunc.nrrd", header("6 4 4 4", kinds) + floats(std::vector<float>(10, 1)), "truncated"},
      {"huge.nrrd", header("6 1000 1000 1000", kinds) + floats({1, 2}), "truncated"},
      {"overflow.nrrd", header("6 4294967296 4294967296 4294967296", kinds), "readNrrd"},
      {"kind.nrrd", header("5 1 1 1", "kinds: vector domain domain domain") + floats({1, 2, 3, 4, 5}), "not a tensor"},
      {"dims.nrrd", "NRRD0005\ntype: float\ndimension: 2\nsizes: 6 1\nencoding: raw\nendian: little\n\n" + floats({1, 2, 3, 4, 5, 6}),
       "axes"},
      {"gz.nrrd", "NRRD0005\ntype: float\ndimension: 4\nsizes: 6 1 1 1\nencoding: gzip\nendian: little\n\nnot gzip at all", "gzip"},
      {"nodata.nhdr", "NRRD0005\ntype: float\ndimension: 4\nsizes: 6 1 1 1\nencoding: raw\nendian: little\ndata file: missing.raw\n",
       "missing.raw cannot be read: No such file or directory"},
      {"garbage.nrrd", "NRRD0005\nthis is not a field\n", "readNrrd"},
      {"longtoken.nrrd",
       "NRRD0005\ntype: float\ndimension: 4\nsizes: 6 1 1 1\nencoding: ascii\n\n" + std::string(5000, '7'), "token"},
      // Counted before Teem's parser steps through two billion names (3 s,
      // then the guard's time limit, before this was checked first).
      {"billion.nhdr",
       "NRRD0005\ntype: float\ndimension: 4\nsizes: 6 5 4 3\nencoding: raw\nendian: little\n"
       "data file: sl%d.raw 0 1999999999 1\n",
       "2000000000 data files; at most 100000"},
      {"twofiles.nhdr",
       "NRRD0005\ntype: float\ndimension: 4\nsizes: 6 1 1 2\nencoding: raw\nendian: little\n"
       "data file: LIST\nnodata.nhdr\ntrunc.nrrd\n",
       "multiple detached data files"},
  };
  for (const Case& c : cases) {
    test::writeFile(d / c.file, c.bytes);
    const std::string e = errorOf(d / c.file);
    EXPECT_NE(e.find(c.expect), std::string::npos) << c.file << ": " << e;
    EXPECT_NE(e.find((d / c.file).string()), std::string::npos) << c.file << ": " << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << c.file << ": " << e;
  }
}

TEST(Nrrd, NonFiniteTensorsAreSkippedAndCounted) {
  std::vector<float> v = {1, 0, 0, 1, 0, 1, NAN, 0, 0, 1, 0, 1, 1, 0, 0, INFINITY, 0, 1};
  const fs::path p = tmpDir() / "nan.nrrd";
  test::writeFile(p, header("6 3 1 1", "kinds: 3D-symmetric-matrix domain domain domain") + floats(v));
  const auto f = io::readTensorField(p.string(), {});
  EXPECT_EQ(f.size(), 1u);
  EXPECT_EQ(f.skippedNonFinite, 2u);
  EXPECT_EQ(f.totalPoints, 3u);
}

TEST(Nrrd, DataSpanningManyChunksReadsBackExactly) {
  // 400k tensors of 6 floats are 9.6 MB: several 4 MiB decode chunks, whose
  // boundaries must never split or drop a voxel.
  constexpr std::size_t n = 400000;
  const fs::path p = tmpDir() / "many.nhdr";
  synth::writeRandomNrrdStreaming(p.string(), n, 3);
  const io::TensorField f = io::readTensorField(p.string(), {});
  const io::TensorField expect = synth::randomField(n, 3);
  ASSERT_EQ(f.size(), expect.size());
  EXPECT_EQ(f.tensors, expect.tensors);
}
