// Tier 2: the VTK datasets published by others load with the right counts.
#include <gtest/gtest.h>

#include <filesystem>

#include "io/core/readers.h"
#include "tensor/glyph.h"
#include "real_data.h"

using namespace tg;

namespace {
io::ReadOptions array(const char* name) {
  io::ReadOptions o;
  o.arrayName = name;
  return o;
}
}  // namespace

TEST(RealData, SlicerFibreTensors) {
  TG_REQUIRE_REAL_DATA();
  const auto f = io::readTensorField(test::realData("slicer-fiber-tensors/fiber_vtk.vtk"), {});
  EXPECT_EQ(f.totalPoints, 1079u);
  EXPECT_EQ(f.size() + f.skippedNonFinite, 1079u);
  EXPECT_GT(f.sampleSpacing, 0.0);
}

TEST(RealData, SlicerTwoTensorTractographyBigEndian) {
  TG_REQUIRE_REAL_DATA();
  const auto f = io::readTensorField(test::realData("slicer-fiber-tensors/tractography.vtk"), {});
  EXPECT_EQ(f.totalPoints, 1293u);
  EXPECT_EQ(f.arrayName, "tensor2");
  const auto g = io::readTensorField(test::realData("slicer-fiber-tensors/tractography.vtk"), array("tensor1"));
  EXPECT_EQ(g.totalPoints, 1293u);
  EXPECT_NE(g.tensors[0], f.tensors[0]);
}

TEST(RealData, KittenStressVtu) {
  TG_REQUIRE_REAL_DATA();
  const auto f = io::readTensorField(test::realData("tsv-kitten-stress/kitten-stress.vtu"), {});
  EXPECT_EQ(f.totalPoints, 14961u);
  EXPECT_EQ(f.arrayName, "stress");
}

TEST(RealData, KittenLegacyTrailerMatchesTheRepackedVtu) {
  TG_REQUIRE_REAL_DATA();
  // The original keeps its stresses in 3D-TSV's trailer; the .vtu beside it
  // holds the same stresses as a standard array. Both must give one field.
  const auto legacy = io::readTensorField(test::realData("tsv-kitten-stress/kitten3D_HexMesh_stressField.vtk"), {});
  const auto vtu = io::readTensorField(test::realData("tsv-kitten-stress/kitten-stress.vtu"), {});
  ASSERT_EQ(legacy.size(), 14961u);
  ASSERT_EQ(vtu.size(), legacy.size());
  EXPECT_NE(legacy.arrayName.find("3D-TSV"), std::string::npos);
  for (std::size_t i = 0; i < legacy.size(); ++i) {
    for (int k = 0; k < 3; ++k) ASSERT_FLOAT_EQ(legacy.positions[3 * i + k], vtu.positions[3 * i + k]);
    for (int k = 0; k < 6; ++k) ASSERT_NEAR(legacy.tensors[6 * i + k], vtu.tensors[6 * i + k], 1e-6) << i << " " << k;
  }
}

TEST(RealData, SlicerHelixStoredTwiceGivesTheSameGlyphs) {
  TG_REQUIRE_REAL_DATA();
  // The masked copy stores tensors in a rotated measurement frame, the
  // 3D-matrix copy in the world frame. Wherever the first is confident, the
  // two must hold the same world tensor at the same place.
  const auto masked = io::readTensorField(test::realData("slicer-helix-dti-masked/helix-DTI.nhdr"), {});
  const auto matrix = io::readTensorField(test::realData("slicer-helix-dti-3dmatrix/helix-DTI.nhdr"), {});
  ASSERT_TRUE(masked.measurementFrame);
  ASSERT_EQ(matrix.size(), 64u * 32u * 16u);
  ASSERT_GT(masked.size(), 500u);
  double worst = 0, worstUnrotated = 0;
  for (std::size_t i = 0; i < masked.size(); ++i) {
    const std::uint32_t id = masked.ids[i];
    for (int k = 0; k < 3; ++k) ASSERT_FLOAT_EQ(masked.positions[3 * i + k], matrix.positions[3 * id + k]);
    const float* a = &masked.tensors[6 * i];
    const float* b = &matrix.tensors[6 * std::size_t(id)];
    double diff = 0, norm = 0;
    for (int k = 0; k < 6; ++k) {
      diff = std::max(diff, double(std::abs(a[k] - b[k])));
      norm = std::max(norm, double(std::abs(b[k])));
    }
    worst = std::max(worst, diff / norm);
    // What a reader that ignored the frame would have compared: the stored
    // (unrotated) tensor, M^T D M, against the world one.
    const auto& m = *masked.measurementFrame;
    const double d[3][3] = {{a[0], a[1], a[2]}, {a[1], a[3], a[4]}, {a[2], a[4], a[5]}};
    double s01 = 0;
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) s01 += m[3 * p + 0] * d[p][q] * m[3 * q + 1];
    worstUnrotated = std::max(worstUnrotated, std::abs(s01 - b[1]) / norm);
  }
  EXPECT_LT(worst, 1e-5) << "largest relative difference of a component";
  EXPECT_GT(worstUnrotated, 0.1) << "the frame must matter for this test to mean anything";
}

TEST(RealData, FaAgreesWithSlicersReferenceMap) {
  TG_REQUIRE_REAL_DATA();
  io::ReadOptions all;
  all.selection.confidenceMin = -1;  // every voxel, as the reference map has
  const auto f = io::readTensorField(test::realData("slicer-helix-dti-masked/helix-DTI.nhdr"), all);
  const int dims[3] = {64, 32, 16};
  const io::ScalarVolume ref =
      io::readNrrdScalar(test::realData("slicer-helix-dti-masked/helix-DTI-FractionalAnisotropy.nhdr"), dims);
  ASSERT_EQ(ref.dims[0] * ref.dims[1] * ref.dims[2], 64 * 32 * 16);
  ASSERT_EQ(f.size(), ref.values.size());
  const tensor::GlyphSet g = tensor::buildGlyphs(f.positions, f.tensors, f.ids);
  double worst = 0;
  std::size_t anisotropic = 0;
  for (const auto& r : g.glyphs) {
    worst = std::max(worst, std::abs(double(r.fa) - ref.values[r.id]));
    anisotropic += ref.values[r.id] > 0.3f;
  }
  EXPECT_GT(anisotropic, 400u);
  EXPECT_LT(worst, 1e-5);
}

TEST(RealData, KindlmannHelixOldHeaderBigEndian) {
  TG_REQUIRE_REAL_DATA();
  const auto f = io::readTensorField(test::realData("kindlmann-dt-helix/dt-helix.nhdr"), {});
  EXPECT_EQ(f.totalPoints, 38u * 39u * 40u);
  EXPECT_EQ(f.size() + f.masked, f.totalPoints);
  // axis mins/maxs -2..2 with cell centring: the first sample sits half a cell in.
  EXPECT_NEAR(f.positions[0], -2.0 + 0.5 * 4.0 / 38.0, 1e-6);
  EXPECT_NEAR(f.positions[2], -2.0 + 0.5 * 4.0 / 40.0, 1e-6);
  const tensor::GlyphSet g = tensor::buildGlyphs(f.positions, f.tensors, f.ids);
  float faMax = 0;
  for (const auto& r : g.glyphs) {
    ASSERT_GT(r.eigenvalues[2], 0.0f);  // a diffusion phantom: all positive definite
    faMax = std::max(faMax, r.fa);
  }
  EXPECT_GT(faMax, 0.5f);
}
