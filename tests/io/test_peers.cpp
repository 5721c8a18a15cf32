// Tier 2: tensor files written by the tools themselves, read back as the
// world tensors they were fitted from. peers/peer_tensors.py simulates one
// DWI from known world tensors and has MRtrix (dwi2tensor) and DIPY
// (ReconstDtiFlow, as dipy_fit_dti runs it, and a script's
// lower_triangular() save) fit and save them; FSL's b-vector convention
// comes from MRtrix's FSL export. Needs python3-dipy, python3-nibabel and
// mrtrix3 (.ci/build installs them).
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/io_test_util.h"
#include "io/core/readers.h"

using namespace tg;
namespace fs = std::filesystem;

namespace {

constexpr int kNx = 3, kNy = 3, kNz = 2;

struct Peers {
  fs::path dir;
  std::vector<std::array<double, 6>> world;  // by voxel index, i fastest
};

// Runs the script for one handedness of the affine (about 2 s: DIPY's import).
Peers peers(const std::string& det) {
  Peers p;
  p.dir = test::scratchDir("peers") / det;
  const std::string cmd = std::string(TG_PYTHON3) + " " + TG_PEER_SCRIPT + " " + p.dir.string() + " " + det + " 2>" +
                          (p.dir.parent_path() / ("py-" + det + ".txt")).string();
  const int status = std::system(cmd.c_str());
  std::ifstream err(p.dir.parent_path() / ("py-" + det + ".txt"));
  const std::string why((std::istreambuf_iterator<char>(err)), {});
  EXPECT_EQ(status, 0) << cmd << "\n" << why << "\n(needs python3-dipy, python3-nibabel and mrtrix3)";
  std::ifstream truth(p.dir / "truth.txt");
  p.world.resize(kNx * kNy * kNz);
  int i, j, k, n = 0;
  while (truth >> i >> j >> k) {
    auto& d = p.world[std::size_t(i + kNx * (j + kNy * k))];
    for (double& x : d) truth >> x;
    ++n;
  }
  EXPECT_EQ(n, kNx * kNy * kNz);
  return p;
}

// The largest difference from the world tensors, over every voxel.
double worstError(const io::TensorField& f, const Peers& p) {
  EXPECT_EQ(f.size(), p.world.size()) << f.path;
  double worst = 0;
  for (std::size_t v = 0; v < f.size(); ++v)
    for (std::size_t c = 0; c < 6; ++c)
      worst = std::max(worst, std::abs(double(f.tensors[6 * v + c]) - p.world[f.ids[v]][c]));
  return worst;
}

io::ReadOptions with(const std::string& layout, const std::string& frame) {
  io::ReadOptions o;
  o.layout = layout;
  o.frame = frame;
  return o;
}

// Eigenvalues are 0.2e-3 to 1.7e-3; a wrong order or frame errs by 1e-4 and
// more, float rounding of a noise-free fit by 1e-8.
constexpr double kTolerance = 1e-6;

}  // namespace

class PeerFiles : public testing::TestWithParam<const char*> {};

// One test per handedness, so that the script runs once for each.
TEST_P(PeerFiles, ReadAsTheWorldTensorsTheyWereFittedFrom) {
  const Peers p = peers(GetParam());
  const bool detPositive = std::string(GetParam()) == "pos";
  // MRtrix: its descrip chooses its order and the scanner frame.
  const io::TensorField mrtrix = io::readTensorField((p.dir / "mrtrix.nii").string(), {});
  EXPECT_NE(mrtrix.layout.find("MRtrix"), std::string::npos) << mrtrix.layout;
  EXPECT_LT(worstError(mrtrix, p), kTolerance) << "MRtrix dwi2tensor";
  EXPECT_TRUE(mrtrix.warnings.empty());
  // DIPY's workflow, default: 5-D SYMMATRIX, voxel axes.
  const io::TensorField voxel = io::readTensorField((p.dir / "dipy-voxel.nii.gz").string(), {});
  EXPECT_NE(voxel.layout.find("SYMMATRIX"), std::string::npos) << voxel.layout;
  EXPECT_LT(worstError(voxel, p), kTolerance) << "DIPY, voxel b-vectors";
  // DIPY's workflow with FSL's b-vectors and --nifti_tensor False: what FSL's
  // dtifit writes, FSL's order in FSL's frame.
  const std::string fslFile = (p.dir / "dipy-fsl.nii.gz").string();
  EXPECT_LT(worstError(io::readTensorField(fslFile, {}), p), kTolerance) << "DIPY, FSL b-vectors";
  // FSL's mirror is there exactly when the affine keeps handedness.
  const double asVoxel = worstError(io::readTensorField(fslFile, with("", "voxel")), p);
  if (detPositive) {
    EXPECT_GT(asVoxel, 1e-5) << "det > 0: FSL's frame is not the voxel frame";
  } else {
    EXPECT_LT(asVoxel, kTolerance) << "det < 0: FSL's frame is the voxel frame";
  }
  // A script's lower_triangular() saved as a plain 4-D image: FSL's order,
  // the default, reads it as indefinite; refused, naming the one that fits.
  const std::string script = (p.dir / "dipy-script.nii").string();
  const std::string guessed = test::readError(script);
  EXPECT_NE(guessed.find("only --layout nifti --frame voxel reads them plausibly"), std::string::npos) << guessed;
  const io::TensorField named = io::readTensorField(script, with("nifti", ""));
  EXPECT_TRUE(named.warnings.empty());
  EXPECT_LT(worstError(named, p), kTolerance);
}

INSTANTIATE_TEST_SUITE_P(BothHandednesses, PeerFiles, testing::Values("pos", "neg"));
