// What the ParaView plugin's tests share (test_paraview_plugin.cpp,
// test_paraview_blocks.cpp): pvbatch runs of plugins/paraview/tests/
// render_glyphs.py, pictures and the CLI's id channel read back, and the
// glyphs a selection test aims at.
#pragma once
#include <gtest/gtest.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <set>
#include <string>
#include <vector>

#include "cli/cli_run.h"
#include "real_data.h"

namespace tg::test::pv {

using tg::test::CmdResult;
namespace fs = std::filesystem;

inline const std::string kKitten = tg::test::realData("tsv-kitten-stress/kitten-stress.vtu");
// The kitten as pvbatch reads it: a legacy copy made once per test process
// by Debian's VTK (tests/paraview/legacy_copy.py), since ParaView 5.11's own
// VTK cannot read its appended XML data under Debian 12's current libexpat1.
// The CLI reads kKitten itself; the arrays are the same.
inline const std::string& pvKitten() {
  struct Copy {
    fs::path path = fs::temp_directory_path() / ("tg_pv_kitten_" + std::to_string(::getpid()) + ".vtk");
    std::string name;
    Copy() {
      const std::string cmd = std::string(TG_PYTHON3) + " " + TG_PARAVIEW_LEGACY_COPY + " " + kKitten + " " + path.string();
      // A failed copy names itself, so that pvbatch's error says why.
      name = std::system(cmd.c_str()) == 0 && fs::exists(path) ? path.string() : "legacy_copy.py-failed-for-" + kKitten;
    }
    ~Copy() {
      std::error_code ec;
      fs::remove(path, ec);
    }
  };
  static const Copy copy;
  return copy.name;
}
// A view of the whole kitten from above its right shoulder.
inline const std::string kCamera = "--size 400 300 --eye 40 70 170 --look-at -1.5 41.8 5.6 --up 0 1 0 --fov 30";
// The plugin's own defaults, stated to the CLI, which gives a stress field
// (the kitten) its stress defaults instead (app/stress_defaults.h); the
// plugin does not choose those. render_glyphs.py shows the glyphs with
// ColorBy None (Solid Color), so that they show TensorGlyphColorMode's
// colours (ParaView colours a new display by the active point scalars, the
// kitten's "fixed", which the glyphs would follow).
inline const std::string kPluginLook = " --glyph ellipsoid --color dec --magnitude linear";

struct Image {
  int width = 0, height = 0, channels = 0;
  std::vector<float> px;
  const float* at(int i) const { return &px[std::size_t(i) * channels]; }
};

inline Image readImage(const fs::path& p) {
  Image img;
  auto in = OIIO::ImageInput::open(p.string());
  if (!in) return img;
  const OIIO::ImageSpec& s = in->spec();
  img.width = s.width;
  img.height = s.height;
  img.channels = s.nchannels;
  img.px.resize(std::size_t(s.width) * s.height * s.nchannels);
  if (!in->read_image(0, 0, 0, s.nchannels, OIIO::TypeDesc::FLOAT, img.px.data())) img = {};
  return img;
}

// The CLI's EXR "id" channel (uint32: each pixel's glyph input index, or
// kNoGlyph), rows top to bottom.
inline constexpr std::uint32_t kNoGlyph = 0xFFFFFFFFu;
inline std::vector<std::uint32_t> readIds(const fs::path& p, const Image& img) {
  std::vector<std::uint32_t> ids;
  auto in = OIIO::ImageInput::open(p.string());
  if (!in) return ids;
  const auto& names = in->spec().channelnames;
  const auto it = std::find(names.begin(), names.end(), "id");
  if (it == names.end()) return ids;
  const int ch = int(it - names.begin());
  ids.resize(std::size_t(img.width) * img.height);
  if (!in->read_image(0, 0, ch, ch + 1, OIIO::TypeDesc::UINT32, ids.data())) ids.clear();
  return ids;
}

inline std::string skipReason() {
  const std::string plugin = TG_PARAVIEW_PLUGIN;
  if (plugin.empty()) return "the ParaView plugin is not built (paraview-dev not found)";
  if (!fs::exists(plugin)) return "the ParaView plugin is not built: " + plugin;
  if (std::system("command -v pvbatch >/dev/null 2>&1") != 0) return "pvbatch is not installed";
  if (!fs::exists(fs::path(TG_PARAVIEW_PYTHONPATH) / "paraview" / "simple.py"))
    return std::string("ParaView's Python modules are not in ") + TG_PARAVIEW_PYTHONPATH;
  if (!fs::exists(kKitten)) return "the published kitten dataset is absent: " + kKitten;
  return "";
}

#define TG_SKIP_WITHOUT_PARAVIEW()                          \
  do {                                                      \
    if (const std::string why = skipReason(); !why.empty()) \
      GTEST_SKIP() << why;                                  \
  } while (0)

// pvbatch (under mpiexec with `ranks` > 0) running the plugin's driver
// script. Two faults outside the plugin are tried again, each run on a
// server of its own (xvfb-run -a), so that a shared display in a bad state
// cannot fail the test, and a display never given cannot pass it:
// - a rank fails to open its window or loses its server ("bad X server
//   connection"): seen with two suites on one machine, and in CI on the one
//   shared Xvfb;
// - a run under mpiexec hangs: rank 0 in IceT's MPI_Comm_dup
//   (vtkIceTContext::SetController, the first composited render), the other
//   ranks waiting for the next RMI. Four-rank runs alone hung in 2 of 12
//   tries, and in 1 of 9 with no glyphs shown at all (a slice only): ParaView
//   5.11's and Open MPI's, not the plugin's. A normal run takes 5-15 s, so
//   a run under mpiexec is stopped after 40 s (a serial one after 120 s)
//   and tried again, up to five tries in all (a serial run three): a hang
//   costs 40 s, not 120.
// timeout signals the whole group (xvfb-run, mpiexec, the ranks).
inline CmdResult runPvbatch(const std::string& args, const fs::path& scratch, int ranks = 0) {
  // Under a display ctest was given (.ci/run's one Xvfb) the first try
  // starts no server.
  const int limitS = ranks > 0 ? 40 : 120, retries = ranks > 0 ? 4 : 2;
  const auto launcher = [ranks, limitS](bool ownServer) {
    std::string l = "timeout -k 10 " + std::to_string(limitS) + " env PYTHONPATH=" + TG_PARAVIEW_PYTHONPATH +
                    (ownServer ? " xvfb-run -a -s '-screen 0 640x480x24' " : " ");
    if (ranks > 0) l += "mpiexec --allow-run-as-root --oversubscribe -n " + std::to_string(ranks) + " ";
    l += "pvbatch " TG_PARAVIEW_SCRIPT " --plugin " TG_PARAVIEW_PLUGIN " --input " + pvKitten();
    return l;
  };
  const auto raced = [](const CmdResult& c) {
    return c.code != 0 && (c.err.find("CreateAWindow") != std::string::npos ||
                           c.err.find("bad X server connection") != std::string::npos || c.code == 124);
  };
  CmdResult r = tg::test::runBinary(args, scratch, launcher(std::getenv("DISPLAY") == nullptr));
  for (int retry = 0; retry < retries && raced(r); ++retry) r = tg::test::runBinary(args, scratch, launcher(true));
  return r;
}

// Pixels whose colour differs by more than `tol` (0..1) in a channel.
inline long differing(const Image& a, const Image& b, float tol) {
  long n = 0;
  for (int i = 0; i < a.width * a.height; ++i)
    for (int c = 0; c < 3; ++c)
      if (std::abs(a.at(i)[c] - b.at(i)[c]) > tol) {
        ++n;
        break;
      }
  return n;
}

inline bool covered(const Image& img, int i, const float bg[3]) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(img.at(i)[c] - bg[c]) > 1.5f / 255.0f) return true;
  return false;
}

inline const float kBackground[3] = {20 / 255.0f, 20 / 255.0f, 26 / 255.0f};  // the CLI's 0.08 0.08 0.10

class ParaViewPlugin : public ::testing::Test {
 protected:
  fs::path dir = tg::test::cliDir("paraview");
  void TearDown() override { fs::remove_all(dir); }
};

// A display rectangle (ParaView's: origin bottom left, corners inclusive).
struct Rect {
  int x0, y0, x1, y1;
  std::string args() const {
    return " --select " + std::to_string(x0) + " " + std::to_string(y0) + " " + std::to_string(x1) + " " +
           std::to_string(y1);
  }
};

// The glyph ids the CLI's id channel shows inside `r`.
inline std::set<std::uint32_t> idsIn(const std::vector<std::uint32_t>& ids, const Image& img, const Rect& r) {
  std::set<std::uint32_t> out;
  for (int y = r.y0; y <= r.y1; ++y)
    for (int x = r.x0; x <= r.x1; ++x) {
      const std::uint32_t id = ids[std::size_t(img.height - 1 - y) * img.width + x];
      if (id != kNoGlyph) out.insert(id);
    }
  return out;
}

// What a selection test aims at in the CLI's id channel (display
// coordinates): the first glyph (bottom up) that covers a 3 x 3 block alone,
// a glyph drawn far from it, and the glyphs shown in a 40 x 40 block at the
// centre. `target` is kNoGlyph when no glyph covers a 3 x 3 block.
struct Picks {
  std::size_t distinct = 0;  // glyphs in the picture
  std::uint32_t target = kNoGlyph, far = kNoGlyph;
  double farthest = 0;
  Rect inside{}, block{};
  std::set<std::uint32_t> shown;
};

inline Picks findPicks(const std::vector<std::uint32_t>& ids, const Image& img) {
  Picks p;
  const int w = img.width, h = img.height;
  auto idAt = [&](int x, int y) { return ids[std::size_t(h - 1 - y) * w + x]; };
  std::set<std::uint32_t> all(ids.begin(), ids.end());
  all.erase(kNoGlyph);
  p.distinct = all.size();
  auto solid = [&](const Rect& r, std::uint32_t id) {
    for (int y = r.y0; y <= r.y1; ++y)
      for (int x = r.x0; x <= r.x1; ++x)
        if (idAt(x, y) != id) return false;
    return true;
  };
  for (int y = 1; y < h - 1 && p.target == kNoGlyph; ++y)
    for (int x = 1; x < w - 1 && p.target == kNoGlyph; ++x) {
      const Rect r{x - 1, y - 1, x + 1, y + 1};
      if (idAt(x, y) != kNoGlyph && solid(r, idAt(x, y))) {
        p.target = idAt(x, y);
        p.inside = r;
      }
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double d = std::hypot(x - p.inside.x0, y - p.inside.y0);
      if (idAt(x, y) != kNoGlyph && d > p.farthest) {
        p.farthest = d;
        p.far = idAt(x, y);
      }
    }
  p.block = Rect{w / 2 - 20, h / 2 - 20, w / 2 + 19, h / 2 + 19};
  p.shown = idsIn(ids, img, p.block);
  return p;
}

// The colour maps of shaders/lib/color.glsl, read from the file the glyph
// shaders are built from: viridis's knots (linear in between) and the sign
// ramp's compression and tension ends (white at 0).
struct ShaderColormaps {
  std::vector<std::array<double, 3>> viridis;
  std::array<double, 3> tension{}, compression{};
};

inline ShaderColormaps readShaderColormaps() {
  ShaderColormaps maps;
  const fs::path glsl = fs::path(TG_PARAVIEW_SCRIPT).parent_path() / "../../../shaders/lib/color.glsl";
  std::ifstream f(glsl);
  std::stringstream text;
  text << f.rdbuf();
  const std::string src = text.str();
  const std::regex vec3(R"(vec3\(([-0-9.]+), ([-0-9.]+), ([-0-9.]+)\))");
  auto vecsIn = [&](const std::string& from, const std::string& to) {
    std::vector<std::array<double, 3>> out;
    const std::size_t a = src.find(from), b = src.find(to, a);
    if (a == std::string::npos || b == std::string::npos) return out;
    const std::string body = src.substr(a, b - a);
    for (auto m = std::sregex_iterator(body.begin(), body.end(), vec3); m != std::sregex_iterator(); ++m)
      out.push_back({std::stod((*m)[1]), std::stod((*m)[2]), std::stod((*m)[3])});
    return out;
  };
  maps.viridis = vecsIn("vec3 viridis(float t)", "float x");
  const auto sign = vecsIn("vec3 signRamp(float t)", "}");
  if (sign.size() == 2) {
    maps.tension = sign[0];
    maps.compression = sign[1];
  }
  return maps;
}

inline std::array<double, 3> shaderColor(const ShaderColormaps& m, bool sign, double t) {
  std::array<double, 3> c{};
  if (sign) {  // t in -1..1
    const auto& end = t >= 0 ? m.tension : m.compression;
    for (int k = 0; k < 3; ++k) c[k] = 1.0 + (end[k] - 1.0) * std::abs(t);
    return c;
  }
  const double x = std::clamp(t, 0.0, 1.0) * double(m.viridis.size() - 1);
  const std::size_t i = std::min(std::size_t(x), m.viridis.size() - 2);
  for (int k = 0; k < 3; ++k) c[k] = m.viridis[i][k] + (m.viridis[i + 1][k] - m.viridis[i][k]) * (x - double(i));
  return c;
}

}  // namespace tg::test::pv
