// Tier 2: the VTK datasets published by others load with the right counts.
#include <gtest/gtest.h>

#include <filesystem>

#include "io/readers.h"
#include "real_data.h"

using namespace tg;

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
  const auto g = io::readTensorField(test::realData("slicer-fiber-tensors/tractography.vtk"), {"tensor1"});
  EXPECT_EQ(g.totalPoints, 1293u);
  EXPECT_NE(g.tensors[0], f.tensors[0]);
}

TEST(RealData, KittenStressVtu) {
  TG_REQUIRE_REAL_DATA();
  const auto f = io::readTensorField(test::realData("tsv-kitten-stress/kitten-stress.vtu"), {});
  EXPECT_EQ(f.totalPoints, 14961u);
  EXPECT_EQ(f.arrayName, "stress");
}

TEST(RealData, KittenLegacyFileHasNoTensorsAndSaysSo) {
  TG_REQUIRE_REAL_DATA();
  // Its stresses sit in a non-standard trailer that VTK's reader ignores.
  try {
    io::readTensorField(test::realData("tsv-kitten-stress/kitten3D_HexMesh_stressField.vtk"), {});
    FAIL() << "expected an InputError";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("9 or 6 components"), std::string::npos) << e.what();
  }
}
