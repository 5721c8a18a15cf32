// The viewer (`tensorglyph view`), driven by a script. Needs an X display:
// ctest runs the View.* tests under Xvfb with Mesa (tests/CMakeLists.txt);
// without a display they skip, unless TG_REQUIRE_DISPLAY makes that a failure.
#include <OpenImageIO/imageio.h>

#include <cstdlib>
#include <fstream>
#include <vector>

#include "cli/cli_run.h"
#include "real_data.h"

namespace {

using tg::test::runBinary;

std::vector<unsigned char> readRgba(const std::filesystem::path& p, int& w, int& h) {
  auto in = OIIO::ImageInput::open(p.string());
  if (!in) return {};
  w = in->spec().width;
  h = in->spec().height;
  std::vector<unsigned char> px(std::size_t(w) * h * 4);
  in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, px.data());
  return px;
}

// Pixels that are not the background (the first pixel, a corner no glyph reaches).
std::size_t covered(const std::vector<unsigned char>& px) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < px.size(); i += 4)
    n += px[i] != px[0] || px[i + 1] != px[1] || px[i + 2] != px[2];
  return n;
}

std::size_t differing(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i + 3 < a.size() && i + 3 < b.size(); i += 4)
    n += a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2];
  return n + (a.size() != b.size() ? 1 : 0);
}

bool haveDisplay() {
  if (std::getenv("DISPLAY")) return true;
  if (std::getenv("TG_REQUIRE_DISPLAY")) ADD_FAILURE() << "TG_REQUIRE_DISPLAY is set but DISPLAY is not";
  return false;
}

}  // namespace

TEST(View, ScriptedScreenshotsMatchTheHeadlessRenderer) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display";
  const auto dir = tg::test::cliDir("view");
  const auto shot = [&](int k) {
    std::string name = std::to_string(k);  // not "s" + ...: GCC 12 warns falsely (-Wrestrict)
    name.insert(0, 1, 's');
    return dir / (name + ".png");
  };
  {
    std::ofstream s(dir / "script.txt");
    s << "# the built-in scene at 320x240\n"
      << "screenshot " << shot(0).string() << "\n"
      << "fa-min 0.5\nglyph superquadric\ngamma 0\ncolor fa\n"
      << "screenshot " << shot(1).string() << "\n"
      << "orbit 90 20\nzoom 1.3\n"
      << "screenshot " << shot(2).string() << "\n"
      << "reset\nfa-min 0.25\nglyph ellipsoid\ngamma 3\ncolor dec  # back to the start\n"
      << "screenshot " << shot(3).string() << "\n"
      << "slab k:10:2\n"
      << "screenshot " << shot(4).string() << "\n";
  }
  // The built-in scene without its look (superquadrics, depth cues, legend),
  // so that the script's "glyph ellipsoid" restores the first view.
  const std::string plain = " --glyph ellipsoid --no-shadows --no-ao --no-outlines --no-legend";
  const auto r = runBinary("view --size 320 240" + plain + " --script " + (dir / "script.txt").string(), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("parameter changes, CPU time per change"), std::string::npos) << r.err;
  ASSERT_EQ(runBinary("render --size 320 240" + plain + " -o " + (dir / "r0.png").string(), dir).code, 0);
  // The second view's glyph replaces the first's: an option is given once.
  const std::string plainSuperquadric = " --glyph superquadric" + plain.substr(plain.find(" --no-shadows"));
  ASSERT_EQ(runBinary("render --size 320 240" + plainSuperquadric + " --fa-min 0.5 --gamma 0 --color fa -o " +
                          (dir / "r1.png").string(), dir).code, 0);
  int w = 0, h = 0;
  std::vector<std::vector<unsigned char>> s;
  for (int k = 0; k < 5; ++k) {
    s.push_back(readRgba(shot(k), w, h));
    ASSERT_EQ(w, 320) << k;
    ASSERT_EQ(h, 240) << k;
  }
  const auto r0 = readRgba(dir / "r0.png", w, h), r1 = readRgba(dir / "r1.png", w, h);
  // Exact: the screenshot is read from the same offscreen target that
  // `render` reads, drawn by the same driver (Mesa llvmpipe); the window
  // only displays a copy.
  EXPECT_EQ(differing(s[0], r0), 0u);
  EXPECT_EQ(differing(s[1], r1), 0u);
  EXPECT_EQ(differing(s[3], s[0]), 0u) << "reset and the restored parameters give the first view back";
  const std::size_t c0 = covered(s[0]);
  EXPECT_GT(c0, 3000u);
  EXPECT_GT(differing(s[2], s[0]), c0 / 2) << "orbit and zoom move the view";
  EXPECT_GT(covered(s[2]), c0 / 2);
  EXPECT_LT(covered(s[4]), c0 / 2) << "the slab hides most glyphs";
  EXPECT_GT(covered(s[4]), 50u);
  std::filesystem::remove_all(dir);
}

// With a legend and no camera flags, the viewer's first view leaves the
// legend the room render leaves it (render/legend/legend_room.h): the same image.
TEST(View, LeavesTheLegendTheRoomRenderLeaves) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display";
  const auto dir = tg::test::cliDir("view_legend");
  const std::string shot = (dir / "v.png").string();
  std::ofstream(dir / "script.txt") << "screenshot " << shot << "\n";
  const std::string flags = " --size 640 480 --no-shadows --no-ao --legend";
  const auto v = runBinary("view" + flags + " --script " + (dir / "script.txt").string(), dir);
  ASSERT_EQ(v.code, 0) << v.err;
  ASSERT_EQ(runBinary("render" + flags + " -o " + (dir / "r.png").string(), dir).code, 0);
  ASSERT_EQ(runBinary("render" + flags + " --legend-corner top-left -o " + (dir / "tl.png").string(), dir).code, 0);
  int w = 0, h = 0;
  const auto s = readRgba(shot, w, h), r = readRgba(dir / "r.png", w, h), tl = readRgba(dir / "tl.png", w, h);
  ASSERT_EQ(w, 640);
  EXPECT_EQ(differing(s, r), 0u);
  EXPECT_GT(differing(s, tl), 10000u);  // the camera follows the legend's corner
  std::filesystem::remove_all(dir);
}

// The viewer takes render's camera, background and march flags from the same
// option table (app/render_options.h): a screenshot before any step is the
// image render draws with those flags, exactly.
TEST(View, TakesRendersCameraAndLookFlags) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display";
  const auto dir = tg::test::cliDir("view_flags");
  const std::string shot = (dir / "v.png").string();
  std::ofstream(dir / "script.txt") << "screenshot " << shot << "\n";
  const std::string flags = " --size 320 240 --glyph superquadric --gamma 2 --no-shadows --no-ao --no-outlines"
                            " --no-legend --eye 6 -4 5 --look-at 0.5 0 0 --up 0 0 1 --fov 40"
                            " --background 0.2 0.3 0.4 1 --iterations 6 --color fa --fa-min 0.1";
  const auto v = runBinary("view" + flags + " --script " + (dir / "script.txt").string(), dir);
  ASSERT_EQ(v.code, 0) << v.err;
  ASSERT_EQ(runBinary("render" + flags + " -o " + (dir / "r.png").string(), dir).code, 0);
  int w = 0, h = 0;
  const auto s = readRgba(shot, w, h), r = readRgba(dir / "r.png", w, h);
  ASSERT_EQ(w, 320);
  EXPECT_EQ(differing(s, r), 0u);
  // The flags did act: the background is the one asked for, and the camera
  // is not the default one.
  EXPECT_EQ(int(s[0]), 51);
  EXPECT_EQ(int(s[2]), 102);
  std::ofstream(dir / "script2.txt") << "screenshot " << (dir / "d.png").string() << "\n";
  const std::string plain = " --size 320 240 --glyph superquadric --gamma 2 --no-shadows --no-ao --no-outlines"
                            " --no-legend --background 0.2 0.3 0.4 1 --iterations 6 --color fa --fa-min 0.1";
  ASSERT_EQ(runBinary("view" + plain + " --script " + (dir / "script2.txt").string(), dir).code, 0);
  EXPECT_GT(differing(readRgba(dir / "d.png", w, h), s), 1000u);
  // render's own options have no meaning in a window and are refused.
  EXPECT_EQ(runBinary("view --repeat 3", dir).code, 2);
  EXPECT_EQ(runBinary("view --size 32 32", dir).code, 2);
  std::filesystem::remove_all(dir);
}

// Slice planes in the viewer take render's flags; `plane N` steps hide and
// move them. A moved plane is exactly the plane render draws at that index
// (same offscreen target and driver), and putting everything back restores
// the first view.
TEST(View, ScriptedSlicePlanesMatchTheHeadlessRenderer) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display";
  const auto dir = tg::test::cliDir("view-planes");
  const auto shot = [&](int k) { return dir / ("plane-shot" + std::to_string(k).append(".png")); };
  {
    std::ofstream s(dir / "script.txt");
    s << "screenshot " << shot(0).string() << "\n"
      << "plane 1 index 3\n"
      << "screenshot " << shot(1).string() << "\n"
      << "plane 1 off\nplane 2 off\n"
      << "screenshot " << shot(2).string() << "\n"
      << "plane 2 on\nplane 1 on\nplane 1 index 10\n"
      << "screenshot " << shot(3).string() << "\n";
  }
  const std::string plain = " --size 320 240 --glyph ellipsoid --no-shadows --no-ao --no-outlines --no-legend";
  const auto r = runBinary("view" + plain + " --plane z:10 --plane x:20 --script " + (dir / "script.txt").string(), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(runBinary("render" + plain + " --plane z:10 --plane x:20 -o " + (dir / "r0.png").string(), dir).code, 0);
  ASSERT_EQ(runBinary("render" + plain + " --plane z:3 --plane x:20 -o " + (dir / "r1.png").string(), dir).code, 0);
  int w = 0, h = 0;
  std::vector<std::vector<unsigned char>> s;
  for (int k = 0; k < 4; ++k) {
    s.push_back(readRgba(shot(k), w, h));
    ASSERT_EQ(w, 320) << k;
  }
  const auto r0 = readRgba(dir / "r0.png", w, h), r1 = readRgba(dir / "r1.png", w, h);
  EXPECT_EQ(differing(s[0], r0), 0u);
  EXPECT_EQ(differing(s[1], r1), 0u) << "the moved plane is render's plane at that index";
  EXPECT_GT(differing(s[1], s[0]), 500u) << "moving the plane changes the view";
  EXPECT_EQ(differing(s[3], s[0]), 0u) << "on again at the first index gives the first view back";
  EXPECT_LT(covered(s[2]) + 5000, covered(s[0])) << "hidden planes leave the background";
  EXPECT_GT(covered(s[2]), 3000u) << "the glyphs stay";
  std::filesystem::remove_all(dir);
}

// The viewer builds its scene as render does (app/render_session.h): the
// same default size, and the underlay's warnings measured against the same
// box. The plane at x index 0 lies within the glyphs' box but beside their
// centres, which the viewer used to measure against, warning where render
// did not.
TEST(View, BuildsTheSceneRenderBuilds) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display";
  TG_REQUIRE_REAL_DATA();
  const auto dir = tg::test::cliDir("view-scene");
  {
    std::ofstream s(dir / "script.txt");
    s << "screenshot " << (dir / "v.png").string() << "\n";
  }
  const std::string field = tg::test::realData("kindlmann-dt-helix/dt-helix.nhdr");
  const std::string flags = " " + field + " --underlay fa --plane x:0 --glyph ellipsoid --no-shadows --no-ao --no-legend";
  const auto v = runBinary("view" + flags + " --script " + (dir / "script.txt").string(), dir);
  ASSERT_EQ(v.code, 0) << v.err;
  const auto r = runBinary("render" + flags + " -o " + (dir / "r.png").string(), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto warnings = [](const std::string& err, const std::string& command) {
    std::string lines;
    std::size_t at = 0;
    while ((at = err.find("tensorglyph " + command + ": --underlay", at)) != std::string::npos) {
      const std::size_t end = err.find('\n', at);
      lines += err.substr(at + command.size(), end - at - command.size()) + "\n";
      at = end;
    }
    return lines;
  };
  EXPECT_EQ(warnings(v.err, "view"), warnings(r.err, "render"));
  int vw = 0, vh = 0, rw = 0, rh = 0;
  const auto vs = readRgba(dir / "v.png", vw, vh), rs = readRgba(dir / "r.png", rw, rh);
  EXPECT_EQ(vw, rw);
  EXPECT_EQ(vh, rh);
  EXPECT_EQ(differing(vs, rs), 0u) << "the same scene, camera and defaults";
  std::filesystem::remove_all(dir);
}

// A mesh toggled and switched by the script: each screenshot is the headless
// render with the same mesh flags, pixel for pixel.
TEST(View, ScriptTogglesAMeshAsRenderDrawsIt) {
  if (!haveDisplay()) GTEST_SKIP() << "no X display";
  TG_REQUIRE_REAL_DATA();
  const auto dir = tg::test::cliDir("view_mesh");
  const std::string field = std::string(TG_REAL_DATA_DIR) + "/tsv-kitten-stress/kitten-stress.vtu";
  {
    std::ofstream s(dir / "script.txt");
    s << "screenshot " << (dir / "s0.png").string() << "\nmesh 1 see-through\n"
      << "screenshot " << (dir / "s1.png").string() << "\nmesh 1 off\n"
      << "screenshot " << (dir / "s2.png").string() << "\n";
  }
  const std::string common = " --size 320 240 " + field + " --mesh-from-input";
  const auto r = runBinary("view" + common + " --script " + (dir / "script.txt").string(), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(runBinary("render" + common + " -o " + (dir / "r0.png").string(), dir).code, 0);
  ASSERT_EQ(runBinary("render" + common + " --mesh-mode see-through -o " + (dir / "r1.png").string(), dir).code, 0);
  ASSERT_EQ(runBinary("render --size 320 240 " + field + " -o " + (dir / "r2.png").string(), dir).code, 0);
  int w = 0, h = 0;
  const char* shots[3] = {"s0.png", "s1.png", "s2.png"};
  const char* renders[3] = {"r0.png", "r1.png", "r2.png"};
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(differing(readRgba(dir / shots[k], w, h), readRgba(dir / renders[k], w, h)), 0u) << k;
  EXPECT_GT(differing(readRgba(dir / "r0.png", w, h), readRgba(dir / "r1.png", w, h)), 5000u);
  std::filesystem::remove_all(dir);
}

// Without a display the one line says what to do instead, and the exit is 1.
TEST(View, WithoutADisplaySaysWhatToRunInstead) {
  const auto dir = tg::test::cliDir("view_nodisplay");
  const tg::test::CmdResult r = runBinary("view", dir, "env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(TG_BINARY));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("DISPLAY"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("xvfb-run -a tensorglyph view"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("tensorglyph render"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  std::filesystem::remove_all(dir);
}
