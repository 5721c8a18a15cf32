// Tractography readers (io/core/tract_reader.h) against nibabel.streamlines on
// files nibabel and MRtrix write at test time (peers/peer_tracts.py), VTK's
// own reading of Slicer's fibre polylines, and hostile inputs: every
// truncation, wrong magic, lying counts and sizes, NaN points.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/io_test_util.h"
#include "io/core/tract_reader.h"

using namespace tg;
namespace fs = std::filesystem;

namespace {

const fs::path kFibres = fs::path(TG_REAL_DATA_DIR) / "slicer-fiber-tensors" / "fiber_vtk.vtk";

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

template <class T>
std::vector<T> raw(const fs::path& p) {
  const std::string b = slurp(p);
  std::vector<T> v(b.size() / sizeof(T));
  std::memcpy(v.data(), b.data(), v.size() * sizeof(T));
  return v;
}

// The peers' files, written once per test binary (about 1 s: nibabel's import).
const fs::path& peers() {
  static const fs::path d = [] {
    const fs::path dir = test::scratchDir("tracts") / "peers";
    const std::string cmd = std::string(TG_PYTHON3) + " " + TG_PEER_TRACTS + " " + dir.string() + " " +
                            kFibres.string() + " 2>" + (dir.parent_path() / "py.txt").string();
    const int status = std::system(cmd.c_str());
    EXPECT_EQ(status, 0) << cmd << "\n" << slurp(dir.parent_path() / "py.txt")
                         << "\n(needs python3-nibabel, python3-vtk9 and mrtrix3)";
    return dir;
  }();
  return d;
}

std::string readError(const fs::path& p) {
  try {
    io::readTractsInProcess(p.string());
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

// Our streamlines against a peer's points and lengths, point for point.
void expectSame(const io::TractData& t, const fs::path& points, const fs::path& lengths, double tol) {
  const std::vector<float> p = raw<float>(points);
  const std::vector<std::int64_t> n = raw<std::int64_t>(lengths);
  ASSERT_FALSE(n.empty()) << lengths;
  ASSERT_EQ(t.streamlineCount(), n.size()) << t.path;
  ASSERT_EQ(t.positionsWC.size(), p.size()) << t.path;
  for (std::size_t k = 0; k < n.size(); ++k) ASSERT_EQ(t.starts[k + 1] - t.starts[k], std::uint64_t(n[k])) << k;
  double worst = 0;
  for (std::size_t k = 0; k < p.size(); ++k)
    worst = std::max(worst, std::abs(double(t.positionsWC[k]) - double(p[k])) / std::max(1.0, std::abs(double(p[k]))));
  EXPECT_LE(worst, tol) << t.path;
  EXPECT_EQ(t.skippedNonFinite, 0u);
}

// A .tck of `values` (x y z triplets, NaN and Inf delimiters as given) after `header` lines.
std::string tck(const std::vector<float>& values, const std::string& extra = "", const char* datatype = "Float32LE") {
  std::string head = std::string("mrtrix tracks\ndatatype: ") + datatype + "\n" + extra;
  std::string h = head + "file: . 000\nEND\n";
  const std::string offset = std::to_string(h.size());
  h = head + "file: . " + std::string(3 - offset.size(), '0') + offset + "\nEND\n";
  return h + std::string(reinterpret_cast<const char*>(values.data()), 4 * values.size());
}

constexpr float kNan = NAN, kInf = INFINITY;
const std::vector<float> kTwoLines = {0, 0, 0, 1, 0, 0, 2, 1, 0, kNan, kNan, kNan,
                                      5, 5, 5, 5, 6, 5, kNan, kNan, kNan, kInf, kInf, kInf};

template <class T>
void put(std::string& s, std::size_t at, T v) {
  std::memcpy(s.data() + at, &v, sizeof v);
}

}  // namespace

TEST(Tracts, AgreeWithNibabelPointForPoint) {
  // nibabel loads every case in RAS+ mm: the .trk ones through its voxmm-to-RAS affine.
  for (const char* name : {"plain", "bigendian", "fibres", "mrtrix"}) {
    SCOPED_TRACE(name);
    const fs::path f = peers() / (std::string(name) + ".tck");
    expectSame(io::readTractsInProcess(f.string()), peers() / (std::string(name) + ".points"),
               peers() / (std::string(name) + ".lengths"), 0.0);
  }
  for (const char* name : {"oblique", "lps-order", "permuted", "scalars", "bigendian-trk", "fibres-trk"}) {
    SCOPED_TRACE(name);
    const fs::path f = peers() / (std::string(name) + ".trk");
    // nibabel applies its float32 affine in float32, ours in double: they
    // differ by float32's rounding at the affine's 126 mm offset (7.5e-6 mm).
    expectSame(io::readTractsInProcess(f.string()), peers() / (std::string(name) + ".points"),
               peers() / (std::string(name) + ".lengths"), 2e-5);
  }
  // The guarded child gives the same.
  const io::TractData a = io::readTracts((peers() / "oblique.trk").string());
  const io::TractData b = io::readTractsInProcess((peers() / "oblique.trk").string());
  EXPECT_TRUE(a.positionsWC == b.positionsWC && a.starts == b.starts);
  EXPECT_NE(a.description.find("TrackVis"), std::string::npos) << a.description;
}

TEST(Tracts, TrkVoxmmToRasIsNibabels) {
  for (const char* name : {"oblique", "lps-order", "permuted", "scalars"}) {
    SCOPED_TRACE(name);
    const std::string h = slurp(peers() / (std::string(name) + ".trk")).substr(0, 1000);
    float v2r[16], sizes[3];
    std::int16_t dims[3];
    std::memcpy(dims, h.data() + 6, 6);
    std::memcpy(sizes, h.data() + 12, 12);
    std::memcpy(v2r, h.data() + 440, 64);
    const io::TrkTransform t = io::trkToWorld(v2r, h.data() + 948, dims, sizes);
    ASSERT_TRUE(t.ok) << t.problem;
    const std::vector<double> want = raw<double>(peers() / (std::string(name) + ".affine"));
    ASSERT_EQ(want.size(), 16u);
    for (std::size_t k = 0; k < 16; ++k) EXPECT_NEAR(t.voxmmToRas[k], want[k], 1e-6 * std::max(1.0, std::abs(want[k]))) << k;
  }
  // The voxel order that disagrees with vox_to_ras flips the axes over the
  // dimensions: voxmm x = 0 (the corner) is voxel -0.5, flipped to dims-1+0.5.
  const std::string h = slurp(peers() / "lps-order.trk").substr(0, 1000);
  float v2r[16], sizes[3];
  std::int16_t dims[3];
  std::memcpy(dims, h.data() + 6, 6);
  std::memcpy(sizes, h.data() + 12, 12);
  std::memcpy(v2r, h.data() + 440, 64);
  const io::TrkTransform t = io::trkToWorld(v2r, h.data() + 948, dims, sizes);
  EXPECT_NEAR(t.voxmmToRas[3], v2r[3] + v2r[0] * (dims[0] - 0.5), 1e-4);   // L: flipped
  EXPECT_NEAR(t.voxmmToRas[0], -v2r[0] / sizes[0], 1e-6);
  EXPECT_NEAR(t.voxmmToRas[11], v2r[11] + v2r[10] * -0.5, 1e-4);          // S: kept
}

TEST(Tracts, VtkPolylinesAreTheLinesVtkReads) {
  ASSERT_TRUE(fs::exists(kFibres)) << kFibres;
  const io::TractData t = io::readTracts(kFibres.string());
  expectSame(t, peers() / "vtk.points", peers() / "vtk.lengths", 0.0);
  EXPECT_EQ(t.streamlineCount(), 8u);
  EXPECT_EQ(t.pointCount(), 1079u);
  // Its .tck copy reads back the same points.
  const io::TractData c = io::readTractsInProcess((peers() / "fibres.tck").string());
  EXPECT_TRUE(c.positionsWC == t.positionsWC && c.starts == t.starts);
}

TEST(Tracts, EveryTruncationIsRefused) {
  const fs::path dir = test::scratchDir("tracts");
  for (const char* name : {"plain.tck", "mrtrix.tck", "oblique.trk", "scalars.trk"}) {
    const std::string whole = slurp(peers() / name);
    const fs::path cut = dir / (std::string("cut") + fs::path(name).extension().string());
    // Through the headers in steps of 7 bytes, then about 300 cuts, and every one of the last 64 bytes.
    const std::size_t step = std::max<std::size_t>(1, whole.size() / 300);
    for (std::size_t n = 1; n < whole.size(); n += n < 1100 ? 7 : n + 64 >= whole.size() ? 1 : step) {
      test::writeFile(cut, whole.substr(0, n));
      const std::string e = readError(cut);
      ASSERT_FALSE(e.empty()) << name << " cut to " << n << " bytes was read";
      ASSERT_EQ(e.rfind("readTracts: " + cut.string() + ": ", 0), 0u) << e;
      ASSERT_EQ(e.find('\n'), std::string::npos) << e;
    }
  }
}

const std::string kPolyHead =
    "# vtk DataFile Version 4.2\nx\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 1 1 2 2 2\n";

TEST(Tracts, HostileHeadersAreRefusedInOneLine) {
  const fs::path dir = test::scratchDir("tracts");
  const std::string good = slurp(peers() / "oblique.trk");
  struct Case {
    std::string name, bytes, what;
  };
  std::vector<Case> cases = {
      {"magic.tck", "mrtrix track\n" + tck(kTwoLines).substr(14), "not an MRtrix tracks file"},
      {"noend.tck", "mrtrix tracks\ndatatype: Float32LE\nfile: . 40\n", "no END line"},
      {"nodatatype.tck", "mrtrix tracks\nfile: . 30\nEND\n" + std::string(12, '\0'), "gives no datatype"},
      {"float16.tck", tck(kTwoLines, "", "Float16LE"), "datatype \"Float16LE\""},
      {"detached.tck", "mrtrix tracks\ndatatype: Float32LE\nfile: other.dat 0\nEND\n", "only \". OFFSET\""},
      {"offset-inside.tck", "mrtrix tracks\ndatatype: Float32LE\nfile: . 3\nEND\n", "inside the header"},
      {"offset-beyond.tck", "mrtrix tracks\ndatatype: Float32LE\nfile: . 99999999999\nEND\n", "beyond the file"},
      {"offset-text.tck", "mrtrix tracks\ndatatype: Float32LE\nfile: . 4e1\nEND\n", "not a whole number"},
      {"badline.tck", "mrtrix tracks\ndatatype Float32LE\nEND\n", "line 2 is not \"key: value\""},
      {"after-end.tck", tck([] {
         std::vector<float> v = kTwoLines;
         v.insert(v.end(), {1, 2, 3});
         return v;
       }()), "1 point after the end marker"},
      {"no-delimiter.tck", tck({0, 0, 0, 1, 1, 1, kInf, kInf, kInf}), "no NaN delimiter"},
      {"huge-count.tck", tck(kTwoLines, "count: 999999999999\n"), ""},  // count is never trusted: read
      {"empty.trk", std::string(999, 'T'), "too short for a TrackVis file"},
      // Legacy cell lists whose counts do not fill the header's size: VTK
      // imported them trusting each count, reading ids past its buffer.
      {"overrun.vtk", kPolyHead + "LINES 1 4\n9 0 1 2\n", "cell 0's point count 9 runs past the list's size"},
      {"short-list.vtk", kPolyHead + "LINES 2 4\n3 0 1 2\n", "its size holds 1 of the cells"},
      {"negative-count.vtk", kPolyHead + "LINES 1 4\n-3 0 1 2\n", "point count -3 runs past"},
  };
  auto trk = [&](const std::string& name, auto edit, const std::string& what) {
    std::string b = good;
    edit(b);
    cases.push_back({name, b, what});
  };
  trk("magic.trk", [](std::string& b) { b[0] = 'X'; }, "does not begin with \"TRACK\"");
  trk("hdrsize.trk", [](std::string& b) { put<std::int32_t>(b, 996, 1001); }, "hdr_size is 1001");
  trk("version.trk", [](std::string& b) { put<std::int32_t>(b, 992, 7); }, "version 7");
  trk("voxsize.trk", [](std::string& b) { put<float>(b, 16, 0.0f); }, "voxel size 1 is 0");
  trk("voxsize-nan.trk", [](std::string& b) { put<float>(b, 12, kNan); }, "voxel size 0 is nan");
  trk("order.trk", [](std::string& b) { std::memcpy(b.data() + 948, "LLS", 3); }, "voxel order \"LLS\"");
  trk("singular.trk", [](std::string& b) { for (int k = 0; k < 4; ++k) put<float>(b, 440 + 4 * k, 0.0f); },
      "vox_to_ras is singular");
  trk("nscalars.trk", [](std::string& b) { put<std::int16_t>(b, 36, -2); }, "negative counts");
  trk("huge-count.trk", [](std::string& b) { put<std::int32_t>(b, 988, 0x7fffffff); }, "is missing");
  trk("short-count.trk", [](std::string& b) { put<std::int32_t>(b, 988, 3); }, "after the 3 streamlines");
  trk("huge-points.trk", [](std::string& b) { put<std::int32_t>(b, 1000, 0x7fffffff); }, "truncated, or the count is wrong");
  trk("negative-points.trk", [](std::string& b) { put<std::int32_t>(b, 1000, -4); }, "has -4 points");
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const fs::path p = dir / c.name;
    test::writeFile(p, c.bytes);
    const auto t0 = std::chrono::steady_clock::now();
    const std::string e = readError(p);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 1.0);
    if (c.what.empty()) {
      EXPECT_EQ(e, "");
      continue;
    }
    EXPECT_EQ(e.rfind("readTracts: " + p.string() + ": ", 0), 0u) << e;
    EXPECT_NE(e.find(c.what), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
  // A name no reader takes, and an extension that holds no tracts.
  EXPECT_NE(io::tractExtensionProblem("a.stl").find("supported: .vtk .vtp .tck .trk"), std::string::npos)
      << io::tractExtensionProblem("a.stl");
  EXPECT_EQ(io::tractExtensionProblem("A.TRK"), "");
}

TEST(Tracts, NonFinitePointsDropTheirStreamlineAndAreCounted) {
  const fs::path dir = test::scratchDir("tracts");
  std::vector<float> v = kTwoLines;
  v[4] = kInf;  // the first streamline's second point: Inf in y only
  test::writeFile(dir / "inf.tck", tck(v));
  const io::TractData t = io::readTractsInProcess((dir / "inf.tck").string());
  EXPECT_EQ(t.skippedNonFinite, 1u);
  ASSERT_EQ(t.streamlineCount(), 1u);
  EXPECT_EQ(t.pointCount(), 2u);
  EXPECT_EQ(t.positionsWC[0], 5.0f);
  // Float64 beyond single precision is as unusable on the GPU.
  std::vector<double> d = {0, 0, 0, 1e300, 0, 0, NAN, NAN, NAN, 1, 1, 1, 2, 2, 2, NAN, NAN, NAN, INFINITY, INFINITY, INFINITY};
  std::string head = "mrtrix tracks\ndatatype: Float64LE\nfile: . 49\nEND\n";
  ASSERT_EQ(head.size(), 49u);
  test::writeFile(dir / "f64.tck", head + std::string(reinterpret_cast<const char*>(d.data()), 8 * d.size()));
  const io::TractData f = io::readTractsInProcess((dir / "f64.tck").string());
  EXPECT_EQ(f.skippedNonFinite, 1u);
  EXPECT_EQ(f.streamlineCount(), 1u);
}

TEST(Tracts, AMemoryBudgetIsKeptBeforeAllocating) {
  const std::string e = [&] {
    try {
      io::readTractsInProcess((peers() / "plain.tck").string(), 1 << 20);
    } catch (const io::InputError& x) {
      return std::string(x.what());
    }
    return std::string();
  }();
  EXPECT_NE(e.find("MiB this load may use"), std::string::npos) << e;
}
