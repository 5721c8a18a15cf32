// The frame check (app/frame_check.h) through the CLI: on the real helices
// (Kindlmann's, Slicer's two) it is silent as read and names the reading
// that undoes each flip and permutation; on a NIfTI volume whose tensors are
// in the voxel frame it names --frame voxel when FSL's frame mirrors them
// (det > 0), and is silent where the two agree (det < 0). On DWIs fitted by
// DIPY at test time (tests/peers/frame_fits.py): its bundled 10x10x10 and
// 6x10x10 DWIs are too small a field to tell, correct or mirrored, and say
// so; a simulated DWI of three known bundles is silent as fitted and each
// b-table mirror is undone by name. Isotropic random fibre fields
// (tests/peers/frame_null_fields.py), which no reading fits better than
// another, never warn.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <utility>
#include <string>

#include "cli/cli_run.h"
#include "data-synthetic/generators.h"
#include "io/nifti_fixture.h"
#include "real_data.h"

namespace fs = std::filesystem;

namespace {

using tg::test::CmdResult;

fs::path dir() { return tg::test::cliDir("frame_check"); }
CmdResult run(const std::string& args) { return tg::test::runBinary(args, dir()); }

long warnings(const std::string& err) {
  long n = 0;
  for (std::size_t at = 0; (at = err.find("look mirrored", at)) != std::string::npos; ++at) ++n;
  return n;
}

// Runs Debian's python3 on a script of tests/peers; false when it fails.
bool python(const std::string& script, const std::string& args) {
  const std::string cmd = std::string(TG_PYTHON3) + " " + TG_PEERS_DIR + "/" + script + " " + args + " > " +
                          (dir() / (script + ".log")).string() + " 2>&1";
  return std::system(cmd.c_str()) == 0;
}

const char* const kMirrors[] = {"-x,y,z", "x,-y,z", "x,y,-z", "y,x,z", "z,y,x", "x,z,y", "y,z,x"};

TEST(FrameCheck, RealHelicesAreSilentAsReadAndEachMirrorIsUndone) {
  for (const char* rel : {"kindlmann-dt-helix/dt-helix.nhdr", "slicer-helix-dti-masked/helix-DTI.nhdr",
                          "slicer-helix-dti-3dmatrix/helix-DTI.nhdr"}) {
    const std::string f = tg::test::realData(rel);
    const CmdResult asRead = run("info -q " + f);
    ASSERT_EQ(asRead.code, 0) << asRead.err;
    EXPECT_EQ(warnings(asRead.err), 0) << rel << "\n" << asRead.err;
    EXPECT_NE(asRead.out.find("frame check: fibre coherence over"), std::string::npos) << asRead.out;
    EXPECT_NE(asRead.out.find("verdict: no alternative reads the fibres clearly better"), std::string::npos)
        << asRead.out;
    // Every other reading scores below the file's own: said so, not as a negative "above".
    EXPECT_NE(asRead.out.find("standard errors below as read"), std::string::npos) << asRead.out;
    EXPECT_EQ(asRead.out.find("best other: -"), std::string::npos) << asRead.out;
    for (const char* m : kMirrors) {
      const CmdResult r = run("info -q " + f + " --tensor-axes " + m);
      ASSERT_EQ(r.code, 0) << r.err;
      EXPECT_EQ(warnings(r.err), 1) << rel << " " << m << "\n" << r.err;
      // The reading that undoes it: the file's own axes.
      EXPECT_NE(r.err.find("give --tensor-axes x,y,z"), std::string::npos) << rel << " " << m << "\n" << r.err;
      EXPECT_NE(r.out.find("verdict: --tensor-axes x,y,z reads the fibres clearly better"), std::string::npos)
          << r.out;
    }
  }
}

// The synthetic helix's tensors in its voxel axes, written under a 2 mm
// affine rotated 30 degrees about z; `negativeDet` reverses i.
fs::path voxelFrameNifti(const std::string& name, bool negativeDet) {
  const tg::synth::Helix h = tg::synth::helixPhantom(40, 40, 40);
  const tg::io::TensorField& f = h.field;
  const tg::io::GridInfo& g = *f.grid;
  tg::test::NiftiTensors fx;
  std::copy(g.dims, g.dims + 3, fx.dims);
  const double c = 2 * std::cos(0.5235987755982988), s = 2 * std::sin(0.5235987755982988), sx = negativeDet ? -1 : 1;
  const double a[3][4] = {{sx * c, -s, 0, -40}, {sx * s, c, 0, -30}, {0, 0, 2, 10}};
  std::copy(&a[0][0], &a[0][0] + 12, &fx.affine[0][0]);
  fx.voxels.assign(std::size_t(g.dims[0]) * g.dims[1] * g.dims[2], {0, 0, 0, 0, 0, 0});
  const double* q = g.directions;  // column k: axis k
  for (std::size_t v = 0; v < f.size(); ++v) {
    const float* t = &f.tensors[6 * v];
    const double d[3][3] = {{t[0], t[1], t[2]}, {t[1], t[3], t[4]}, {t[2], t[4], t[5]}};
    double w[3][3] = {};  // Qᵀ D Q
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) w[r][k] += q[3 * i + r] * d[i][j] * q[3 * j + k];
    fx.voxels[f.ids[v]] = {float(w[0][0]), float(w[0][1]), float(w[0][2]), float(w[1][1]), float(w[1][2]),
                           float(w[2][2])};
  }
  const fs::path p = dir() / name;
  tg::test::writeNifti(p, fx);
  return p;
}

TEST(FrameCheck, FslFrameOverVoxelFrameTensorsIsNamedAndTheVoxelFrameIsNot) {
  const std::string pos = voxelFrameNifti("voxel-pos.nii", false).string();
  CmdResult r = run("info -q " + pos + " --frame voxel");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(warnings(r.err), 0) << r.err;
  // FSL's frame, the fsl layout's default, mirrors i under det > 0.
  r = run("info -q " + pos);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(warnings(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("give --frame voxel"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("frame voxel "), std::string::npos) << r.out;
  // Where det < 0 the two frames agree: nothing to name, and no other frame listed but world.
  const std::string neg = voxelFrameNifti("voxel-neg.nii", true).string();
  r = run("info -q " + neg);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(warnings(r.err), 0) << r.err;
  EXPECT_EQ(r.out.find("frame voxel "), std::string::npos) << r.out;
  // render says it too, once.
  r = run("render -q " + pos + " -o " + (dir() / "mirrored.png").string() + " --size 64 64");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(warnings(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("tensorglyph render: " + pos + ": the tensors look mirrored"), std::string::npos) << r.err;
}

TEST(FrameCheck, DipyFitsOfBundledAndSimulatedDwisAsFittedAndMirrored) {
  const fs::path out = dir() / "dipy";
  ASSERT_TRUE(python("frame_fits.py", out.string())) << (dir() / "frame_fits.py.log");
  // Each b-table error, and the reading that undoes it.
  const std::pair<const char*, const char*> variants[] = {{"", nullptr},
                                                          {"-flip-x", "--tensor-axes -x,y,z"},
                                                          {"-flip-y", "--tensor-axes x,-y,z"},
                                                          {"-flip-z", "--tensor-axes x,y,-z"},
                                                          {"-swap-xy", "--tensor-axes y,x,z"}};
  for (const char* name : {"small_64D", "small_101D", "sim"}) {
    const bool small = std::string(name) != "sim";
    for (const auto& [suffix, undo] : variants) {
      const std::string f = (out / (std::string(name) + suffix + ".nii")).string();
      const CmdResult r = run("info -q " + f + " --frame voxel");
      ASSERT_EQ(r.code, 0) << r.err;
      if (small) {
        EXPECT_EQ(warnings(r.err), 0) << f << "\n" << r.err;
        EXPECT_NE(r.out.find("verdict: too small a field to tell"), std::string::npos) << f << "\n" << r.out;
      } else if (!undo) {
        EXPECT_EQ(warnings(r.err), 0) << f << "\n" << r.err;
        EXPECT_NE(r.out.find("verdict: no alternative reads the fibres clearly better"), std::string::npos) << r.out;
      } else {
        EXPECT_EQ(warnings(r.err), 1) << f << "\n" << r.err;
        EXPECT_NE(r.err.find(std::string("give ") + undo + " "), std::string::npos) << f << "\n" << r.err;
      }
    }
  }
}

TEST(FrameCheck, IsotropicRandomFibreFieldsNeverWarn) {
  // Smoothing over 1.5 to 4 voxels, the smoother the fewer independent
  // bundles (docs/conventions.md, "Frame check": 840 such fields, none fired).
  int fields = 0;
  for (const char* sigma : {"1.5", "4"}) {
    const fs::path out = dir() / (std::string("null-") + sigma);
    ASSERT_TRUE(python("frame_null_fields.py", out.string() + " 12 10x15x20 " + sigma + " 5"))
        << (dir() / "frame_null_fields.py.log");
    for (const auto& e : fs::directory_iterator(out)) {
      const CmdResult r = run("info -q " + e.path().string() + " --frame voxel");
      ASSERT_EQ(r.code, 0) << r.err;
      EXPECT_EQ(warnings(r.err), 0) << e.path() << "\n" << r.err << r.out;
      EXPECT_NE(r.out.find("in 24 blocks of 5^3"), std::string::npos) << r.out;  // big enough to tell
      ++fields;
    }
  }
  EXPECT_EQ(fields, 24);
}

TEST(FrameCheck, ASelectionSkipsItAndBadAxesAreRefused) {
  const std::string f = tg::test::realData("kindlmann-dt-helix/dt-helix.nhdr");
  CmdResult r = run("info -q " + f + " --tensor-axes -x,y,z --slice k:20");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(warnings(r.err), 0) << r.err;
  EXPECT_NE(r.out.find("frame check: not run: --slice, --stride or --roi left voxels out"), std::string::npos) << r.out;
  r = run("info -q " + f + " --tensor-axes x,x,z");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--tensor-axes: \"x,x,z\" is not a signed permutation of x, y, z"), std::string::npos) << r.err;
  for (const char* bad : {"-", "x,y", "x,y,z,w", "X,Y,Z", "x, y, z", "\xc3\xa9,y,z"}) {
    r = run("info -q " + f + " --tensor-axes '" + bad + "'");
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_NE(r.err.find("is not a signed permutation of x, y, z"), std::string::npos) << r.err;
  }
  r = run("info -q " + f + " --tensor-axes ''");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--tensor-axes: an empty value"), std::string::npos) << r.err;
  r = run("render -q --tensor-axes -x,y,z -o " + (dir() / "builtin.png").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--tensor-axes does not apply to the built-in scene"), std::string::npos) << r.err;
}

}  // namespace
