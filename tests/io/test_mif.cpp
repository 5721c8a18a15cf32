// Tier 2: MRtrix .mif/.mih input: data types and byte orders, layouts
// (strides), placement, scaling, masks, bad input, and MRtrix's own
// mrconvert as a peer of the NIfTI reader.
#include <gtest/gtest.h>

#include <nifti2_io.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "io/io_test_util.h"
#include "io/mif_fixture.h"
#include "io/core/readers.h"

using namespace tg;
namespace fs = std::filesystem;

namespace {

fs::path tmpDir() { return test::scratchDir("mif"); }

// Checks every voxel of `fx` against `f`: ids in index order, positions at
// R (ijk .* vox) + t, tensors reordered (and scaled) but not rotated.
void expectMatches(const io::TensorField& f, const test::MifFixture& fx, double offset = 0, double scale = 1,
                   const std::string& what = "") {
  ASSERT_EQ(f.size(), fx.voxels()) << what;
  for (std::size_t v = 0; v < fx.voxels(); ++v) {
    ASSERT_EQ(f.ids[v], v) << what;
    const int ijk[3] = {int(v) % fx.dims[0], int(v) / fx.dims[0] % fx.dims[1], int(v) / (fx.dims[0] * fx.dims[1])};
    for (int r = 0; r < 3; ++r) {
      double p = fx.transform[std::size_t(r)][3];
      for (int c = 0; c < 3; ++c) p += fx.transform[std::size_t(r)][std::size_t(c)] * ijk[c] * fx.vox[c];
      EXPECT_NEAR(f.positions[3 * v + std::size_t(r)], p, 1e-4) << what << " voxel " << v << " row " << r;
    }
    const auto& m = fx.mrtrix[v];
    const double sym[6] = {m[0], m[3], m[4], m[1], m[5], m[2]};  // xx xy xz yy yz zz
    for (int k = 0; k < 6; ++k)
      EXPECT_FLOAT_EQ(f.tensors[6 * v + std::size_t(k)], float(offset + scale * sym[k])) << what << " voxel " << v;
  }
}

io::TensorField read(const fs::path& p, const io::ReadOptions& o = {}) { return io::readTensorField(p.string(), o); }

}  // namespace

TEST(Mif, EveryDataTypeAndByteOrder) {
  for (const char* type : {"Int8", "UInt8", "Int16LE", "Int16BE", "UInt16LE", "UInt16BE", "Int32LE", "Int32BE",
                           "UInt32LE", "UInt32BE", "Int64LE", "Int64BE", "UInt64LE", "UInt64BE", "Float32LE",
                           "Float32BE", "Float64LE", "Float64BE", "Float32", "int16be"}) {
    test::MifFixture fx;
    fx.datatype = type;
    fx.fillDistinct(std::string(type).find("UInt") == std::string::npos);
    if (std::string(type) == "int16be") fx.datatype = "Int16BE";  // written as such, named in lower case below
    const fs::path p = tmpDir() / (std::string("type-") + type + ".mif");
    test::writeMif(p, fx);
    if (std::string(type) == "int16be") {
      std::string bytes = test::slurpBytes(p);
      bytes.replace(bytes.find("Int16BE"), 7, "int16be");
      test::writeFile(p, bytes);
    }
    const io::TensorField f = read(p);
    expectMatches(f, fx, 0, 1, type);
    EXPECT_EQ(f.skippedNonFinite, 0u);
  }
}

TEST(Mif, EveryLayoutGivesTheSameTensorsAtTheSamePositions) {
  const std::array<std::string, 4> layouts[] = {
      {"+1", "+2", "+3", "+0"},  // voxel by voxel, i fastest: MRtrix's tensor default
      {"+0", "+1", "+2", "+3"},  // one volume per component, as NIfTI
      {"-0", "+1", "+2", "+3"},  // mrconvert's default from a det > 0 NIfTI
      {"-1", "+2", "+3", "+0"},  {"+3", "+2", "+1", "+0"},  {"+2", "-3", "+1", "+0"},
      {"-3", "-2", "-1", "-0"},  {"+1", "+0", "+3", "+2"},  {"+0", "+2", "+1", "-3"}};
  test::MifFixture fx;
  fx.transform = {{0, -1, 0, 5}, {1, 0, 0, -7}, {0, 0, 1, 2.5}};  // a quarter turn, so axes matter
  fx.fillDistinct(true);
  io::ReadOptions sliced;
  sliced.selection.slice = io::SliceSpec{2, 2, 1};
  sliced.selection.stride = 2;
  std::vector<std::uint32_t> firstIds;
  std::vector<float> firstTensors;
  for (const auto& layout : layouts) {
    fx.layout = layout;
    const std::string name = layout[0] + layout[1] + layout[2] + layout[3];
    for (const bool mih : {false, true}) {
      const fs::path p = tmpDir() / ("layout" + name + (mih ? ".mih" : ".mif"));
      if (mih) test::writeMih(p, fx, "layout" + name + ".dat", 0);
      else test::writeMif(p, fx);
      expectMatches(read(p), fx, 0, 1, name);
      // The selection keeps the same voxels whatever the order on file.
      const io::TensorField s = read(p, sliced);
      if (firstIds.empty()) {
        firstIds.assign(s.ids.begin(), s.ids.end());
        firstTensors.assign(s.tensors.begin(), s.tensors.end());
        EXPECT_EQ(firstIds, (std::vector<std::uint32_t>{12, 16}));  // k = 2, stride 2: (0,0,2), (0,2,2)
      }
      EXPECT_EQ(s.ids, firstIds) << name;
      EXPECT_EQ(s.tensors, firstTensors) << name;
      EXPECT_EQ(s.unselected, fx.voxels() - firstIds.size()) << name;
    }
  }
}

TEST(Mif, HeaderWithASeparateDataFileAtAnOffset) {
  test::MifFixture fx;
  fx.datatype = "Float64BE";
  fx.fillDistinct(true);
  const fs::path sub = tmpDir() / "mih-sub";
  fs::create_directories(sub);
  test::writeMih(sub / "t.mih", fx, "t.dat", 100);
  // The data file is found beside the header, not in the working directory.
  const io::TensorField f = read(sub / "t.mih");
  expectMatches(f, fx);
  EXPECT_NE(f.description.find("data in"), std::string::npos) << f.description;
  EXPECT_NE(f.frame.find("scanner"), std::string::npos) << f.frame;
}

TEST(Mif, MihHeaderMayEndAtTheEndOfItsFile) {
  test::MifFixture fx;
  fx.fillDistinct(true);
  const fs::path mih = tmpDir() / "no-end.mih";
  test::writeMih(mih, fx, "no-end.dat", 0);
  std::string header = test::slurpBytes(mih);
  ASSERT_TRUE(header.ends_with("\nEND\n"));
  header.resize(header.size() - 4);  // as MRtrix 3.0.3's mrconvert writes a .mih
  test::writeFile(mih, header);
  expectMatches(read(mih), fx);
  // Its last line may also lack its newline.
  header.pop_back();
  test::writeFile(mih, header);
  expectMatches(read(mih), fx);
  // A .mif's data follows its header, so the header must end with END.
  const fs::path mif = tmpDir() / "no-end.mif";
  test::writeFile(mif, header);
  try {
    read(mif);
    ADD_FAILURE() << "a .mif without END was read";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no END line"), std::string::npos) << e.what();
  }
}

TEST(Mif, ScalingIsApplied) {
  test::MifFixture fx;
  fx.datatype = "Int16LE";
  fx.fillDistinct(true);
  fx.scaling = "0.5,0.25";
  const fs::path p = tmpDir() / "scaled.mif";
  test::writeMif(p, fx);
  expectMatches(read(p), fx, 0.5, 0.25);
}

TEST(Mif, RotationAndTranslationPlaceTheGridButDoNotRotateTensors) {
  test::MifFixture fx;
  const double c = std::cos(0.5), s = std::sin(0.5);
  fx.transform = {{c, -s, 0, 10}, {s, c, 0, -20}, {0, 0, 1, 30.5}};
  fx.layout = {"-0", "+1", "+2", "+3"};
  fx.fillDistinct(true);
  const fs::path p = tmpDir() / "rotated.mif";
  test::writeMif(p, fx);
  const io::TensorField f = read(p);
  expectMatches(f, fx);
  ASSERT_TRUE(f.grid);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(f.grid->spacing[k], fx.vox[k], 1e-12);
  EXPECT_NEAR(f.grid->directions[3], s, 1e-12);  // column 0 is R's first column
  EXPECT_NEAR(f.grid->origin[1], -20, 1e-12);
  EXPECT_TRUE(f.warnings.empty());
  EXPECT_NE(f.space.find("RAS"), std::string::npos);
}

TEST(Mif, NonOrthonormalTransformUsesItsRotationWithAWarning) {
  test::MifFixture fx;
  fx.fillDistinct(true);
  fx.transform = {{2, 0, 0, 1}, {0, 2, 0, 2}, {0, 0, 2, 3}};  // vox folded in twice
  const fs::path p = tmpDir() / "scaled-transform.mif";
  test::writeMif(p, fx);
  const io::TensorField f = read(p);
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_NE(f.warnings[0].find("not orthonormal"), std::string::npos) << f.warnings[0];
  fx.transform = {{1, 0, 0, 1}, {0, 1, 0, 2}, {0, 0, 1, 3}};  // what is drawn: its polar part, the identity
  expectMatches(f, fx);
}

TEST(Mif, NoTransformPlacesByVoxWithAWarning) {
  test::MifFixture fx;
  fx.fillDistinct(true);
  fx.transform.clear();
  const fs::path p = tmpDir() / "no-transform.mif";
  test::writeMif(p, fx);
  const io::TensorField f = read(p);
  ASSERT_EQ(f.warnings.size(), 1u);
  fx.transform = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
  expectMatches(f, fx);
}

TEST(Mif, NonFiniteTensorsAreSkippedAndCounted) {
  test::MifFixture fx;
  fx.fillDistinct(true);
  fx.mrtrix[3][4] = NAN;
  fx.mrtrix[5][0] = INFINITY;
  fx.layout = {"+0", "+1", "+2", "+3"};
  const fs::path p = tmpDir() / "nan.mif";
  test::writeMif(p, fx);
  const io::TensorField f = read(p);
  EXPECT_EQ(f.size(), fx.voxels() - 2);
  EXPECT_EQ(f.skippedNonFinite, 2u);
  EXPECT_EQ(f.totalPoints, fx.voxels());
}

// A finite Float64 beyond single precision is an overflow, a NaN or Inf the
// file's own, in every layout: the gathering path once kept values as floats,
// where 1e39 became Inf and was counted as the file's (an attacker run).
TEST(Mif, OverflowIsToldFromNonFiniteInEveryLayout) {
  for (const auto& layout : {std::array<std::string, 4>{"+1", "+2", "+3", "+0"},
                             std::array<std::string, 4>{"+0", "+1", "+2", "+3"},
                             std::array<std::string, 4>{"-3", "+0", "+2", "+1"}}) {
    test::MifFixture fx;
    fx.datatype = "Float64LE";
    fx.fillDistinct(true);
    fx.mrtrix[3][4] = NAN;
    fx.mrtrix[5][0] = 1e39;
    fx.mrtrix[6][1] = -1e300;
    fx.mrtrix[7][2] = INFINITY;
    fx.mrtrix[7][3] = 1e39;  // the file's Inf decides: non-finite
    fx.layout = layout;
    const fs::path p = tmpDir() / "overflow.mif";
    test::writeMif(p, fx);
    const io::TensorField f = read(p);
    EXPECT_EQ(f.skippedNonFinite, 2u) << layout[0];
    EXPECT_EQ(f.skippedOverflow, 2u) << layout[0];
    EXPECT_EQ(f.size(), fx.voxels() - 4) << layout[0];
  }
}

TEST(Mif, MaskInAnyLayout) {
  // A 2x3x4 mask stored k fastest, j descending: keeps voxels 1, 6 and 23.
  const std::string header =
      "mrtrix image\ndim: 2,3,4\nvox: 1,1,1\nlayout: +2,-1,+0\ndatatype: UInt8\nfile: mask.raw\nEND\n";
  std::string raw(24, '\0');
  for (const int v : {1, 6, 23}) {
    const int i = v % 2, j = v / 2 % 3, k = v / 6;
    raw[std::size_t(k + 4 * (2 - j) + 12 * i)] = 1;
  }
  test::writeFile(tmpDir() / "mask.mih", header);
  test::writeFile(tmpDir() / "mask.raw", raw);
  const int dims[3] = {2, 3, 4};
  const io::ScalarVolume m = io::readScalarVolume((tmpDir() / "mask.mih").string(), dims);
  ASSERT_EQ(m.values.size(), 24u);
  for (int v = 0; v < 24; ++v) EXPECT_EQ(m.values[std::size_t(v)], (v == 1 || v == 6 || v == 23) ? 1.f : 0.f) << v;

  test::MifFixture fx;
  fx.fillDistinct(true);
  const fs::path p = tmpDir() / "masked.mif";
  test::writeMif(p, fx);
  io::ReadOptions o;
  o.selection.maskPath = (tmpDir() / "mask.mih").string();
  const io::TensorField f = read(p, o);
  EXPECT_EQ(f.ids, (std::vector<std::uint32_t>{1, 6, 23}));
  EXPECT_EQ(f.masked, 21u);
}

TEST(Mif, BadInputFailsWithOneLineNamingFileAndProblem) {
  test::MifFixture fx;
  fx.fillDistinct(true);
  const fs::path good = tmpDir() / "good.mif";
  test::writeMif(good, fx);
  const std::string goodBytes = test::slurpBytes(good);
  const std::string dataOffset = goodBytes.substr(goodBytes.find("file: . ") + 8, 4);
  auto withHeaderLine = [&](const std::string& from, const std::string& to) {
    std::string b = goodBytes;
    const auto at = b.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return b.replace(at, from.size(), to);
  };
  const std::string longLine = "comments: " + std::string(1 << 21, 'x') + "\n";
  struct Case {
    std::string name, bytes, message;
  } cases[] = {
      {"truncated", goodBytes.substr(0, goodBytes.size() - 5), "data is truncated"},
      {"header-only", goodBytes.substr(0, goodBytes.find("END")), "no END line"},
      {"not-mrtrix", "P5\n2 2\n255\n", "not an MRtrix image"},
      {"binary", std::string("\x89PNG\r\n\x1a\n") + std::string(2 << 20, 'x'), "not an MRtrix image"},
      {"huge-dims", withHeaderLine("dim: 2,3,4,6", "dim: 100000,100000,1000,6"), "more than 2^32-256 voxels"},
      {"overflow", withHeaderLine("dim: 2,3,4,6", "dim: 2147483647,2147483647,2147483647,2147483647"), "overflows"},
      {"dim-zero", withHeaderLine("dim: 2,3,4,6", "dim: 2,0,4,6"), "dim: size 0"},
      {"dim-negative", withHeaderLine("dim: 2,3,4,6", "dim: 2,-3,4,6"), "not a non-negative integer"},
      {"five-components", withHeaderLine("dim: 2,3,4,6", "dim: 2,3,4,5"), "hold no tensor"},
      {"three-axes", withHeaderLine("dim: 2,3,4,6\nvox: 1.5,2,2.5,nan\nlayout: +1,+2,+3,+0",
                                    "dim: 2,3,4\nvox: 1.5,2,2.5\nlayout: +0,+1,+2"),
       "hold no tensor"},
      {"bit", withHeaderLine("Float32LE", "Bit"), "not supported"},
      {"complex", withHeaderLine("Float32LE", "CFloat32LE"), "not supported"},
      {"unknown-type", withHeaderLine("Float32LE", "Float16LE"), "not an MRtrix data type"},
      {"int8le", withHeaderLine("Float32LE", "Int8LE"), "not an MRtrix data type"},
      {"offset-beyond-eof", withHeaderLine("file: . " + dataOffset, "file: . 9999"), "beyond the end"},
      {"offset-in-header", withHeaderLine("file: . " + dataOffset, "file: . 0016"), "inside the header"},
      {"duplicate-dim", withHeaderLine("vox:", "dim: 2,3,4,6\nvox:"), "\"dim\" appears twice"},
      {"duplicate-datatype", withHeaderLine("vox:", "datatype: Float64LE\nvox:"), "\"datatype\" appears twice"},
      {"two-files", withHeaderLine("vox:", "file: other.dat\nvox:"), "several files"},
      {"no-layout", withHeaderLine("layout: +1,+2,+3,+0\n", ""), "no layout"},
      {"no-file", withHeaderLine("file: . " + dataOffset, "comments: none"), "no file"},
      {"layout-repeats", withHeaderLine("+1,+2,+3,+0", "+1,+1,+3,+0"), "not an order"},
      {"layout-short", withHeaderLine("+1,+2,+3,+0", "+1,+2,+0"), "axes"},
      {"layout-range", withHeaderLine("+1,+2,+3,+0", "+1,+2,+3,+4"), "not an order"},
      {"vox-zero", withHeaderLine("vox: 1.5,", "vox: 0,"), "not positive"},
      {"vox-negative", withHeaderLine("vox: 1.5,", "vox: -1.5,"), "not positive"},
      {"vox-nan", withHeaderLine("vox: 1.5,", "vox: nan,"), "not finite"},
      {"vox-inf", withHeaderLine("vox: 1.5,", "vox: inf,"), "not finite"},
      {"vox-word", withHeaderLine("vox: 1.5,", "vox: 1.5mm,"), "not a number"},
      {"transform-nan", withHeaderLine("transform: 1, 0, 0, 10", "transform: nan, 0, 0, 10"), "not finite"},
      {"transform-short", withHeaderLine("transform: 1, 0, 0, 10", "transform: 1, 0, 0"), "not 4"},
      {"transform-two-rows", withHeaderLine("transform: 1, 0, 0, 10\n", ""), "three rows"},
      {"transform-four-rows", withHeaderLine("vox:", "transform: 0,0,0,1\nvox:"), "more than three rows"},
      {"transform-singular", withHeaderLine("transform: 1, 0, 0, 10", "transform: 0, 1, 0, 10"), "singular"},
      {"no-colon", withHeaderLine("vox:", "garbage line\nvox:"), "not \"key: value\""},
      {"nul-byte", withHeaderLine("vox:", std::string("comments: a") + '\0' + "b\nvox:"), "NUL byte"},
      {"long-line", withHeaderLine("vox:", longLine + "vox:"), "longer than 1 MiB"},
      {"scaling-nan", withHeaderLine("vox:", "scaling: 0,nan\nvox:"), "not finite"},
      {"missing-data-file", withHeaderLine("file: . " + dataOffset, "file: absent.dat"), "cannot open data file"},
  };
  for (const Case& c : cases) {
    const fs::path p = tmpDir() / ("bad-" + c.name + ".mif");
    test::writeFile(p, c.bytes);
    const std::string e = test::readError(p);
    EXPECT_EQ(e.rfind("readMif: " + p.string() + ": ", 0), 0u) << c.name << ": " << e;
    EXPECT_NE(e.find(c.message), std::string::npos) << c.name << ": " << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << c.name;
  }
  io::ReadOptions fsl;
  fsl.layout = "fsl";
  EXPECT_NE(test::readError(good, fsl).find("--layout does not apply"), std::string::npos);
}

TEST(Mif, FifoHeaderOrDataFileIsRefusedWithoutBlocking) {
  const fs::path fifo = tmpDir() / "fifo.dat";
  fs::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  test::writeFile(tmpDir() / "fifo.mih", "mrtrix image\ndim: 1,1,1,6\nvox: 1,1,1,1\nlayout: +1,+2,+3,+0\n"
                                         "datatype: Float32LE\nfile: fifo.dat\nEND\n");
  EXPECT_NE(test::readError(tmpDir() / "fifo.mih").find("is not a regular file"), std::string::npos);
  const fs::path fifoMif = tmpDir() / "fifo.mif";
  fs::remove(fifoMif);
  ASSERT_EQ(mkfifo(fifoMif.c_str(), 0600), 0);
  try {
    io::readMif(fifoMif.string(), {});
    ADD_FAILURE() << "a FIFO was read";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is not a regular file"), std::string::npos) << e.what();
  }
}

namespace {

// A 4-D NIfTI-1 tensor volume (six volumes in MRtrix's order, float32),
// placed by an sform alone.
void writeNifti(const fs::path& path, const int dims[3], const double affine[3][4],
                const std::vector<std::array<float, 6>>& voxels) {
  const int64_t d[8] = {4, dims[0], dims[1], dims[2], 6, 1, 1, 1};
  nifti_image* nim = nifti_make_new_nim(d, NIFTI_TYPE_FLOAT32, 1);
  ASSERT_TRUE(nim);
  auto* data = static_cast<float*>(nim->data);
  for (std::size_t v = 0; v < voxels.size(); ++v)
    for (std::size_t c = 0; c < 6; ++c) data[c * voxels.size() + v] = voxels[v][c];
  nim->sform_code = NIFTI_XFORM_SCANNER_ANAT;
  nim->qform_code = 0;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) nim->sto_xyz.m[r][c] = r < 3 ? affine[r][c] : (c == 3 ? 1 : 0);
  const std::string prefix = path.string();
  ASSERT_EQ(nifti_set_filenames(nim, prefix.c_str(), 0, 1), 0);
  nifti_image_write(nim);
  nifti_image_free(nim);
}

}  // namespace

// MRtrix's own writer as a peer: mrconvert turns a NIfTI tensor volume into
// .mif with other strides and data types (and realigns the axes to the
// scanner's, so voxel indices differ); the same tensors must sit at the same
// world positions as our NIfTI reader gives with --layout mrtrix.
TEST(Mif, MrconvertOutputMatchesTheNiftiReader) {
  const int dims[3] = {3, 4, 5};
  std::vector<std::array<float, 6>> voxels(60);
  for (std::size_t v = 0; v < voxels.size(); ++v)
    for (std::size_t c = 0; c < 6; ++c) voxels[v][c] = float(std::sin(double(7 * v + c)) * 1e-3);
  const double c = std::cos(0.3), s = std::sin(0.3);
  // An oblique affine of 2 x 2.5 x 3 mm voxels, with det > 0 and with x mirrored (det < 0).
  const double oblique[3][4] = {{2 * c, -2.5 * s, 0, -10}, {2 * s, 2.5 * c, 0, 20}, {0, 0, 3, 5}};
  const double mirrored[3][4] = {{-2, 0, 0, 40}, {0, 2.5, 0, -3}, {0, 0, 3, 1}};
  io::ReadOptions mrtrix;
  mrtrix.layout = "mrtrix";
  for (const auto* affine : {&oblique, &mirrored}) {
    const fs::path nii = tmpDir() / "peer.nii";
    writeNifti(nii, dims, *affine, voxels);
    const io::TensorField ref = read(nii, mrtrix);
    ASSERT_EQ(ref.size(), voxels.size());
    // mrconvert writes a .mih without an END line; its data file beside it.
    for (const auto& [opts, name] : {std::pair{"-strides -1,3,2,4", "peer.mif"},
                                     {"-strides 4,3,-2,1 -datatype float64be", "peer.mif"},
                                     {"-datatype float32be", "peer.mif"},
                                     {"-strides 3,-1,2,4", "peer.mih"}}) {
      const fs::path mif = tmpDir() / name;
      const std::string cmd = std::string(TG_MRCONVERT) + " -quiet -force " + nii.string() + " " + mif.string() +
                              " " + opts + " 2>&1";
      ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
      const io::TensorField f = read(mif);
      ASSERT_EQ(f.size(), ref.size()) << opts;
      // Match each of ours to the reference sample at the same place.
      for (std::size_t a = 0; a < f.size(); ++a) {
        std::size_t best = 0;
        double bestD = INFINITY;
        for (std::size_t b = 0; b < ref.size(); ++b) {
          const double d = std::hypot(f.positions[3 * a] - ref.positions[3 * b],
                                      f.positions[3 * a + 1] - ref.positions[3 * b + 1],
                                      f.positions[3 * a + 2] - ref.positions[3 * b + 2]);
          if (d < bestD) bestD = d, best = b;
        }
        ASSERT_LT(bestD, 1e-3) << opts << " sample " << a;
        for (std::size_t k = 0; k < 6; ++k)
          EXPECT_EQ(f.tensors[6 * a + k], ref.tensors[6 * best + k]) << opts << " sample " << a;
      }
    }
  }
}

// MRtrix's own tensor fit as a peer: dwi2tensor fits noiseless signals of one
// known tensor D (given in scanner space, as dw_scheme's gradients are) in a
// rotated image stored x-descending; the .mif it writes must read back as D
// at every voxel, unrotated, which pins the component order and the frame.
TEST(Mif, Dwi2tensorOutputReadsBackAsTheFittedTensor) {
  const double d[6] = {1.2e-3, 0.3e-3, 0.2e-3, 0.8e-3, -0.1e-3, 0.5e-3};  // xx xy xz yy yz zz
  std::vector<std::array<double, 4>> scheme{{0, 0, 0, 0}};
  for (int k = 0; k < 12; ++k) {  // twelve directions on a spiral
    const double z = 1 - (k + 0.5) / 6.0, r = std::sqrt(1 - z * z), phi = 2.4 * k;
    scheme.push_back({r * std::cos(phi), r * std::sin(phi), z, 1000});
  }
  const int nv = int(scheme.size()), voxels = 8;
  std::string raw;
  for (int v = 0; v < nv; ++v) {
    const auto& g = scheme[std::size_t(v)];
    const double gdg = d[0] * g[0] * g[0] + d[3] * g[1] * g[1] + d[5] * g[2] * g[2] +
                       2 * (d[1] * g[0] * g[1] + d[2] * g[0] * g[2] + d[4] * g[1] * g[2]);
    const float s = float(1000 * std::exp(-g[3] * gdg));
    for (int i = 0; i < voxels; ++i) raw.append(reinterpret_cast<const char*>(&s), 4);
  }
  std::string header = "mrtrix image\ndim: 2,2,2," + std::to_string(nv) +
                       "\nvox: 2,2,2,1\nlayout: -0,+1,+2,+3\ndatatype: Float32LE\n"
                       "transform: 0.8660254037844387,-0.5,0,-4\ntransform: 0.5,0.8660254037844387,0,6\n"
                       "transform: 0,0,1,8\n";
  for (const auto& g : scheme)
    header += "dw_scheme: " + std::to_string(g[0]) + "," + std::to_string(g[1]) + "," + std::to_string(g[2]) + "," +
              std::to_string(g[3]) + "\n";
  test::writeFile(tmpDir() / "dwi.mih", header + "file: dwi.raw\nEND\n");
  test::writeFile(tmpDir() / "dwi.raw", raw);
  const fs::path dt = tmpDir() / "dt.mif";
  const std::string cmd =
      std::string(TG_DWI2TENSOR) + " -quiet -force " + (tmpDir() / "dwi.mih").string() + " " + dt.string() + " 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const io::TensorField f = read(dt);
  ASSERT_EQ(f.size(), std::size_t(voxels));
  for (std::size_t v = 0; v < f.size(); ++v)
    for (std::size_t k = 0; k < 6; ++k) EXPECT_NEAR(f.tensors[6 * v + k], d[k], 1e-7) << "voxel " << v << " " << k;
  // Voxel (1, 0, 0) lies one rotated 2 mm step from the origin.
  EXPECT_NEAR(f.positions[3], -4 + 2 * 0.8660254037844387, 1e-5);
  EXPECT_NEAR(f.positions[4], 6 + 2 * 0.5, 1e-5);
}
