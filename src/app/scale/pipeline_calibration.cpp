#include "app/scale/pipeline_calibration.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <glm/mat3x3.hpp>

#include "app/scale/scale_sweep.h"
#include "data-synthetic/generators.h"
#include "io/field/atomic_file.h"
#include "render/glyph_path.h"
#include "render/renderer.h"

namespace tg::app {
namespace {

using Clock = std::chrono::steady_clock;

// The fastest of `frames` finished frames after a warm-up: the least
// disturbed by other work on the machine.
double fastestFrameMs(const gl::Api& gl, render::GlyphRenderer& r, const render::Camera& cam,
                      const render::FrameParams& p, const render::GBuffer& t, int frames) {
  r.render(cam, p, t);
  gl.Finish();
  double best = INFINITY;
  for (int k = 0; k < frames; ++k) {
    const auto t0 = Clock::now();
    r.render(cam, p, t);
    gl.Finish();
    best = std::min(best, std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
  }
  return best;
}

// Least squares over the terms in `use` (fixed, glyphs, pixels); false when
// singular. Units: ms, thousands of glyphs, megapixels.
bool fitTerms(const std::vector<double>& g, const std::vector<double>& px, const std::vector<double>& t,
              const bool use[3], double coef[3], double& residual) {
  glm::dmat3 ata(0.0);
  glm::dvec3 atb(0.0);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const glm::dvec3 row(use[0] ? 1.0 : 0.0, use[1] ? g[i] * 1e-3 : 0.0, use[2] ? px[i] * 1e-6 : 0.0);
    ata += glm::outerProduct(row, row);
    atb += row * t[i];
  }
  for (int k = 0; k < 3; ++k)
    if (!use[k]) ata[k][k] = 1.0;  // the unused term's coefficient solves to 0
  if (std::abs(glm::determinant(ata)) < 1e-12) return false;
  const glm::dvec3 x = glm::inverse(ata) * atb;
  residual = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double e = x[0] + x[1] * g[i] * 1e-3 + x[2] * px[i] * 1e-6 - t[i];
    residual += e * e;
  }
  for (int k = 0; k < 3; ++k) coef[k] = x[k];
  return true;
}

std::string readCache(const std::string& file) {
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0) return {};
  if (!S_ISREG(st.st_mode)) throw std::runtime_error(file + ": not a regular file");
  if (st.st_size > 64 * 1024) throw std::runtime_error(file + ": " + std::to_string(st.st_size) + " bytes, too large for a calibration cache");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file + ": cannot be read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

PathCost fitPathCost(const std::vector<double>& glyphs, const std::vector<double>& pixels,
                     const std::vector<double>& frameMs) {
  if (frameMs.size() < 3 || glyphs.size() != frameMs.size() || pixels.size() != frameMs.size())
    throw std::invalid_argument("fitPathCost: needs three frames or more, each with its glyphs and pixels");
  double best[3] = {0, 0, 0}, bestResidual = INFINITY;
  for (int mask = 1; mask < 8; ++mask) {
    const bool use[3] = {(mask & 1) != 0, (mask & 2) != 0, (mask & 4) != 0};
    double coef[3], residual;
    if (!fitTerms(glyphs, pixels, frameMs, use, coef, residual)) continue;
    if (coef[0] < 0.0 || coef[1] < 0.0 || coef[2] < 0.0) continue;
    if (residual < bestResidual) {
      bestResidual = residual;
      std::copy(coef, coef + 3, best);
    }
  }
  if (!std::isfinite(bestResidual)) throw std::invalid_argument("fitPathCost: no fit with non-negative costs");
  return {best[0], best[1], best[2]};
}

namespace {

constexpr double kCalibrationScale = 0.5;  // bench scale's: the largest glyph spans one grid spacing

tensor::GlyphSet calibrationSet(std::size_t n) {
  const io::TensorField f = synth::randomField(n, 7);
  return tensor::buildGlyphs(f.positions, f.tensors, f.ids);
}

}  // namespace

std::vector<std::size_t> calibrationGlyphs(const gl::Api& gl, const gl::ShaderLibrary& lib, const CalibrationPlan& plan) {
  std::vector<std::size_t> glyphs = plan.glyphs;
  if (glyphs.empty() || plan.sizes.empty() || !(plan.growUntilMs > 0)) return glyphs;
  constexpr std::size_t kGrowth = 8;
  const auto [w, h] = plan.sizes.back();
  for (;;) {
    const std::size_t n = *std::max_element(glyphs.begin(), glyphs.end());
    if (n * kGrowth > plan.maxGlyphs) return glyphs;
    const tensor::GlyphSet set = calibrationSet(n);
    render::GlyphRenderer r(gl, lib, {}, "raster");
    r.upload(set);
    render::GBuffer target(gl, w, h);
    render::FrameParams p;
    p.scale = kCalibrationScale;
    if (fastestFrameMs(gl, r, sweepCamera(set, kCalibrationScale, w, h), p, target, plan.frames) >= plan.growUntilMs)
      return glyphs;
    for (std::size_t& g : glyphs) g *= kGrowth;
  }
}

PathCalibration calibratePaths(const gl::Api& gl, const gl::ShaderLibrary& lib, const std::string& key,
                               const CalibrationPlan& plan) {
  PathCalibration cal{key, {}};
  std::map<std::size_t, tensor::GlyphSet> sets;
  for (const std::size_t n : plan.glyphs) sets[n] = calibrationSet(n);
  constexpr double kScale = kCalibrationScale;
  for (const std::string_view path : render::kGlyphPathNames)
    for (const CostClass cls : {CostClass::ClosedForm, CostClass::March}) {
      std::vector<double> g, px, t;
      for (const auto& [n, set] : sets) {
        render::GlyphRenderer r(gl, lib, {}, path);
        r.upload(set);
        for (const auto& [w, h] : plan.sizes) {
          const render::Camera cam = sweepCamera(set, kScale, w, h);
          render::GBuffer target(gl, w, h);
          render::FrameParams p;
          p.scale = kScale;
          p.glyph = cls == CostClass::March ? render::GlyphKind::Superquadric : render::GlyphKind::Ellipsoid;
          p.gamma = 3.0;
          g.push_back(double(n));
          px.push_back(double(w) * double(h));
          t.push_back(fastestFrameMs(gl, r, cam, p, target, plan.frames));
        }
      }
      cal.rows.push_back({std::string(path), cls, fitPathCost(g, px, t)});
    }
  return cal;
}

std::string currentCalibrationKey(const gl::Api& gl) {
  auto str = [&](GLenum e) {
    const auto* s = reinterpret_cast<const char*>(gl.GetString(e));
    return std::string(s ? s : "?");
  };
  const char* lpThreads = std::getenv("LP_NUM_THREADS");
  return calibrationKey(str(GL_RENDERER), str(GL_VERSION), std::thread::hardware_concurrency(), lpThreads ? lpThreads : "");
}

std::string calibrationCachePath() {
  auto env = [](const char* name) {
    const char* v = std::getenv(name);
    return std::string(v ? v : "");
  };
  if (!env("TG_CACHE_DIR").empty()) return env("TG_CACHE_DIR") + "/pipelines.tsv";
  // The XDG base directory rules: a relative path is to be ignored.
  if (env("XDG_CACHE_HOME").rfind('/', 0) == 0) return env("XDG_CACHE_HOME") + "/tensorglyph/pipelines.tsv";
  if (!env("HOME").empty()) return env("HOME") + "/.cache/tensorglyph/pipelines.tsv";
  return {};
}

bool calibrationComplete(const PathCalibration& cal) {
  for (const std::string_view path : render::kGlyphPathNames)
    for (const CostClass c : {CostClass::ClosedForm, CostClass::March})
      if (!cal.cost(path, c)) return false;
  return true;
}

namespace {

// An exclusive lock on FILE.lock while it is held; none (and no wait) where
// the directory cannot hold one.
class CacheLock {
 public:
  explicit CacheLock(const std::string& file) {
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(file).parent_path(), ec);
    fd_ = ::open((file + ".lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd_ < 0) return;
    // Another run measuring takes about 2 s; a stuck one is not waited for.
    for (int k = 0; k < 600; ++k) {
      if (::flock(fd_, LOCK_EX | LOCK_NB) == 0) return;
      ::usleep(100000);
    }
    ::close(fd_);
    fd_ = -1;
  }
  ~CacheLock() {
    if (fd_ >= 0) ::close(fd_);  // releases the lock
  }
  CacheLock(const CacheLock&) = delete;
  CacheLock& operator=(const CacheLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace

CachedCalibration calibrationFor(const gl::Api& gl, const gl::ShaderLibrary& lib, const std::string& key) {
  CachedCalibration out;
  out.file = calibrationCachePath();
  std::optional<CacheLock> lock;
  if (!out.file.empty()) lock.emplace(out.file);
  std::vector<PathCalibration> kept;
  std::string problem;
  if (!out.file.empty()) {
    try {
      const std::string text = readCache(out.file);
      if (!text.empty()) kept = parseCalibrations(text, out.file);
    } catch (const std::exception& e) {
      problem = e.what();
      kept.clear();
    }
    for (const PathCalibration& c : kept)
      if (c.key == key) {
        if (calibrationComplete(c)) {
          out.cal = c;
          return out;
        }
        problem = out.file + ": this renderer's rows are incomplete";
      }
  }
  const auto t0 = Clock::now();
  CalibrationPlan plan;
  plan.glyphs = calibrationGlyphs(gl, lib, plan);
  out.cal = calibratePaths(gl, lib, key, plan);
  out.measured = true;
  out.measuredMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  char took[128];
  std::snprintf(took, sizeof took, "measured the glyph paths on this renderer in %.1f s (%zu and %zu glyphs)",
                out.measuredMs * 1e-3, plan.glyphs.front(), plan.glyphs.back());
  const std::string why = problem.empty() ? "" : problem + "; ";
  if (out.file.empty()) {
    out.said = std::string(took) + ", for this run only: no cache directory (TG_CACHE_DIR, XDG_CACHE_HOME and HOME unset or empty)";
    return out;
  }
  std::erase_if(kept, [&](const PathCalibration& c) { return c.key == key; });
  kept.push_back(out.cal);
  try {
    io::AtomicFile f(out.file);
    const std::string text = formatCalibrations(kept);
    f.write(text.data(), text.size());
    f.commit(std::int64_t(text.size()));
    out.said = why + took + ", kept in " + out.file;
  } catch (const std::exception& e) {
    out.said = why + took + ", not kept: " + e.what();
    out.file.clear();
  }
  return out;
}

}  // namespace tg::app
