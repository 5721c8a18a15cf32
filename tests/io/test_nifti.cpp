// Tier 2: NIfTI-1/-2 input through libnifti2: layouts, placement, tensor
// frames, and bad input. Fixtures are written with libnifti2 itself.
#include <gtest/gtest.h>

#include <nifti2_io.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <filesystem>
#include <fstream>

#include "io/core/readers.h"
#include "io/io_test_util.h"

using namespace tg;
namespace fs = std::filesystem;

namespace {

fs::path tmpDir() { return test::scratchDir("nifti"); }

struct Fixture {
  int nx = 2, ny = 1, nz = 1;
  bool symmatrix = false;  // 5D (x y z 1 6) with the SYMMATRIX intent, else 4D (x y z 6)
  bool nifti2 = false;
  double affine[3][4] = {{2, 0, 0, 10}, {0, 2, 0, 20}, {0, 0, 2, 30}};
  std::vector<std::array<float, 6>> voxels;  // six values per voxel, in file order
};

void write(const fs::path& path, const Fixture& fx) {
  const int64_t dims[8] = {fx.symmatrix ? 5 : 4, fx.nx, fx.ny, fx.nz, fx.symmatrix ? 1 : 6, fx.symmatrix ? 6 : 1, 1, 1};
  nifti_image* nim = nifti_make_new_nim(dims, NIFTI_TYPE_FLOAT32, 1);
  ASSERT_TRUE(nim);
  const std::size_t n = std::size_t(fx.nx * fx.ny * fx.nz);
  ASSERT_EQ(fx.voxels.size(), n);
  auto* data = static_cast<float*>(nim->data);
  for (std::size_t v = 0; v < n; ++v)
    for (int c = 0; c < 6; ++c) data[c * n + v] = fx.voxels[v][c];
  nim->sform_code = NIFTI_XFORM_SCANNER_ANAT;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) nim->sto_xyz.m[r][c] = r < 3 ? fx.affine[r][c] : (c == 3 ? 1 : 0);
  if (fx.symmatrix) nim->intent_code = NIFTI_INTENT_SYMMATRIX;
  if (fx.nifti2) {
    // libnifti2 3.0.1's writer leaves the header out of a NIfTI-2 .nii, so
    // the fixture is assembled from its converted header: 540 bytes, the
    // 4-byte extension flag, then the data at offset 544.
    nim->nifti_type = NIFTI_FTYPE_NIFTI2_1;  // sets the magic to n+2
    nifti_2_header h{};
    ASSERT_EQ(nifti_convert_nim2n2hdr(nim, &h), 0);
    h.vox_offset = 544;
    std::memcpy(h.magic, "n+2\0\r\n\032\n", 8);  // the converter leaves the last four bytes 0
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(&h), sizeof h);
    out.write("\0\0\0\0", 4);
    out.write(static_cast<const char*>(nim->data), std::streamsize(4 * 6 * n));
    nifti_image_free(nim);
    return;
  }
  std::string prefix = path.string();
  ASSERT_EQ(nifti_set_filenames(nim, prefix.c_str(), 0, 1), 0);
  nifti_image_write(nim);
  nifti_image_free(nim);
  ASSERT_TRUE(fs::exists(path)) << path;
}

std::string errorOf(const fs::path& p, const io::ReadOptions& o = {}) { return test::readError(p, o); }

}  // namespace

TEST(Nifti, FslLayoutPlacementAndBothFileKinds) {
  Fixture fx;
  fx.voxels = {{{1, 0.1f, 0.2f, 2, 0.3f, 3}}, {{4, 0, 0, 5, 0, 6}}};
  fx.affine[0][0] = -2;  // radiological storage (det < 0): FSL's frame is the voxel frame mirrored... back to x
  for (const char* name : {"fsl.nii", "fsl.nii.gz"}) {
    for (bool v2 : {false, std::string(name) == "fsl.nii"}) {
      fx.nifti2 = v2;
      const fs::path p = tmpDir() / (std::string(v2 ? "n2-" : "n1-") + name);
      write(p, fx);
      const io::TensorField f = io::readTensorField(p.string(), {});
      ASSERT_EQ(f.size(), 2u) << p;
      EXPECT_EQ(f.positions, (std::vector<float>{10, 20, 30, 8, 20, 30})) << p;
      // det < 0: the rotation part diag(-1, 1, 1) mirrors x, so xy and xz flip.
      const float expect[6] = {1, -0.1f, -0.2f, 2, 0.3f, 3};
      for (int k = 0; k < 6; ++k) EXPECT_FLOAT_EQ(f.tensors[k], expect[k]) << p << " component " << k;
      EXPECT_NE(f.description.find(v2 ? "NIfTI-2" : "NIfTI-1"), std::string::npos) << f.description;
    }
  }
}

// A big-endian file reads as its little-endian twin. Its raw header is in
// the file's byte order: the checks made on it (dims, vox_offset) must swap.
TEST(Nifti, BigEndianFileReadsLikeItsLittleEndianTwin) {
  Fixture fx;
  fx.voxels = {{{1, 0.1f, 0.2f, 2, 0.3f, 3}}, {{4, 0, 0, 5, 0, 6}}};
  const fs::path le = tmpDir() / "le.nii", be = tmpDir() / "be.nii";
  write(le, fx);
  std::ifstream in(le, std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(in), {}};
  ASSERT_EQ(bytes.size(), 352u + 4 * 12);
  nifti_1_header h;
  std::memcpy(&h, bytes.data(), sizeof h);
  nifti_swap_as_nifti1(&h);
  std::memcpy(bytes.data(), &h, sizeof h);
  for (std::size_t at = 352; at < bytes.size(); at += 4) std::reverse(bytes.begin() + long(at), bytes.begin() + long(at) + 4);
  std::ofstream(be, std::ios::binary) << bytes;
  const io::TensorField a = io::readTensorField(le.string(), {}), b = io::readTensorField(be.string(), {});
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.tensors, b.tensors);
}

TEST(Nifti, FslTensorsMeanTheSameWorldTensorWhateverTheStorageHandedness) {
  // FSL's voxel frame is radiological whatever the storage, so the same FSL
  // tensor stored neurologically (det > 0) or radiologically (det < 0) is the
  // same tensor in the world.
  Fixture neuro, radio;
  neuro.nx = radio.nx = 1;
  neuro.voxels = radio.voxels = {{{1, 0.1f, 0.2f, 2, 0.3f, 3}}};
  radio.affine[0][0] = -2;
  write(tmpDir() / "neuro.nii", neuro);
  write(tmpDir() / "radio.nii", radio);
  const auto a = io::readTensorField((tmpDir() / "neuro.nii").string(), {});
  const auto b = io::readTensorField((tmpDir() / "radio.nii").string(), {});
  for (int k = 0; k < 6; ++k) EXPECT_FLOAT_EQ(a.tensors[k], b.tensors[k]) << k;
  // Read as a plain voxel-frame layout, the two differ: the convention matters.
  io::ReadOptions voxelFrame;
  voxelFrame.layout = "vtk";
  const auto c = io::readTensorField((tmpDir() / "neuro.nii").string(), voxelFrame);
  const auto d = io::readTensorField((tmpDir() / "radio.nii").string(), voxelFrame);
  EXPECT_NE(c.tensors, d.tensors);
}

TEST(Nifti, SymmatrixIntentIsLowerTriangleAlongDimensionFive) {
  Fixture fx;
  fx.nx = 1;
  fx.symmatrix = true;
  fx.voxels = {{{1, 0.1f, 2, 0.2f, 0.3f, 3}}};  // xx xy yy xz yz zz
  write(tmpDir() / "sym.nii", fx);
  const auto f = io::readTensorField((tmpDir() / "sym.nii").string(), {});
  ASSERT_EQ(f.size(), 1u);
  EXPECT_NE(f.layout.find("nifti"), std::string::npos);
  const float expect[6] = {1, 0.1f, 0.2f, 2, 0.3f, 3};  // xx xy xz yy yz zz
  for (int k = 0; k < 6; ++k) EXPECT_FLOAT_EQ(f.tensors[k], expect[k]) << k;
}

TEST(Nifti, RotatedAffineRotatesVoxelFrameTensorsButNotMrtrixOnes) {
  // 90 degrees about z, with anisotropic spacing: the orthogonal part maps
  // voxel x to world y, so a tensor long along voxel x is long along world y.
  Fixture fx;
  fx.nx = 1;
  const double a[3][4] = {{0, -3, 0, 0}, {1.5, 0, 0, 0}, {0, 0, 2, 0}};
  std::memcpy(fx.affine, a, sizeof a);
  fx.voxels = {{{5, 0, 1, 0, 0, 1}}};  // diag(5, 1, 1) as xx xy yy xz yz zz
  write(tmpDir() / "rot-nifti.nii", fx);
  io::ReadOptions nifti;
  nifti.layout = "nifti";
  const auto r = io::readTensorField((tmpDir() / "rot-nifti.nii").string(), nifti);
  EXPECT_NEAR(r.tensors[0], 1, 1e-6);
  EXPECT_NEAR(r.tensors[3], 5, 1e-6);
  EXPECT_NEAR(r.tensors[1], 0, 1e-6);
  fx.voxels = {{{5, 1, 1, 0, 0, 0}}};  // diag(5, 1, 1) as xx yy zz xy xz yz
  write(tmpDir() / "rot-mrtrix.nii", fx);
  io::ReadOptions mrtrix;
  mrtrix.layout = "mrtrix";
  const auto m = io::readTensorField((tmpDir() / "rot-mrtrix.nii").string(), mrtrix);
  EXPECT_FLOAT_EQ(m.tensors[0], 5);
  EXPECT_FLOAT_EQ(m.tensors[3], 1);
}

TEST(Nifti, MrtrixOrder) {
  Fixture fx;
  fx.nx = 1;
  fx.voxels = {{{1, 2, 3, 0.1f, 0.2f, 0.3f}}};  // xx yy zz xy xz yz
  write(tmpDir() / "mrtrix.nii", fx);
  io::ReadOptions o;
  o.layout = "mrtrix";
  const auto f = io::readTensorField((tmpDir() / "mrtrix.nii").string(), o);
  const float expect[6] = {1, 0.1f, 0.2f, 2, 0.3f, 3};
  for (int k = 0; k < 6; ++k) EXPECT_FLOAT_EQ(f.tensors[k], expect[k]) << k;
}

TEST(Nifti, MaskAndSliceSelectVoxelsBeforeTheDataIsRead) {
  Fixture fx;
  fx.nx = 4;
  fx.ny = 3;
  fx.nz = 2;
  for (int v = 0; v < 24; ++v) fx.voxels.push_back({{float(v + 1), 0, 0, 1, 0, 1}});
  write(tmpDir() / "grid.nii", fx);
  // A mask keeping the voxels with even index.
  const int64_t dims[8] = {3, 4, 3, 2, 1, 1, 1, 1};
  nifti_image* mask = nifti_make_new_nim(dims, NIFTI_TYPE_UINT8, 1);
  for (int v = 0; v < 24; ++v) static_cast<std::uint8_t*>(mask->data)[v] = v % 2 == 0;
  const std::string maskPath = (tmpDir() / "mask.nii.gz").string();
  nifti_set_filenames(mask, maskPath.c_str(), 0, 1);
  nifti_image_write(mask);
  nifti_image_free(mask);
  io::ReadOptions o;
  o.selection.maskPath = maskPath;
  o.selection.slice = io::SliceSpec{2, 1, 1};
  const auto f = io::readTensorField((tmpDir() / "grid.nii").string(), o);
  EXPECT_EQ(f.size(), 6u);  // 12 voxels in slice k = 1, half of them even
  EXPECT_EQ(f.unselected, 12u);
  EXPECT_EQ(f.masked, 6u);
  for (std::size_t i = 0; i < f.size(); ++i) {
    EXPECT_EQ(f.ids[i] % 2, 0u);
    EXPECT_GE(f.ids[i], 12u);
    EXPECT_FLOAT_EQ(f.tensors[6 * i], float(f.ids[i] + 1));  // the data of that voxel, not its neighbour's
  }
}

namespace {

// A uint8 mask of `dims` placed by the sform `affine`, values in index order (i fastest).
void writeMask(const fs::path& path, const int d[3], const double affine[3][4], const std::vector<std::uint8_t>& v) {
  const int64_t dims[8] = {3, d[0], d[1], d[2], 1, 1, 1, 1};
  nifti_image* mask = nifti_make_new_nim(dims, NIFTI_TYPE_UINT8, 1);
  ASSERT_TRUE(mask);
  std::copy(v.begin(), v.end(), static_cast<std::uint8_t*>(mask->data));
  mask->sform_code = NIFTI_XFORM_SCANNER_ANAT;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) mask->sto_xyz.m[r][c] = r < 3 ? affine[r][c] : (c == 3 ? 1 : 0);
  const std::string name = path.string();
  nifti_set_filenames(mask, name.c_str(), 0, 1);
  nifti_image_write(mask);
  nifti_image_free(mask);
}

}  // namespace

// Masks are applied by voxel index, so a mask of the same grid stored in
// another axis order (mrconvert stores a LAS image's mask with i reversed,
// near RAS) is first put in the tensors' order by where its voxels lie; it
// was refused as lying elsewhere. A mask one voxel off is still refused.
TEST(Nifti, AMaskOfTheSameGridInAnotherAxisOrderSelectsTheSameVoxels) {
  Fixture fx;
  fx.nx = 4;
  fx.ny = 3;
  fx.nz = 2;
  fx.affine[0][0] = -2;  // LAS, as FSL stores
  for (int v = 0; v < 24; ++v) fx.voxels.push_back({{float(v + 1), 0, 0, 1, 0, 1}});
  const fs::path grid = tmpDir() / "las-grid.nii";
  write(grid, fx);
  const int d[3] = {4, 3, 2};
  auto keep = [](int i, int j, int k) { return std::uint8_t((i * 7 + j * 3 + k * 5) % 4 == 0); };
  auto keptIds = [&](const fs::path& mask) {
    io::ReadOptions o;
    o.selection.maskPath = mask.string();
    const io::TensorField f = io::readTensorField(grid.string(), o);
    for (std::size_t n = 0; n < f.size(); ++n) EXPECT_FLOAT_EQ(f.tensors[6 * n], float(f.ids[n] + 1));
    return f.ids;
  };
  std::vector<std::uint8_t> same;
  std::vector<std::uint32_t> expect;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) {
        same.push_back(keep(i, j, k));
        if (keep(i, j, k)) expect.push_back(std::uint32_t(i + 4 * (j + 3 * k)));
      }
  ASSERT_GT(expect.size(), 2u);
  writeMask(tmpDir() / "m-same.nii", d, fx.affine, same);
  EXPECT_EQ(keptIds(tmpDir() / "m-same.nii"), expect);
  // i reversed: axis 0 is +2 in x, from the other end.
  const double flipped[3][4] = {{2, 0, 0, 10 - 2 * 3}, {0, 2, 0, 20}, {0, 0, 2, 30}};
  std::vector<std::uint8_t> v;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) v.push_back(keep(3 - i, j, k));
  writeMask(tmpDir() / "m-flipped.nii", d, flipped, v);
  EXPECT_EQ(keptIds(tmpDir() / "m-flipped.nii"), expect);
  // Axes reordered (the mask's axes are the tensors' k, i, j) and its second one reversed.
  const int pd[3] = {2, 4, 3};
  const double reordered[3][4] = {{0, 2, 0, 10 - 2 * 3}, {0, 0, 2, 20}, {2, 0, 0, 30}};
  v.clear();
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 2; ++k) v.push_back(keep(3 - i, j, k));
  writeMask(tmpDir() / "m-reordered.nii", pd, reordered, v);
  EXPECT_EQ(keptIds(tmpDir() / "m-reordered.nii"), expect);
  // One voxel off in z: the same dimensions elsewhere.
  const double shifted[3][4] = {{-2, 0, 0, 10}, {0, 2, 0, 20}, {0, 0, 2, 32}};
  writeMask(tmpDir() / "m-shifted.nii", d, shifted, same);
  EXPECT_NE(errorOf(grid, [&] {
              io::ReadOptions o;
              o.selection.maskPath = (tmpDir() / "m-shifted.nii").string();
              return o;
            }()).find("mask lies elsewhere"),
            std::string::npos);
#ifdef TG_MRCONVERT
  // MRtrix's own copy of the mask: i reversed on disk and in its transform.
  const fs::path mif = tmpDir() / "m-mrconvert.mif";
  const std::string cmd = std::string(TG_MRCONVERT) + " -quiet -force " + (tmpDir() / "m-same.nii").string() + " " +
                          mif.string() + " 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  EXPECT_EQ(keptIds(mif), expect);
#endif
}

namespace {

// `bytes` as a one-member gzip file at compression `level` (0: stored blocks,
// so that a flipped byte of the data survives inflation unchanged).
std::string gzipped(const std::string& bytes, int level) {
  z_stream z{};
  EXPECT_EQ(deflateInit2(&z, level, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY), Z_OK);
  std::string out(deflateBound(&z, uLong(bytes.size())), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = uInt(bytes.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = uInt(out.size());
  EXPECT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

}  // namespace

// A .nii.gz whose CRC disagrees with its data, or that ends without the
// CRC, is refused saying so. Before, a wrong CRC read as "data is truncated:
// ... the image ends after 4611686018427387903" (znzread's -1 as a count) and
// a stream cut at its trailer was drawn unchecked.
TEST(Nifti, CorruptGzipIsRefusedNamingTheFault) {
  Fixture fx;
  fx.nx = 16;
  fx.ny = 16;
  fx.nz = 16;
  fx.voxels.assign(4096, {{1, 0, 0, 1, 0, 1}});
  const fs::path plain = tmpDir() / "gz-src.nii";
  write(plain, fx);
  std::ifstream in(plain, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), {}};
  const fs::path d = tmpDir();
  for (int level : {0, 6}) {
    const std::string gz = gzipped(bytes, level);
    const std::string tag = "gz" + std::to_string(level) + "-";
    std::ofstream(d / (tag + "good.nii.gz"), std::ios::binary) << gz;
    const io::TensorField good = io::readTensorField((d / (tag + "good.nii.gz")).string(), {});
    EXPECT_EQ(good.size(), 4096u);
    // Trailing bytes after the stream are not part of it.
    std::ofstream(d / (tag + "trailing.nii.gz"), std::ios::binary) << gz << std::string(100, '\0');
    EXPECT_EQ(io::readTensorField((d / (tag + "trailing.nii.gz")).string(), {}).tensors, good.tensors);
    std::string crc = gz;
    crc[crc.size() - 8] = char(crc[crc.size() - 8] ^ 0x5a);  // the trailer: CRC-32, then the length
    std::ofstream(d / (tag + "crc.nii.gz"), std::ios::binary) << crc;
    std::ofstream(d / (tag + "cut.nii.gz"), std::ios::binary) << gz.substr(0, gz.size() - 8);
    struct Case {
      std::string file;
      const char* expect;
    } cases[] = {{tag + "crc.nii.gz", "gzip data is corrupt: incorrect data check"},
                 {tag + "cut.nii.gz", "gzip data is corrupt: the stream ends without its trailer"}};
    for (const Case& c : cases) {
      const std::string e = errorOf(d / c.file);
      EXPECT_NE(e.find(c.expect), std::string::npos) << c.file << ": " << e;
      EXPECT_NE(e.find((d / c.file).string() + ": gzip"), std::string::npos) << c.file << ": " << e;
      EXPECT_EQ(e.find('\n'), std::string::npos) << c.file << ": " << e;
    }
  }
  // A value flipped inside a stored block inflates cleanly; only the CRC tells.
  std::string flipped = gzipped(bytes, 0);
  const std::size_t at = flipped.find(bytes.substr(352, 64));
  ASSERT_NE(at, std::string::npos);
  flipped[at + 3] = char(flipped[at + 3] ^ 0x40);  // the first value's exponent: 1 becomes infinite
  std::ofstream(d / "flipped.nii.gz", std::ios::binary) << flipped;
  const std::string e = errorOf(d / "flipped.nii.gz");
  EXPECT_NE(e.find("gzip data is corrupt: incorrect data check"), std::string::npos) << e;
}

// The two-voxel fixture's bytes with the NIfTI-1 placement fields set: the
// qform and sform codes, a qform (by default unrotated, qfac 1) at `offset`,
// and pixdim.
struct Placement {
  std::int16_t qform = 1, sform = 1;
  float pixdim[3] = {2, 2, 2};
  float offset[3] = {10, 20, 30};
  float qfac = 1;
  float quatern[3] = {0, 0, 0};
};

std::string placedBytes(const fs::path& p, const Placement& pl) {
  Fixture fx;
  fx.voxels = {{{1, 0, 0, 1, 0, 1}}, {{2, 0, 0, 2, 0, 2}}};
  write(p, fx);  // sform diag(2) + (10, 20, 30)
  std::ifstream in(p, std::ios::binary);
  std::string b(std::istreambuf_iterator<char>(in), {});
  std::memcpy(&b[252], &pl.qform, 2);
  std::memcpy(&b[254], &pl.sform, 2);
  for (int k = 0; k < 3; ++k) std::memcpy(&b[256 + 4 * k], &pl.quatern[k], 4);  // quatern_b..d
  for (int k = 0; k < 3; ++k) std::memcpy(&b[268 + 4 * k], &pl.offset[k], 4);  // qoffset_x..z
  std::memcpy(&b[76], &pl.qfac, 4);  // pixdim[0]
  for (int k = 0; k < 3; ++k) std::memcpy(&b[80 + 4 * k], &pl.pixdim[k], 4);
  return b;
}

io::TensorField readPlaced(const Placement& pl) {
  const fs::path p = tmpDir() / "placed.nii";
  test::writeFile(p, placedBytes(p, pl));
  return io::readTensorField(p.string(), {});
}

// A file holding two placements that disagree draws where the sform says
// (as FSL, nibabel and MRtrix read it) and says so; one whose qform matches
// its sform says nothing.
TEST(Nifti, DisagreeingSformAndQformAreSaid) {
  const io::TensorField agree = readPlaced({});
  EXPECT_TRUE(agree.warnings.empty()) << agree.warnings.front();
  Placement moved;
  moved.offset[2] = 35;
  const io::TensorField f = readPlaced(moved);
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_NE(f.warnings[0].find("the sform and qform disagree (by up to 5.0"), std::string::npos) << f.warnings[0];
  EXPECT_FLOAT_EQ(f.positions[2], 30);  // the sform's
}

// A voxel size of 0 or below is invalid; libnifti2 put 1 in its place
// (a qform with pixdim -2 placed voxels 1 apart, where nibabel, and so DIPY,
// places them 2 apart). nibabel's reading is taken and said, for a qform and
// for pixdim alone; with an sform pixdim places nothing and is not said.
TEST(Nifti, NonPositiveVoxelSizesAreReadAsNibabelReadsThem) {
  struct Case {
    float pixdim;
    std::int16_t qform, sform;
    float stepX;
    const char* said;
  };
  const Case cases[] = {{-2, 1, 0, 2, "pixdim[1] (a voxel size) is -2; 2 is used, as nibabel uses it"},
                        {0, 1, 0, 1, "pixdim[1] (a voxel size) is 0; 1 is used"},
                        {-3, 0, 0, 3, "pixdim[1] (a voxel size) is -3; 3 is used"},
                        {2, 1, 0, 2, nullptr},
                        // The sform's diag(2) places: no word, and the qform
                        // built from |pixdim| agrees with it.
                        {-2, 1, 1, 2, nullptr}};
  for (const Case& c : cases) {
    Placement pl;
    pl.qform = c.qform;
    pl.sform = c.sform;
    pl.pixdim[0] = c.pixdim;
    if (!c.sform) pl.pixdim[1] = pl.pixdim[2] = 1;
    const io::TensorField f = readPlaced(pl);
    ASSERT_EQ(f.positions.size(), 6u);
    EXPECT_FLOAT_EQ(f.positions[3] - f.positions[0], c.stepX) << c.pixdim << " qform " << c.qform;
    const bool said = std::any_of(f.warnings.begin(), f.warnings.end(), [&](const std::string& w) {
      return c.said && w.find(c.said) != std::string::npos;
    });
    EXPECT_EQ(said, c.said != nullptr) << c.pixdim << " qform " << c.qform;
    if (!c.said) {
      EXPECT_TRUE(c.sform == 0 || f.warnings.empty()) << f.warnings.front();
      for (const std::string& w : f.warnings) EXPECT_EQ(w.find("pixdim"), std::string::npos) << w;
    }
  }
}

bool saysIt(const io::TensorField& f, const char* what) {
  return std::any_of(f.warnings.begin(), f.warnings.end(),
                     [&](const std::string& w) { return w.find(what) != std::string::npos; });
}

// Fields outside the standard that libnifti2 and nibabel (so DIPY) read
// apart, which drew the glyphs where nibabel does not put them, unsaid:
// a qfac of -2 (libnifti2: its sign flips z; nibabel: 1), a code above 5
// (libnifti2 used the transform; nibabel does not). nibabel's reading is
// taken and said. A quaternion longer than 1 nibabel refuses; it is said.
TEST(Nifti, PlacementFieldsOutsideTheStandardAreReadAsNibabelReadsThem) {
  Placement qfac;
  qfac.sform = 0;
  qfac.qfac = -2;
  io::TensorField f = readPlaced(qfac);
  ASSERT_TRUE(f.grid);
  EXPECT_DOUBLE_EQ(f.grid->directions[8], 1) << "z is not flipped";
  EXPECT_TRUE(saysIt(f, "pixdim[0] (qfac) is -2, not 1 or -1; 1 is used, as nibabel uses it"));
  qfac.qfac = -1;  // the standard's flip: no word
  f = readPlaced(qfac);
  EXPECT_DOUBLE_EQ(f.grid->directions[8], -1);
  EXPECT_TRUE(f.warnings.empty()) << f.warnings.front();

  Placement sform7;  // sform diag(2) at z 30; the qform says z 35
  sform7.sform = 7;
  sform7.offset[2] = 35;
  f = readPlaced(sform7);
  EXPECT_FLOAT_EQ(f.positions[2], 35) << "placed by the sform";
  EXPECT_TRUE(saysIt(f, "sform_code is 7, not a NIfTI code (0..5); it is not used, as nibabel does not use it"));
  EXPECT_FALSE(saysIt(f, "disagree"));

  Placement qform9;
  qform9.sform = 0;
  qform9.qform = 9;
  f = readPlaced(qform9);
  EXPECT_FLOAT_EQ(f.positions[0], 0) << "placed by the qform";
  EXPECT_TRUE(saysIt(f, "qform_code is 9"));
  EXPECT_TRUE(saysIt(f, "no sform or qform; placed by pixdim alone"));

  Placement longQuaternion;
  longQuaternion.sform = 0;
  longQuaternion.quatern[0] = longQuaternion.quatern[1] = 0.9f;
  f = readPlaced(longQuaternion);
  EXPECT_TRUE(saysIt(f, "the qform's quaternion (b, c, d) is longer than 1"));
}

// Six volumes whose header says they are a vector (or any intent but none,
// a parameter estimate or SYMMATRIX) are read as asked, with a warning.
TEST(Nifti, AnIntentOtherThanATensorIsSaid) {
  Fixture fx;
  fx.voxels = {{{1, 0, 0, 1, 0, 1}}, {{2, 0, 0, 2, 0, 2}}};
  const fs::path p = tmpDir() / "intent.nii";
  write(p, fx);
  std::string bytes;
  {
    std::ifstream in(p, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  for (const int intent : {NIFTI_INTENT_NONE, NIFTI_INTENT_ESTIMATE, NIFTI_INTENT_VECTOR, NIFTI_INTENT_GENMATRIX}) {
    const auto code = std::int16_t(intent);
    std::memcpy(&bytes[68], &code, 2);  // intent_code
    test::writeFile(p, bytes);
    const io::TensorField f = io::readTensorField(p.string(), {});
    ASSERT_EQ(f.size(), 2u);
    const bool warned = f.warnings.size() == 1 && f.warnings[0].find("not a symmetric matrix") != std::string::npos;
    EXPECT_EQ(warned, intent == NIFTI_INTENT_VECTOR || intent == NIFTI_INTENT_GENMATRIX) << intent;
  }
}

TEST(Nifti, BadInputGetsOneLineNamingFileAndProblem) {
  Fixture fx;
  fx.nx = 8;
  fx.ny = 8;
  fx.nz = 8;
  fx.voxels.assign(512, {{1, 0, 0, 1, 0, 1}});
  const fs::path good = tmpDir() / "good.nii";
  write(good, fx);
  std::string bytes;
  {
    std::ifstream in(good, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const fs::path d = tmpDir();
  std::ofstream(d / "trunc.nii", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  std::ofstream(d / "garbage.nii", std::ios::binary) << std::string(400, 'x');
  std::string huge = bytes.substr(0, 352);
  const int16_t big = 32767;
  for (int k = 1; k <= 3; ++k) std::memcpy(&huge[40 + 2 * k], &big, 2);  // dim[1..3] of a NIfTI-1 header
  std::ofstream(d / "huge.nii", std::ios::binary) << huge;
  std::string badType = bytes;
  const int16_t seven = 7;  // no such NIfTI datatype; libnifti2 prints its own "** ERROR" line for it
  std::memcpy(&badType[70], &seven, 2);
  std::ofstream(d / "datatype.nii", std::ios::binary) << badType;
  // libnifti2 reads a NaN voxel size as 1: pixdim[2] at byte 76 + 4 * 2 of a NIfTI-1 header.
  std::string nanPixdim = bytes;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&nanPixdim[76 + 4 * 2], &nan, 4);
  std::ofstream(d / "nan-pixdim.nii", std::ios::binary) << nanPixdim;
  struct Case {
    const char* file;
    const char* expect;
  } cases[] = {{"trunc.nii", "truncated"}, {"garbage.nii", "NIfTI"}, {"huge.nii", "readNifti"},
               {"datatype.nii", "NIfTI"}, {"nan-pixdim.nii", "pixdim[2] (a voxel size) is not finite"}};
  for (const Case& c : cases) {
    testing::internal::CaptureStderr();
    const std::string e = errorOf(d / c.file);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << c.file << ": the library must not print";
    EXPECT_NE(e.find(c.expect), std::string::npos) << c.file << ": " << e;
    EXPECT_NE(e.find((d / c.file).string()), std::string::npos) << c.file << ": " << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << c.file << ": " << e;
  }
  // NIfTI-2 dimensions are 64-bit: 2^40 cubed overflows past 2^63.
  Fixture n2 = fx;
  n2.nifti2 = true;
  write(d / "n2.nii", n2);
  std::string n2bytes;
  {
    std::ifstream in(d / "n2.nii", std::ios::binary);
    n2bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const int64_t side = int64_t(1) << 40;
  for (int k = 1; k <= 3; ++k) std::memcpy(&n2bytes[16 + 8 * k], &side, 8);  // dim[1..3] of a NIfTI-2 header
  std::ofstream(d / "n2-overflow.nii", std::ios::binary) << n2bytes;
  const std::string overflow = errorOf(d / "n2-overflow.nii");
  EXPECT_NE(overflow.find("n2-overflow.nii"), std::string::npos) << overflow;
  EXPECT_EQ(overflow.find('\n'), std::string::npos) << overflow;

  io::ReadOptions bad;
  bad.layout = "upside-down";
  EXPECT_NE(errorOf(good, bad).find("unknown layout"), std::string::npos);
}
