// Tier 2: tensor frames and options through the real binary. `info` states
// the frame it applied; an option the input's format has no use for is a
// command-line error (exit 2); nothing left to draw is an input error (exit
// 1) for every command, with no output written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "cli/cli_run.h"
#include "io/nifti_fixture.h"

namespace fs = std::filesystem;

namespace {

using tg::test::CmdResult;

fs::path dir() { return tg::test::cliDir("cli_frames"); }

CmdResult run(const std::string& args) { return tg::test::runBinary(args, dir()); }

long lines(const std::string& s) { return std::count(s.begin(), s.end(), '\n'); }

// One diffusion tensor per voxel of a 2x2x2 grid, 40 degrees about z, 2 mm
// voxels, det > 0, in FSL's order.
fs::path niftiFile(const std::string& name, bool negativeDet = false) {
  tg::test::NiftiTensors fx;
  fx.dims[0] = fx.dims[1] = fx.dims[2] = 2;
  const double c = 2 * std::cos(0.7), s = 2 * std::sin(0.7), sx = negativeDet ? -1 : 1;
  const double a[3][4] = {{sx * c, -s, 0, 5}, {sx * s, c, 0, 6}, {0, 0, 2, 7}};
  std::copy(&a[0][0], &a[0][0] + 12, &fx.affine[0][0]);
  fx.voxels.assign(8, {1.7e-3f, 0.1e-3f, 0, 0.3e-3f, 0, 0.3e-3f});
  const fs::path p = dir() / name;
  tg::test::writeNifti(p, fx);
  return p;
}

// A synthetic NRRD helix (a measurement frame, no confidence) and its VTK twin.
fs::path synth(const std::string& name) {
  const fs::path p = dir() / name;
  if (!fs::exists(p)) {
    EXPECT_EQ(run("synth helix --n 8 -o " + p.string()).code, 0);
  }
  return p;
}

void expectUsageError(const std::string& args, const std::string& what, const fs::path& out) {
  fs::remove(out);
  const CmdResult r = run(args);
  EXPECT_EQ(r.code, 2) << args << " -> " << r.err;
  EXPECT_NE(r.err.find(what), std::string::npos) << args << " -> " << r.err;
  EXPECT_EQ(lines(r.err), 1) << args << " -> " << r.err;
  EXPECT_FALSE(fs::exists(out)) << args;
}

}  // namespace

TEST(CliFrames, OptionsThatDoNotApplyToTheInputsFormatAreUsageErrors) {
  const std::string nii = niftiFile("opts.nii").string(), nrrd = synth("helix.nrrd").string(),
                    vtk = synth("helix.vtk").string();
  const fs::path out = dir() / "never.png";
  const std::string o = " -o " + out.string() + " --size 32 32";
  const std::pair<std::string, std::string> cases[] = {
      {"render " + nrrd + o + " --layout fsl", "--layout does not apply to " + nrrd + ", a NRRD file"},
      {"render " + nrrd + o + " --array tensors", "--array does not apply"},
      {"render " + vtk + o + " --frame world", "--frame does not apply to " + vtk + ", a VTK file"},
      {"render " + nii + o + " --array sigma", "--array does not apply to " + nii + ", a NIfTI file"},
      {"render " + nii + o + " --confidence-min 0.2", "--confidence-min does not apply"},
      // Known only from the header: the helix has no confidence value.
      {"render " + nrrd + o + " --confidence-min 0.2", "its tensors have no confidence value"},
      {"render" + o + " --layout fsl", "--layout does not apply to the built-in scene"},
      {"render " + nii + o + " --frame sideways", "--frame: unknown frame \"sideways\"; choose voxel, fsl or world"},
      {"bench accuracy " + nrrd + " -o " + (dir() / "never.csv").string() + " --frame fsl", "--frame does not apply"},
  };
  for (const auto& [args, what] : cases) expectUsageError(args, what, out);
  EXPECT_FALSE(fs::exists(dir() / "never.csv"));
  // The options that do apply are taken.
  EXPECT_EQ(run("render " + nii + o + " --layout nifti --frame world").code, 0);
  EXPECT_EQ(run("render " + vtk + o + " --array tensors").code, 0);
}

TEST(CliFrames, NothingLeftToDrawFailsEveryCommandWithoutOutput) {
  const std::string nrrd = synth("helix.nrrd").string();
  // Every tensor with a NaN component.
  const fs::path nan = dir() / "all-nan.nrrd";
  std::ofstream(nan) << "NRRD0004\ntype: float\ndimension: 4\nsizes: 6 2 1 1\nkinds: 3D-symmetric-matrix space "
                        "space space\nencoding: ascii\n\nnan 0 0 1 0 1\n1 0 0 nan 0 1\n";
  const std::string away = " --roi 1e6 1e6 1e6 2e6 2e6 2e6";
  const fs::path png = dir() / "empty.png", csv = dir() / "empty.csv";
  struct Case {
    std::string args, file, counts;
    fs::path out;
  } cases[] = {
      {"render " + nrrd + away + " -o " + png.string(), nrrd, "outside the selection", png},
      {"render " + nan.string() + " -o " + png.string(), nan.string(), "2 skipped (NaN/Inf)", png},
      {"info " + nrrd + away, nrrd, "outside the selection", ""},
      {"bench accuracy " + nrrd + away + " -o " + csv.string(), nrrd, "outside the selection", csv},
      // The viewer fails before it opens a window, so no display is needed.
      {"view " + nrrd + away, nrrd, "outside the selection", ""},
      {"render --stride 5" + away + " -o " + png.string(), "(built-in helix phantom)", "outside the selection", png},
  };
  for (const Case& c : cases) {
    if (!c.out.empty()) fs::remove(c.out);
    const CmdResult r = run(c.args);
    EXPECT_EQ(r.code, 1) << c.args << " -> " << r.err;
    EXPECT_NE(r.err.find(c.file + ": no tensor to draw"), std::string::npos) << c.args << " -> " << r.err;
    EXPECT_NE(r.err.find(c.counts), std::string::npos) << c.args << " -> " << r.err;
    EXPECT_EQ(lines(r.err), 1) << c.args << " -> " << r.err;
    EXPECT_EQ(r.out, "") << c.args;
    if (!c.out.empty()) {
      EXPECT_FALSE(fs::exists(c.out)) << c.args;
    }
  }
  EXPECT_FALSE(fs::exists(dir() / "empty.png"));  // bench accuracy's plot beside the CSV
}

TEST(CliFrames, InfoPrintsTheFrameItApplied) {
  // NIfTI, det > 0: FSL's frame mirrors i, so T is a reflection.
  const std::string nii = niftiFile("info.nii").string();
  CmdResult r = run("info " + nii);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("components: fsl: xx xy xz yy yz zz (the default, FSL's; override with --layout)"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("tensor frame: fsl (the fsl layout's; override with --frame): FSL's voxel axes, i reversed as "
                       "the affine's det > 0, rotated by the affine's orthogonal part"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(a reflection)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("world frame"), std::string::npos) << r.out;
  // The rotation printed is the affine's: 40 degrees about z (cos 0.7 = 0.764842).
  EXPECT_NE(r.out.find("[-0.764842 -0.644218 0]"), std::string::npos) << r.out;
  r = run("info " + nii + " --frame voxel");
  EXPECT_NE(r.out.find("tensor frame: voxel (--frame): the voxel axes, rotated"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("[0.764842 -0.644218 0]"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("(a reflection)"), std::string::npos) << r.out;
  r = run("info " + nii + " --layout mrtrix");
  EXPECT_NE(r.out.find("tensor frame: world (the mrtrix layout's; override with --frame)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("tensors to world: identity"), std::string::npos) << r.out;
  // det < 0: FSL's frame is the voxel frame; the reflection is the affine's own.
  r = run("info " + niftiFile("info-neg.nii", true).string());
  EXPECT_NE(r.out.find("the voxel axes as the affine's det < 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(a reflection)"), std::string::npos) << r.out;
  // NRRD: the measurement frame; VTK: world axes as stored.
  r = run("info " + synth("helix.nrrd").string());
  EXPECT_NE(r.out.find("tensor frame: the measurement frame"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("measurement frame (columns)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("tensors to world, D = T D Tᵀ"), std::string::npos) << r.out;
  r = run("info " + synth("helix.vtk").string());
  EXPECT_NE(r.out.find("tensor frame: world: the points' axes, not rotated"), std::string::npos) << r.out;
}

TEST(CliFrames, AFourDimensionalDipyFileIsRefusedNamingTheLayout) {
  // DIPY's tenfit.lower_triangular() saved as a plain 4-D image: without the
  // intent, the default FSL order makes most of these tensors indefinite.
  tg::test::NiftiTensors fx;
  fx.dims[0] = fx.dims[1] = fx.dims[2] = 4;
  std::mt19937 rng(3);
  std::normal_distribution<float> n(0, 0.4e-3f);
  for (int v = 0; v < 64; ++v) {
    // A random rank-one direction plus isotropy: D = 0.3e-3 I + g gᵀ.
    const float g[3] = {n(rng), n(rng), n(rng)};
    const float iso = 0.3e-3f;
    const float scale = 1.0f / 0.4e-3f;
    fx.voxels.push_back({iso + g[0] * g[0] * scale, g[0] * g[1] * scale, iso + g[1] * g[1] * scale,
                         g[0] * g[2] * scale, g[1] * g[2] * scale, iso + g[2] * g[2] * scale});
  }
  const fs::path p = dir() / "dipy-4d.nii";
  tg::test::writeNifti(p, fx);
  const fs::path out = dir() / "dipy.png";
  // Refused (exit 1, one line, no picture): "nifti" is the one order that
  // reads them as diffusion tensors.
  CmdResult r = run("render " + p.string() + " -o " + out.string() + " --size 32 32");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(p.string() + ": "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("indefinite"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("only --layout nifti --frame voxel reads them plausibly"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  // Named, FSL's order is drawn, with the advice as a warning.
  r = run("render " + p.string() + " -o " + out.string() + " --size 32 32 --layout fsl");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("try --layout nifti --frame voxel"), std::string::npos) << r.err;
  r = run("render " + p.string() + " -o " + out.string() + " --size 32 32 --layout nifti");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
}
