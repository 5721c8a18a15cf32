// Tier 2: tensor conventions. The same world tensors, stored as each tool
// stores them (every NIfTI component order in every frame, under affines with
// det > 0 and det < 0; NRRD with measurement frames in RAS and LPS; VTK), read
// back as the same world tensors and the same glyphs. The stored values are
// computed here from each convention's definition, not by the reader's code.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include "io/io_test_util.h"
#include "io/nifti_fixture.h"
#include "io/core/readers.h"
#include "io/core/writers.h"
#include "tensor/glyph.h"

using namespace tg;
namespace fs = std::filesystem;

namespace {

using M3 = std::array<double, 9>;  // row-major

M3 mul(const M3& a, const M3& b) {
  M3 c{};
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) c[3 * r + j] += a[3 * r + k] * b[3 * k + j];
  return c;
}
M3 transpose(const M3& a) { return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]}; }
M3 diag(double x, double y, double z) { return {x, 0, 0, 0, y, 0, 0, 0, z}; }
// T D Tᵀ
M3 carry(const M3& t, const M3& d) { return mul(mul(t, d), transpose(t)); }

// Rotation by `deg` about `axis` (Rodrigues).
M3 rotation(std::array<double, 3> axis, double deg) {
  const double n = std::hypot(axis[0], axis[1], axis[2]);
  const double x = axis[0] / n, y = axis[1] / n, z = axis[2] / n, a = deg * M_PI / 180, c = std::cos(a),
               s = std::sin(a), C = 1 - c;
  return {c + x * x * C,     x * y * C - z * s, x * z * C + y * s, y * x * C + z * s, c + y * y * C,
          y * z * C - x * s, z * x * C - y * s, z * y * C + x * s, c + z * z * C};
}

// Components by name, in the order the reader returns them: xx xy xz yy yz zz.
enum { XX, XY, XZ, YY, YZ, ZZ };
std::array<double, 6> sym6(const M3& d) { return {d[0], d[1], d[2], d[4], d[5], d[8]}; }

// Each writer's stored order, from its documentation.
struct Order {
  const char* layout;
  std::array<int, 6> stored;  // stored value k holds this component
};
const Order kOrders[] = {
    {"fsl", {XX, XY, XZ, YY, YZ, ZZ}},     // FSL dtifit --save_tensor: upper triangle
    {"nifti", {XX, XY, YY, XZ, YZ, ZZ}},   // NIfTI SYMMATRIX: lower triangle (DIPY's lower_triangular)
    {"mrtrix", {XX, YY, ZZ, XY, XZ, YZ}},  // MRtrix dwi2tensor: D11 D22 D33 D12 D13 D23
    {"vtk", {XX, YY, ZZ, XY, YZ, XZ}},     // VTK's six-component order
};

constexpr int kN = 2;  // a 2x2x2 grid

// Eight distinct prolate and oblate diffusion tensors (mm²/s), world frame.
std::vector<M3> worldTensors() {
  std::vector<M3> out;
  for (int v = 0; v < kN * kN * kN; ++v) {
    const M3 r = rotation({1.0 + v, 2.0 - v, 0.5 + 0.3 * v}, 17.0 + 23.0 * v);
    out.push_back(carry(r, diag(1.7e-3, (v % 2 ? 0.9e-3 : 0.4e-3), 0.2e-3)));
  }
  return out;
}

// A = R diag(s): a rotated, scaled voxel grid. The orthogonal part of A is
// R diag(sign s); det A has the sign of s0 s1 s2.
struct Affine {
  const char* name;
  std::array<double, 3> s;
  M3 r = rotation({1, 2, 3}, 40);
  std::array<double, 3> origin{10, -5, 3};
  M3 linear() const { return mul(r, diag(s[0], s[1], s[2])); }
  M3 orthogonal() const { return mul(r, diag(s[0] < 0 ? -1 : 1, s[1] < 0 ? -1 : 1, s[2] < 0 ? -1 : 1)); }
  bool detPositive() const { return s[0] * s[1] * s[2] > 0; }
  std::array<double, 3> position(int i, int j, int k) const {
    const M3 a = linear();
    std::array<double, 3> p{};
    for (int row = 0; row < 3; ++row) p[row] = origin[row] + a[3 * row] * i + a[3 * row + 1] * j + a[3 * row + 2] * k;
    return p;
  }
};
const Affine kAffines[] = {{"det>0", {2, 2.5, 3}}, {"det<0", {-2, 2.5, 3}}};

// The stored tensor of world tensor d in `frame` (as its name says, from the
// conventions): voxel axes Q; FSL's voxel axes, x mirrored when det > 0; world.
M3 storedIn(const std::string& frame, const Affine& a, const M3& d) {
  if (frame == "world") return d;
  const M3 q = a.orthogonal();
  const M3 f = frame == "fsl" && a.detPositive() ? diag(-1, 1, 1) : diag(1, 1, 1);
  return carry(mul(f, transpose(q)), d);
}

test::NiftiTensors niftiOf(const Order& order, const std::string& frame, const Affine& a) {
  test::NiftiTensors fx;
  fx.dims[0] = fx.dims[1] = fx.dims[2] = kN;
  const M3 lin = a.linear();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) fx.affine[r][c] = lin[3 * r + c];
    fx.affine[r][3] = a.origin[r];
  }
  for (const M3& d : worldTensors()) {
    const auto s = sym6(storedIn(frame, a, d));
    std::array<float, 6> v{};
    for (int k = 0; k < 6; ++k) v[std::size_t(k)] = float(s[std::size_t(order.stored[std::size_t(k)])]);
    fx.voxels.push_back(v);
  }
  return fx;
}

// Every tensor and position of `f` equals the world field, voxel by voxel.
void expectWorldField(const io::TensorField& f, const Affine& a, const std::string& what) {
  const auto world = worldTensors();
  ASSERT_EQ(f.size(), world.size()) << what;
  for (std::size_t v = 0; v < f.size(); ++v) {
    const int i = int(f.ids[v] % kN), j = int(f.ids[v] / kN % kN), k = int(f.ids[v] / (kN * kN));
    const auto p = a.position(i, j, k);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f.positions[3 * v + std::size_t(c)], p[std::size_t(c)], 1e-4) << what;
    const auto d = sym6(world[f.ids[v]]);
    for (int c = 0; c < 6; ++c)
      EXPECT_NEAR(f.tensors[6 * v + std::size_t(c)], d[std::size_t(c)], 2e-9) << what << " voxel " << v << " comp " << c;
  }
}

fs::path dir() { return test::scratchDir("conventions"); }

io::ReadOptions readAs(const std::string& layout, const std::string& frame) {
  io::ReadOptions o;
  o.layout = layout;
  o.frame = frame;
  return o;
}

}  // namespace

TEST(Conventions, EveryNiftiLayoutAndFrameUnderBothHandednessesGivesTheWorldTensors) {
  for (const Affine& a : kAffines)
    for (const Order& order : kOrders)
      for (const std::string frame : {"voxel", "fsl", "world"}) {
        const std::string what = std::string(order.layout) + "/" + frame + "/" + a.name;
        const fs::path p = dir() / (std::string(order.layout) + "-" + frame + "-" + (a.detPositive() ? "pos" : "neg") + ".nii");
        test::writeNifti(p, niftiOf(order, frame, a));
        const io::TensorField f = io::readTensorField(p.string(), readAs(order.layout, frame));
        expectWorldField(f, a, what);
        EXPECT_EQ(f.frame.rfind(frame + " (--frame)", 0), 0u) << f.frame;
        // A mirror is applied exactly when FSL's frame meets det > 0: T's det
        // is then that of Q times -1.
        if (frame != "world") {
          ASSERT_TRUE(f.tensorToWC) << what;
          const auto& t = *f.tensorToWC;
          const double det = t[0] * (t[4] * t[8] - t[5] * t[7]) - t[1] * (t[3] * t[8] - t[5] * t[6]) +
                             t[2] * (t[3] * t[7] - t[4] * t[6]);
          const bool mirrored = frame == "fsl" && a.detPositive();
          EXPECT_NEAR(det, (a.detPositive() ? 1.0 : -1.0) * (mirrored ? -1.0 : 1.0), 1e-9) << what;
          EXPECT_EQ(f.frame.find("i reversed") != std::string::npos, mirrored) << f.frame;
        } else {
          EXPECT_FALSE(f.tensorToWC) << what;
        }
      }
}

TEST(Conventions, EachLayoutDefaultsToItsWritersFrame) {
  // FSL dtifit: FSL's frame; MRtrix: scanner (world); SYMMATRIX and VTK order: voxel axes.
  const std::pair<const char*, const char*> defaults[] = {
      {"fsl", "fsl"}, {"nifti", "voxel"}, {"mrtrix", "world"}, {"vtk", "voxel"}};
  const Affine& a = kAffines[0];
  for (const auto& [layout, frame] : defaults) {
    const Order& order = *std::find_if(std::begin(kOrders), std::end(kOrders),
                                       [&](const Order& o) { return std::string(o.layout) == layout; });
    const fs::path p = dir() / (std::string("default-") + layout + ".nii");
    test::writeNifti(p, niftiOf(order, frame, a));
    const io::TensorField f = io::readTensorField(p.string(), readAs(layout, ""));
    expectWorldField(f, a, layout);
    EXPECT_EQ(f.frame.rfind(std::string(frame) + " (the " + layout + " layout's", 0), 0u) << f.frame;
  }
}

TEST(Conventions, TheHeaderChoosesTheLayoutAndItsFrame) {
  const Affine& a = kAffines[0];
  // DIPY's workflow: 5-D, the SYMMATRIX intent, lower triangle, voxel axes.
  test::NiftiTensors dipy = niftiOf(kOrders[1], "voxel", a);
  dipy.symmatrix = true;
  test::writeNifti(dir() / "dipy5d.nii", dipy);
  const auto d = io::readTensorField((dir() / "dipy5d.nii").string(), {});
  expectWorldField(d, a, "SYMMATRIX");
  EXPECT_NE(d.layout.find("SYMMATRIX"), std::string::npos) << d.layout;
  // MRtrix: 4-D, its own order, scanner axes, and its name in descrip.
  test::NiftiTensors mrtrix = niftiOf(kOrders[2], "world", a);
  mrtrix.descrip = "MRtrix version: 3.0.3";
  test::writeNifti(dir() / "mrtrix.nii", mrtrix);
  const auto m = io::readTensorField((dir() / "mrtrix.nii").string(), {});
  expectWorldField(m, a, "MRtrix descrip");
  EXPECT_NE(m.layout.find("MRtrix"), std::string::npos) << m.layout;
  EXPECT_EQ(m.frame.rfind("world", 0), 0u) << m.frame;
  // The options still win over the header.
  const auto asVoxel = io::readTensorField((dir() / "mrtrix.nii").string(), readAs("", "voxel"));
  EXPECT_NE(asVoxel.tensors, m.tensors);
  // Without either: FSL's order and frame.
  test::writeNifti(dir() / "plain.nii", niftiOf(kOrders[0], "fsl", a));
  expectWorldField(io::readTensorField((dir() / "plain.nii").string(), {}), a, "no hint");
}

TEST(Conventions, BioImageSuiteAndDipyVoxelAxesUnderAPositiveAffineNeedOnlyTheFrame) {
  // Upper-triangle order in plain voxel axes (DIPY's dipy_fit_dti
  // --nifti_tensor False; BioImage Suite): FSL's order, not FSL's frame.
  const Affine& a = kAffines[0];
  test::writeNifti(dir() / "voxel-upper.nii", niftiOf(kOrders[0], "voxel", a));
  const std::string p = (dir() / "voxel-upper.nii").string();
  expectWorldField(io::readTensorField(p, readAs("", "voxel")), a, "--frame voxel");
  // The default reading mirrors them: same eigenvalues, wrong directions.
  const auto fsl = io::readTensorField(p, {});
  const auto world = worldTensors();
  double worst = 0;
  for (std::size_t v = 0; v < fsl.size(); ++v) worst = std::max(worst, double(std::abs(fsl.tensors[6 * v + 1] - float(sym6(world[fsl.ids[v]])[XY]))));
  EXPECT_GT(worst, 1e-5);
}

TEST(Conventions, NrrdMeasurementFramesInRasAndLpsGiveTheWorldTensors) {
  const Affine& a = kAffines[0];
  const M3 frames[] = {diag(1, 1, 1), rotation({0.3, -1, 0.4}, 70), mul(rotation({1, 1, 0}, 25), diag(1, 1, -1))};
  int n = 0;
  for (const M3& m : frames)
    for (const bool lps : {false, true}) {
      // World (RAS) -> the file's space: LPS negates x and y.
      const M3 toSpace = lps ? diag(-1, -1, 1) : diag(1, 1, 1);
      const fs::path p = dir() / ("frame" + std::to_string(n++) + ".nhdr");
      std::ofstream h(p);
      h.precision(17);
      h << "NRRD0005\ntype: double\ndimension: 4\nspace: " << (lps ? "left-posterior-superior" : "right-anterior-superior")
        << "\nsizes: 6 " << kN << " " << kN << " " << kN << "\nkinds: 3D-symmetric-matrix space space space\n";
      const M3 dirs = mul(toSpace, a.linear());
      h << "space directions: none";
      for (int c = 0; c < 3; ++c) h << " (" << dirs[c] << "," << dirs[3 + c] << "," << dirs[6 + c] << ")";
      h << "\nspace origin: (" << (lps ? -a.origin[0] : a.origin[0]) << "," << (lps ? -a.origin[1] : a.origin[1]) << ","
        << a.origin[2] << ")\n";
      // NRRD's spec: vector k is column k of M, which maps measurement-frame
      // coordinates into the space: D_space = M D Mᵀ.
      h << "measurement frame:";
      for (int c = 0; c < 3; ++c) h << " (" << m[c] << "," << m[3 + c] << "," << m[6 + c] << ")";
      h << "\nencoding: ascii\n\n";
      for (const M3& d : worldTensors()) {
        const auto s = sym6(carry(transpose(m), carry(toSpace, d)));
        for (double x : s) h << x << " ";
        h << "\n";
      }
      h.close();
      const io::TensorField f = io::readTensorField(p.string(), {});
      expectWorldField(f, a, p.filename().string());
      EXPECT_TRUE(f.measurementFrame);
      EXPECT_NE(f.frame.find(lps ? "left-posterior-superior to RAS" : "measurement frame"), std::string::npos) << f.frame;
    }
}

TEST(Conventions, VtkWorldTensorsInNineAndSixComponentsAndEveryFormatGiveTheSameGlyphs) {
  const Affine& a = kAffines[1];
  io::TensorField world;
  const auto tensors = worldTensors();
  for (std::uint32_t v = 0; v < tensors.size(); ++v) {
    const auto p = a.position(int(v % kN), int(v / kN % kN), int(v / (kN * kN)));
    const auto s = sym6(tensors[v]);
    world.addSym(v, p.data(), s.data());
  }
  io::writeVtk(world, (dir() / "world.vtu").string());
  const io::TensorField vtu = io::readTensorField((dir() / "world.vtu").string(), {});
  expectWorldField(vtu, a, "vtu");
  EXPECT_FALSE(vtu.tensorToWC);
  // Six components in VTK's order, hand-written as a FIELD array.
  {
    std::ofstream h(dir() / "six.vtk");
    h.precision(17);
    h << "# vtk DataFile Version 3.0\nsix\nASCII\nDATASET POLYDATA\nPOINTS " << world.size() << " double\n";
    for (std::size_t v = 0; v < world.size(); ++v) {
      const auto p = a.position(int(v % kN), int(v / kN % kN), int(v / (kN * kN)));
      h << p[0] << " " << p[1] << " " << p[2] << "\n";
    }
    h << "POINT_DATA " << world.size() << "\nFIELD FieldData 1\nd6 6 " << world.size() << " double\n";
    for (const M3& d : tensors) {
      const auto s = sym6(d);
      h << s[XX] << " " << s[YY] << " " << s[ZZ] << " " << s[XY] << " " << s[YZ] << " " << s[XZ] << "\n";
    }
  }
  io::ReadOptions six;
  six.arrayName = "d6";
  expectWorldField(io::readTensorField((dir() / "six.vtk").string(), six), a, "6-component VTK");

  // The glyphs of every reading: those of the VTK field.
  test::writeNifti(dir() / "glyph-fsl.nii", niftiOf(kOrders[0], "fsl", a));
  test::writeNifti(dir() / "glyph-mrtrix.nii", niftiOf(kOrders[2], "world", a));
  const tensor::GlyphSet ref = tensor::buildGlyphs(vtu.positions, vtu.tensors, vtu.ids, 0, {});
  for (const char* name : {"glyph-fsl.nii", "glyph-mrtrix.nii"}) {
    const io::TensorField f = io::readTensorField((dir() / name).string(), readAs(name[6] == 'f' ? "fsl" : "mrtrix", ""));
    const tensor::GlyphSet g = tensor::buildGlyphs(f.positions, f.tensors, f.ids, 0, {});
    ASSERT_EQ(g.glyphs.size(), ref.glyphs.size()) << name;
    for (std::size_t k = 0; k < g.glyphs.size(); ++k) {
      const auto &x = g.glyphs[k], &y = ref.glyphs[k];
      ASSERT_EQ(x.id, y.id);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(x.posWC[c], y.posWC[c], 1e-4) << name;
        EXPECT_NEAR(x.eigenvalues[c], y.eigenvalues[c], 1e-8) << name;
      }
      // The same rotation, up to the quaternion's sign and the eigenvectors'.
      float dot = 0;
      for (int c = 0; c < 4; ++c) dot += x.frameWC[c] * y.frameWC[c];
      EXPECT_GT(std::abs(dot), 0.999f) << name << " glyph " << k;
    }
  }
}

namespace {

// n diffusion tensors in random orientations, as a fit of a brain gives them.
std::vector<M3> randomDiffusionTensors(int n) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1), l(0.1e-3, 0.5e-3);
  std::vector<M3> out;
  for (int v = 0; v < n; ++v) {
    const M3 r = rotation({u(rng), u(rng), u(rng)}, 180 * u(rng));
    out.push_back(carry(r, diag(1.0e-3 + 1.5 * l(rng), l(rng), l(rng))));
  }
  return out;
}

test::NiftiTensors randomField(const Order& order) {
  test::NiftiTensors fx;
  fx.dims[0] = fx.dims[1] = fx.dims[2] = 6;
  for (const M3& d : randomDiffusionTensors(216)) {
    const auto s = sym6(d);
    std::array<float, 6> v{};
    for (int k = 0; k < 6; ++k) v[std::size_t(k)] = float(s[std::size_t(order.stored[std::size_t(k)])]);
    fx.voxels.push_back(v);
  }
  return fx;
}

}  // namespace

TEST(Conventions, AnImplausibleDefaultOrderIsRefusedNamingThePlausibleOne) {
  // DIPY's lower_triangular saved as a plain 4-D image, and MRtrix's order
  // without its descrip: both read as FSL's order by default, which makes
  // most of them indefinite. Where one other order reads them as diffusion
  // tensors the read is refused, naming it; where two do (MRtrix's and VTK's
  // differ by xz and yz only), the picture is drawn with a warning naming
  // both. Every order a message names reads them plausibly.
  struct Case {
    const Order& stored;
    bool refused;
    std::vector<std::string> named;
  } cases[] = {{kOrders[1], true, {"--layout nifti --frame voxel"}},
               {kOrders[2], false, {"--layout mrtrix --frame world", "--layout vtk --frame voxel (or paraview"}}};
  for (const Case& c : cases) {
    const fs::path p = dir() / (std::string("indefinite-") + c.stored.layout + ".nii");
    test::writeNifti(p, randomField(c.stored));
    std::string said;
    if (c.refused) {
      said = test::readError(p);
      EXPECT_NE(said.find("to draw this reading"), std::string::npos) << said;
      // Named, the implausible order is drawn, with the same advice as a warning.
      const io::TensorField asked = io::readTensorField(p.string(), readAs("fsl", ""));
      ASSERT_EQ(asked.warnings.size(), 1u);
      EXPECT_NE(asked.warnings[0].find("try " + c.named[0]), std::string::npos) << asked.warnings[0];
    } else {
      const io::TensorField f = io::readTensorField(p.string(), {});
      ASSERT_EQ(f.warnings.size(), 1u) << c.stored.layout;
      said = f.warnings[0];
    }
    EXPECT_NE(said.find("indefinite"), std::string::npos) << said;
    for (const std::string& n : c.named) EXPECT_NE(said.find(n), std::string::npos) << said;
    EXPECT_EQ(said.find("--layout fsl --frame fsl reads"), std::string::npos) << said;  // implausible: never offered
    EXPECT_EQ(said.find('\n'), std::string::npos);
    // Read as written: no warning.
    EXPECT_TRUE(io::readTensorField(p.string(), readAs(c.stored.layout, "")).warnings.empty()) << c.stored.layout;
  }
  // FEM orders are for VTK files and arrays, not NIfTI.
  EXPECT_NE(test::readError(dir() / "indefinite-mrtrix.nii", readAs("abaqus", "")).find("--layout abaqus does not "
                                                                                         "apply to NIfTI"),
            std::string::npos);
}

TEST(Conventions, DefiniteTensorsInAnyFrameDoNotWarn) {
  for (const Affine& a : kAffines)
    for (const std::string frame : {"voxel", "fsl", "world"}) {
      const fs::path p = dir() / ("quiet-" + frame + ".nii");
      test::writeNifti(p, niftiOf(kOrders[0], frame, a));
      EXPECT_TRUE(io::readTensorField(p.string(), readAs("fsl", frame)).warnings.empty()) << frame;
    }
}

TEST(Conventions, OptionsForAnotherFormatAreRefused) {
  const Affine& a = kAffines[0];
  test::writeNifti(dir() / "opt.nii", niftiOf(kOrders[0], "fsl", a));
  io::TensorField world;
  const double p[3] = {0, 0, 0}, s[6] = {1, 0, 0, 1, 0, 1};
  world.addSym(0, p, s);
  io::writeVtk(world, (dir() / "opt.vtp").string());
  io::ReadOptions array, layout, frame, confidence;
  array.arrayName = "x";
  layout.layout = "fsl";
  frame.frame = "world";
  confidence.confidenceGiven = true;
  EXPECT_NE(test::readError(dir() / "opt.nii", array).find("--array does not apply to NIfTI"), std::string::npos);
  EXPECT_NE(test::readError(dir() / "opt.nii", confidence).find("--confidence-min"), std::string::npos);
  // --layout orders six values: a 9-component array has none to order.
  EXPECT_NE(test::readError(dir() / "opt.vtp", layout).find("--layout applies to 6-component arrays"),
            std::string::npos);
  EXPECT_NE(test::readError(dir() / "opt.vtp", frame).find("--frame does not apply to VTK"), std::string::npos);
  EXPECT_NE(test::readError(dir() / "opt.nii", readAs("", "sideways")).find("unknown frame"), std::string::npos);
}
