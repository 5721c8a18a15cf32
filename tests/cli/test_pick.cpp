// Tier 2: `render --pick I J` through the real binary, its JSON parsed back.
// The oracles: the tensors the test wrote, the projected glyph centres, and
// the double-precision reference (ref::renderEllipsoids) for silhouettes and
// depth; on real data, the file's values as Teem reads them.
#include <gtest/gtest.h>
#include <json/json.h>
#include <teem/nrrd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_run.h"
#include "io/core/writers.h"
#include "real_data.h"
#include "ref/ellipsoid_ref.h"
#include "view/camera.h"
#include "tensor/glyph.h"

namespace fs = std::filesystem;
using tg::test::CmdResult;

namespace {

fs::path dir() { return tg::test::cliDir("pick"); }

constexpr int kW = 160, kH = 120, kSub = 4;  // the reference's subpixels a side
const glm::dvec3 kEye(4, 4, 40), kLookAt(4, 4, 0);
constexpr double kOrtho = 14.0;

// R diag(l) Rᵀ for R rotating by `angle` about `axis`, as xx xy xz yy yz zz.
std::array<float, 6> rotated(glm::dvec3 l, glm::dvec3 axis, double angle) {
  axis = glm::normalize(axis);
  const double c = std::cos(angle), s = std::sin(angle);
  double r[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double cross = (i == j) ? 0.0 : ((j == (i + 1) % 3 ? -1.0 : 1.0) * axis[3 - i - j]);
      r[i][j] = (i == j ? c : 0.0) + (1 - c) * axis[i] * axis[j] + s * cross;
    }
  auto d = [&](int i, int j) { return r[i][0] * l.x * r[j][0] + r[i][1] * l.y * r[j][1] + r[i][2] * l.z * r[j][2]; };
  return {float(d(0, 0)), float(d(0, 1)), float(d(0, 2)), float(d(1, 1)), float(d(1, 2)), float(d(2, 2))};
}

// Nine distinct tensors on a 3 x 3 grid, 4 apart: positive definite ones in
// several orientations, an isotropic one (4), a negative definite one (7)
// and one of mixed sign (8). Semi-axes at most 1.5: no two glyphs touch.
struct Field {
  std::vector<float> positions, tensors;
  std::vector<std::uint32_t> ids;
};
Field synthetic() {
  Field f;
  const glm::dvec3 evals[9] = {{1.4, 0.6, 0.3}, {1.2, 1.0, 0.4}, {0.9, 0.5, 0.45},   {1.5, 0.35, 0.3}, {0.9, 0.9, 0.9},
                               {1.1, 0.8, 0.5}, {1.3, 0.7, 0.6}, {-0.4, -0.7, -1.2}, {1.1, 0.3, -0.6}};
  for (int k = 0; k < 9; ++k) {
    f.positions.insert(f.positions.end(), {float(4 * (k % 3)), float(4 * (k / 3)), 0.0f});
    const auto t = rotated(evals[k], glm::dvec3(1.0 + k, 2.0 - 0.3 * k, 0.5 + 0.2 * k), 0.35 * k + 0.2);
    f.tensors.insert(f.tensors.end(), t.begin(), t.end());
    f.ids.push_back(std::uint32_t(k));
  }
  return f;
}

fs::path writeField(const Field& f) {
  tg::io::TensorField tf;
  for (std::size_t k = 0; k < f.ids.size(); ++k) {
    const double p[3] = {f.positions[3 * k], f.positions[3 * k + 1], f.positions[3 * k + 2]};
    double s[6];
    for (int c = 0; c < 6; ++c) s[c] = f.tensors[6 * k + std::size_t(c)];
    tf.addSym(f.ids[k], p, s);
  }
  const fs::path path = dir() / "nine.vtp";
  tg::io::writeVtk(tf, path.string());
  return path;
}

tg::render::Camera camera(const tg::tensor::GlyphSet& set, int w, int h) {
  tg::render::CameraDesc d;
  d.eyeWC = kEye;
  d.lookAtWC = kLookAt;
  d.upWC = {0, 1, 0};
  d.projection = tg::render::Projection::Orthographic;
  d.orthoHeight = kOrtho;
  const auto box = tg::tensor::glyphBoxWC(set, 1.0);
  return tg::render::makeCamera(d, w, h, box.lo, box.hi);
}

std::string cameraFlags() {
  return "--size " + std::to_string(kW) + " " + std::to_string(kH) +
         " --scale-mode absolute --scale 2 --eye 4 4 40 --look-at 4 4 0 --up 0 1 0 --ortho 14";
}

std::vector<Json::Value> parseLines(const std::string& out) {
  std::vector<Json::Value> v;
  std::istringstream in(out);
  Json::CharReaderBuilder b;
  for (std::string line; std::getline(in, line);) {
    Json::Value o;
    std::string err;
    std::istringstream one(line);
    EXPECT_TRUE(Json::parseFromStream(b, one, &o, &err)) << err << ": " << line;
    v.push_back(o);
  }
  return v;
}

std::string pickFlags(const std::vector<std::array<int, 2>>& pixels) {
  std::string s;
  for (const auto& p : pixels) s += " --pick " + std::to_string(p[0]) + " " + std::to_string(p[1]);
  return s;
}

glm::dvec3 vec3(const Json::Value& a) { return {a[0].asDouble(), a[1].asDouble(), a[2].asDouble()}; }

// The eigensystem and invariants against their definitions, not the solver.
void expectConsistent(const Json::Value& g, const std::array<float, 6>& t) {
  const double m[3][3] = {{t[0], t[1], t[2]}, {t[1], t[3], t[4]}, {t[2], t[4], t[5]}};
  const glm::dvec3 l = vec3(g["eigenvalues"]);
  const double norm = std::sqrt(l.x * l.x + l.y * l.y + l.z * l.z);
  EXPECT_GE(l.x, l.y);
  EXPECT_GE(l.y, l.z);
  EXPECT_NEAR(l.x + l.y + l.z, t[0] + t[3] + t[5], 1e-6 * norm);
  for (int k = 0; k < 3; ++k) {
    const glm::dvec3 v = vec3(g["eigenvectors"][k]);
    EXPECT_NEAR(glm::length(v), 1.0, 1e-9);
    for (int r = 0; r < 3; ++r)
      EXPECT_NEAR(m[r][0] * v.x + m[r][1] * v.y + m[r][2] * v.z, l[k] * v[r], 1e-6 * norm) << "eigenpair " << k;
  }
  const double md = (l.x + l.y + l.z) / 3.0;
  EXPECT_NEAR(g["md"].asDouble(), md, 1e-12);
  const double dev = (l.x - md) * (l.x - md) + (l.y - md) * (l.y - md) + (l.z - md) * (l.z - md);
  EXPECT_NEAR(g["fa"].asDouble(), std::sqrt(1.5 * dev) / norm, 1e-9);
  if (l.x + l.y + l.z > 0) {
    EXPECT_NEAR(g["cl"].asDouble(), (l.x - l.y) / (l.x + l.y + l.z), 1e-9);
    EXPECT_NEAR(g["cp"].asDouble(), 2 * (l.y - l.z) / (l.x + l.y + l.z), 1e-9);
  }
}

// The reference at kSub x kSub subpixels: the id a pixel's centre shows,
// when the four subpixels around it (1/8 pixel away) agree, else nothing
// (a silhouette passes too close to the centre to call).
struct SafeIds {
  tg::ref::RefImage img;
  std::optional<std::uint32_t> at(int i, int j) const {
    const std::uint32_t first = img.id[std::size_t(kSub * j + 1) * img.width + std::size_t(kSub * i + 1)];
    for (int b = 1; b < 3; ++b)
      for (int a = 1; a < 3; ++a)
        if (img.id[std::size_t(kSub * j + b) * img.width + std::size_t(kSub * i + a)] != first) return std::nullopt;
    return first;
  }
};

}  // namespace

// The pixel under each glyph's projected centre reports that glyph: its
// index, position and tensor exactly as written, a consistent eigensystem,
// the sign classes, and a surface point and depth that agree with the
// reference; a corner pixel reports the background.
TEST(Pick, GlyphCentresReportTheirTensors) {
  const Field f = synthetic();
  const fs::path in = writeField(f);
  const tg::tensor::GlyphSet set = tg::tensor::buildGlyphs(f.positions, f.tensors, f.ids);
  const tg::render::Camera cam = camera(set, kW, kH);
  const tg::ref::RefImage ref = tg::ref::renderEllipsoids(cam, set.glyphs, tg::ref::RefParams(1.0));
  std::vector<std::array<int, 2>> pixels;
  for (int k = 0; k < 9; ++k) {
    const glm::dvec4 c = cam.projVCCC * cam.viewWCVC *
                         glm::dvec4(f.positions[3 * k], f.positions[3 * k + 1], f.positions[3 * k + 2], 1.0);
    pixels.push_back({int(std::floor((c.x / c.w + 1) / 2 * kW)), int(std::floor((1 - c.y / c.w) / 2 * kH))});
  }
  pixels.push_back({0, 0});
  const fs::path out = dir() / "centres.png";
  const CmdResult r = tg::test::runBinary(
      "render " + in.string() + " -o " + out.string() + " " + cameraFlags() + pickFlags(pixels), dir());
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<Json::Value> picks = parseLines(r.out);
  ASSERT_EQ(picks.size(), pixels.size()) << r.out;
  const char* signs[9] = {"positive-definite", "positive-definite", "positive-definite",
                          "positive-definite", "positive-definite", "positive-definite",
                          "positive-definite", "negative-definite", "indefinite"};
  const char* groups[9] = {"definite", "definite", "definite", "definite", "sphere",
                           "definite", "definite", "definite", "mixed"};
  for (int k = 0; k < 9; ++k) {
    SCOPED_TRACE("glyph " + std::to_string(k));
    const Json::Value& g = picks[std::size_t(k)];
    EXPECT_EQ(g["pixel"][0].asInt(), pixels[std::size_t(k)][0]);
    EXPECT_EQ(g["pixel"][1].asInt(), pixels[std::size_t(k)][1]);
    ASSERT_EQ(g["hit"].asString(), "glyph");
    EXPECT_EQ(g["index"].asUInt(), std::uint32_t(k));
    EXPECT_FALSE(g.isMember("voxel")) << "a point set has input indices, no voxels";
    EXPECT_EQ(g["id"].asUInt(), std::uint32_t(k));
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(g["position"][c].asDouble(), double(f.positions[3 * std::size_t(k) + std::size_t(c)]));
    // Exactly the float components written, as a symmetric matrix.
    std::array<float, 6> t;
    std::copy_n(&f.tensors[6 * std::size_t(k)], 6, t.begin());
    const int idx[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) EXPECT_EQ(g["tensor"][a][b].asDouble(), double(t[std::size_t(idx[a][b])]));
    expectConsistent(g, t);
    EXPECT_EQ(g["sign"].asString(), signs[k]);
    EXPECT_EQ(g["glyph_group"].asString(), groups[k]);
    // The reference's point on the same pixel centre: the GPU intersects in
    // float (relative error ~1e-6 of the 40-unit eye distance); 1e-3 is
    // still 1/300 of the thinnest glyph's semi-axis.
    const auto [i, j] = pixels[std::size_t(k)];
    const std::size_t px = std::size_t(j) * kW + std::size_t(i);
    ASSERT_EQ(ref.id[px], std::uint32_t(k));
    EXPECT_NEAR(g["depth"].asDouble(), ref.depth[px], 1e-3);
    const tg::render::RayWC ray = cam.rayThroughPixel(i + 0.5, j + 0.5);
    const glm::dvec3 expected = ray.origin + ref.depth[px] * ray.direction;
    EXPECT_LT(glm::length(vec3(g["surface"]) - expected), 1e-3);
  }
  const Json::Value& bg = picks.back();
  EXPECT_EQ(bg["hit"].asString(), "background");
  EXPECT_FALSE(bg.isMember("index") || bg.isMember("surface") || bg.isMember("id"));
}

// Beside each glyph's silhouette, per the reference at 4 x 4 subpixels: a
// pixel whose centre is outside reports the background and its neighbour
// whose centre is inside reports the glyph. (Pixels whose centre lies within
// 1/8 pixel of the silhouette are left out: their side is a rounding away.)
TEST(Pick, PixelsJustOutsideASilhouetteAreBackground) {
  const Field f = synthetic();
  const fs::path in = writeField(f);
  const tg::tensor::GlyphSet set = tg::tensor::buildGlyphs(f.positions, f.tensors, f.ids);
  const SafeIds safe{tg::ref::renderEllipsoids(camera(set, kSub * kW, kSub * kH), set.glyphs, tg::ref::RefParams(1.0))};
  std::vector<std::array<int, 2>> pixels;
  std::vector<std::uint32_t> expected;
  std::vector<bool> found(9, false);
  for (int j = 1; j + 1 < kH; ++j)
    for (int i = 1; i + 1 < kW; ++i) {
      const auto out = safe.at(i, j);
      if (!out || *out != tg::ref::kNoGlyph) continue;
      for (const auto [di, dj] : {std::array<int, 2>{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const auto inside = safe.at(i + di, j + dj);
        if (!inside || *inside == tg::ref::kNoGlyph || found[*inside]) continue;
        found[*inside] = true;
        pixels.push_back({i, j});
        expected.push_back(tg::ref::kNoGlyph);
        pixels.push_back({i + di, j + dj});
        expected.push_back(*inside);
        break;
      }
    }
  ASSERT_EQ(pixels.size(), 18u) << "a pair for every glyph";
  const fs::path out = dir() / "edges.png";
  const CmdResult r = tg::test::runBinary(
      "render " + in.string() + " -o " + out.string() + " " + cameraFlags() + pickFlags(pixels), dir());
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<Json::Value> picks = parseLines(r.out);
  ASSERT_EQ(picks.size(), pixels.size());
  for (std::size_t k = 0; k < picks.size(); ++k) {
    SCOPED_TRACE("pixel " + std::to_string(pixels[k][0]) + " " + std::to_string(pixels[k][1]));
    if (expected[k] == tg::ref::kNoGlyph) {
      EXPECT_EQ(picks[k]["hit"].asString(), "background");
    } else {
      EXPECT_EQ(picks[k]["hit"].asString(), "glyph");
      EXPECT_EQ(picks[k]["index"].asUInt(), expected[k]);
    }
  }
}

// A pixel outside the image, a negative or malformed coordinate, or a
// missing one: a usage error (exit 2), checked before the input is read (a
// missing file would be exit 1) and before anything is drawn or printed.
TEST(Pick, BadPixelsAreUsageErrors) {
  const fs::path in = writeField(synthetic());
  const fs::path out = dir() / "bad.png";
  const std::string base = "render " + in.string() + " -o " + out.string() + " " + cameraFlags();
  const std::string missing =
      "render " + (dir() / "no-such.vtp").string() + " -o " + out.string() + " " + cameraFlags();
  const std::pair<std::string, std::string> cases[] = {
      {base + " --pick 160 0", "outside the 160 x 120 image"},
      {base + " --pick 0 120", "outside the 160 x 120 image"},
      {base + " --pick 3 4 --pick 5 999", "(5, 999)"},
      {base + " --pick -1 0", "--pick"},
      {base + " --pick 2x 3", "--pick"},
      {base + " --pick 4", "--pick"},
      {missing + " --pick 170 0", "outside"},
  };
  for (const auto& [args, what] : cases) {
    tg::test::expectFailsCleanly(args, what, out, dir(), 1);
    const CmdResult r = tg::test::runBinary(args, dir());
    EXPECT_EQ(r.code, 2) << args << " -> " << r.err;
    EXPECT_TRUE(r.out.empty()) << args;
  }
}

// Kindlmann's helix (NRRD, 7 floats a voxel: confidence, then Dxx Dxy Dxz
// Dyy Dyz Dzz): every glyph picked across the middle row of the default
// view carries exactly the file's tensor for its input index (the voxel),
// read here by Teem.
TEST(Pick, RealHelixTensorsMatchTheFile) {
  TG_REQUIRE_REAL_DATA();
  const std::string path = tg::test::realData("kindlmann-dt-helix/dt-helix.nhdr");
  std::vector<std::array<int, 2>> pixels;
  for (int i = 0; i < 320; i += 8) pixels.push_back({i, 120});
  const fs::path out = dir() / "helix.png";
  const CmdResult r =
      tg::test::runBinary("render " + path + " -o " + out.string() + " --size 320 240" + pickFlags(pixels), dir());
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<Json::Value> picks = parseLines(r.out);
  ASSERT_EQ(picks.size(), pixels.size());
  Nrrd* nin = nrrdNew();
  ASSERT_EQ(nrrdLoad(nin, path.c_str(), nullptr), 0);
  const std::unique_ptr<Nrrd, Nrrd* (*)(Nrrd*)> owner(nin, nrrdNuke);
  ASSERT_EQ(nin->type, nrrdTypeFloat);
  ASSERT_EQ(nin->dim, 4u);
  const auto* data = static_cast<const float*>(nin->data);
  const std::size_t voxels = nin->axis[1].size * nin->axis[2].size * nin->axis[3].size;
  int glyphs = 0;
  for (const Json::Value& p : picks) {
    if (p["hit"].asString() != "glyph") continue;
    ++glyphs;
    const std::size_t v = p["index"].asUInt();
    ASSERT_LT(v, voxels);
    // The voxel the index names on the file's 38 x 39 x 40 grid, i fastest.
    ASSERT_EQ(p["voxel"].size(), 3u);
    const std::size_t X = nin->axis[1].size, Y = nin->axis[2].size;
    const std::size_t i = p["voxel"][0].asUInt(), j = p["voxel"][1].asUInt(), k = p["voxel"][2].asUInt();
    EXPECT_TRUE(i < X && j < Y && k < nin->axis[3].size) << p["voxel"];
    EXPECT_EQ(i + X * (j + Y * k), v) << p["voxel"];
    const float* t = data + 7 * v + 1;
    const int idx[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) EXPECT_EQ(p["tensor"][a][b].asDouble(), double(t[idx[a][b]])) << "voxel " << v;
    expectConsistent(p, {t[0], t[1], t[2], t[3], t[4], t[5]});
  }
  EXPECT_GE(glyphs, 5) << "the middle row crosses the helix";
}

// The viewer script's `pick I J` prints the same line as `render --pick` for
// the same view (the default framing at 320 x 240, as View.* compares
// screenshots); a script pick outside the window fails before the window
// opens, naming the script's line. Needs an X display (run under Xvfb by
// ctest's PickView.ScriptUnderXvfb).
TEST(PickView, ScriptPicksMatchRender) {
  if (!std::getenv("DISPLAY")) {
    if (std::getenv("TG_REQUIRE_DISPLAY")) ADD_FAILURE() << "TG_REQUIRE_DISPLAY is set but DISPLAY is not";
    GTEST_SKIP() << "no X display";
  }
  const fs::path in = writeField(synthetic());
  const std::vector<std::array<int, 2>> pixels = {{160, 120}, {0, 0}, {100, 90}, {210, 150}, {130, 60}};
  const fs::path script = dir() / "pick.txt";
  {
    std::ofstream s(script);
    for (const auto& p : pixels) s << "pick " << p[0] << " " << p[1] << "\n";
  }
  const std::string flags = " --size 320 240 --no-legend";
  const CmdResult v = tg::test::runBinary("view " + in.string() + flags + " --script " + script.string(), dir());
  ASSERT_EQ(v.code, 0) << v.err;
  const CmdResult r = tg::test::runBinary(
      "render " + in.string() + flags + " -o " + (dir() / "same.png").string() + pickFlags(pixels), dir());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(v.out, r.out);
  const std::vector<Json::Value> picks = parseLines(v.out);
  ASSERT_EQ(picks.size(), pixels.size());
  EXPECT_EQ(picks[0]["hit"].asString(), "glyph") << "the middle of the default view";
  {
    std::ofstream s(script);
    s << "orbit 10 0\npick 320 5\n";
  }
  const CmdResult bad = tg::test::runBinary("view " + in.string() + flags + " --script " + script.string(), dir());
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find(script.string() + ":2: pick"), std::string::npos) << bad.err;
  EXPECT_TRUE(bad.out.empty());
}

// A box's corner and a cylinder's rim reach sqrt(3) and sqrt(2) semi-axes
// from the centre; the depth range must hold them, or the near plane cuts
// the glyph nearest the eye and the pick finds its far wall. One glyph with
// eigenvalues 1, 0.95, 0.9, turned 45 degrees about y so that an edge of the
// box faces the eye: on the central ray both the box's edge and the
// cylinder's rim lie 0.9 sqrt(2) = 1.2728 in front of the centre, beyond
// the largest semi-axis (1) where the near plane used to be.
TEST(Pick, BoxesAndCylindersNearTheEyeAreWhole) {
  Field f;
  f.positions = {0, 0, 0};
  f.tensors = {0.95f, 0.0f, -0.05f, 0.95f, 0.0f, 0.95f};
  f.ids = {0};
  const fs::path path = writeField(f);
  const double s = std::sqrt(0.5);
  for (const auto& [kind, front] : {std::pair{"box", 1.8 * s}, std::pair{"cylinder", 0.9 * std::sqrt(2.0)}}) {
    const auto r = tg::test::runBinary("render " + path.string() + " -o " + (dir() / "near.png").string() + " --glyph " + kind +
                                 " --scale-mode absolute --scale 2 --size 65 65 --eye 0 0 10 --look-at 0 0 0 --ortho 3 --pick 32 32",
                             dir());
    ASSERT_EQ(r.code, 0) << r.err;
    const auto picks = parseLines(r.out);
    ASSERT_EQ(picks.size(), 1u);
    EXPECT_EQ(picks[0]["hit"].asString(), "glyph") << kind;
    EXPECT_NEAR(picks[0]["depth"].asDouble(), 10.0 - front, 1e-3) << kind;
  }
}
