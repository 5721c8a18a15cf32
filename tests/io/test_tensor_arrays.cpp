// Tier 2: which VTK point array holds the tensors. Several candidates are
// refused by name, never the first taken; 2-D FEM tensors (OpenGeoSys's
// four components, plane codes' three) become 3-D tensors with zero
// out-of-plane shear. Fixtures are .vtu files as OpenGeoSys writes them
// (ascii here, the same structure).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/io_test_util.h"
#include "io/core/readers.h"
#include "real_data.h"

using namespace tg;
namespace fs = std::filesystem;

namespace {

fs::path dir() { return test::scratchDir("tensor_arrays"); }

struct Array {
  std::string name;
  int components;
  std::vector<double> values;  // components per point
};

// Three points of one triangle, at z = `z` (the third one at z + zSpan).
fs::path writeVtu(const std::string& file, const std::vector<Array>& arrays, const std::string& activeTensors = "",
                  double zSpan = 0) {
  const fs::path p = dir() / file;
  std::ofstream o(p);
  o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
       "<UnstructuredGrid><Piece NumberOfPoints=\"3\" NumberOfCells=\"1\">\n<PointData"
    << (activeTensors.empty() ? "" : " Tensors=\"" + activeTensors + "\"") << ">\n";
  for (const Array& a : arrays) {
    o << "<DataArray type=\"Float64\" Name=\"" << a.name << "\" NumberOfComponents=\"" << a.components
      << "\" format=\"ascii\">";
    for (double v : a.values) o << v << " ";
    o << "</DataArray>\n";
  }
  o << "</PointData>\n<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
    << "0 0 0 1 0 0 0 1 " << zSpan << "</DataArray></Points>\n"
    << "<Cells><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2</DataArray>"
       "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">3</DataArray>"
       "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">5</DataArray></Cells>\n"
       "</Piece></UnstructuredGrid></VTKFile>\n";
  return p;
}

// OpenGeoSys's 2-D sigma: xx yy zz xy per point.
const Array kSigma{"sigma", 4, {-1, -2, -0.5, 0.3, -1.5, -2.5, -0.7, 0.1, -3, -1, -0.6, -0.2}};
const Array kEpsilon{"epsilon", 4, {1e-3, 2e-3, 0, 3e-4, 1e-3, 1e-3, 0, 0, 2e-3, 1e-3, 0, -1e-4}};

io::ReadOptions array(const std::string& name) {
  io::ReadOptions o;
  o.arrayName = name;
  return o;
}

}  // namespace

TEST(TensorArrays, OpenGeoSysSigmaIsReadAsAThreeDTensorWithZeroOutOfPlaneShear) {
  const fs::path p = writeVtu("ogs-sigma.vtu", {kSigma, {"displacement", 2, {0, 0, 1, 1, 2, 2}}});
  const io::TensorField f = io::readTensorField(p.string(), {});
  ASSERT_EQ(f.size(), 3u);
  EXPECT_EQ(f.arrayName, "sigma");
  EXPECT_NE(f.layout.find("XX YY ZZ XY"), std::string::npos) << f.layout;
  EXPECT_TRUE(f.warnings.empty());  // the points lie in one z plane
  for (std::size_t i = 0; i < 3; ++i) {
    const double* s = &kSigma.values[4 * i];
    const float expect[6] = {float(s[0]), float(s[3]), 0, float(s[1]), 0, float(s[2])};  // xx xy xz yy yz zz
    for (int k = 0; k < 6; ++k) EXPECT_FLOAT_EQ(f.tensors[6 * i + std::size_t(k)], expect[k]) << i << " " << k;
  }
}

TEST(TensorArrays, ThreeComponentsAreTensorsOnlyWhenArrayNamesThem) {
  const Array plane{"stress2d", 3, {1, 2, 0.5, 3, 4, -1, 5, 6, 0}};
  const fs::path p = writeVtu("plane.vtu", {plane});
  const std::string e = test::readError(p);
  EXPECT_NE(e.find("no point array with 9 or 6 components"), std::string::npos) << e;
  EXPECT_NE(e.find("stress2d (3 components)"), std::string::npos) << e;
  EXPECT_NE(e.find("--array"), std::string::npos) << e;
  const io::TensorField f = io::readTensorField(p.string(), array("stress2d"));
  ASSERT_EQ(f.size(), 3u);
  const float expect[6] = {1, 0.5f, 0, 2, 0, 0};  // xx xy xz yy yz zz: zz = 0
  for (int k = 0; k < 6; ++k) EXPECT_FLOAT_EQ(f.tensors[std::size_t(k)], expect[k]) << k;
  // A 4-component array under another name is a colour as often: only by --array.
  const fs::path rgba = writeVtu("rgba.vtu", {{"colour", 4, std::vector<double>(12, 0.5)}});
  EXPECT_NE(test::readError(rgba).find("colour (4 components)"), std::string::npos);
  EXPECT_EQ(io::readTensorField(rgba.string(), array("colour")).size(), 3u);
}

TEST(TensorArrays, TwoDTensorsOnPointsOffThePlaneWarn) {
  const fs::path p = writeVtu("ogs-3d.vtu", {kSigma}, "", 0.5);
  const io::TensorField f = io::readTensorField(p.string(), {});
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_NE(f.warnings[0].find("x-y plane"), std::string::npos) << f.warnings[0];
}

TEST(TensorArrays, SeveralCandidatesAreRefusedByName) {
  // OpenGeoSys writes epsilon before sigma; neither is taken silently.
  const fs::path p = writeVtu("ogs-both.vtu", {kEpsilon, kSigma});
  const std::string e = test::readError(p);
  EXPECT_NE(e.find("2 point arrays could hold the tensors"), std::string::npos) << e;
  EXPECT_NE(e.find("epsilon (4 components), sigma (4 components)"), std::string::npos) << e;
  EXPECT_NE(e.find(p.string()), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  EXPECT_EQ(io::readTensorField(p.string(), array("sigma")).arrayName, "sigma");
  EXPECT_EQ(io::readTensorField(p.string(), array("epsilon")).arrayName, "epsilon");
  // Two 3-D arrays, as well.
  const fs::path six = writeVtu("two-six.vtu", {{"a", 6, std::vector<double>(18, 1)}, {"b", 9, std::vector<double>(27, 1)}});
  EXPECT_NE(test::readError(six).find("a (6 components), b (9 components)"), std::string::npos);
  // The active tensors attribute is not ambiguous.
  const fs::path active =
      writeVtu("active.vtu", {{"a", 6, std::vector<double>(18, 1)}, {"b", 6, std::vector<double>(18, 2)}}, "b");
  EXPECT_EQ(io::readTensorField(active.string(), {}).arrayName, "b");
  // A missing --array names what there is.
  EXPECT_NE(test::readError(p, array("stress")).find("found epsilon (4 components), sigma (4 components)"),
            std::string::npos);
}

TEST(TensorArrays, PublishedVtkFilesKeepTheirTensors) {
  TG_REQUIRE_REAL_DATA();
  // Two tensors, one the active TENSORS attribute: that one, as before.
  EXPECT_EQ(io::readTensorField(test::realData("slicer-fiber-tensors/tractography.vtk"), {}).arrayName, "tensor2");
  EXPECT_EQ(io::readTensorField(test::realData("slicer-fiber-tensors/fiber_vtk.vtk"), {}).totalPoints, 1079u);
  EXPECT_EQ(io::readTensorField(test::realData("tsv-kitten-stress/kitten-stress.vtu"), {}).arrayName, "stress");
  EXPECT_EQ(io::readTensorField(test::realData("tsv-kitten-stress/kitten3D_HexMesh_stressField.vtk"), {}).size(),
            14961u);
}
