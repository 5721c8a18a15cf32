#include "tensor/glyph.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include "tensor/anisotropy.h"
#include "tensor/eigen.h"

namespace tg::tensor {
namespace {

struct Partial {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()};
  glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
  double maxAbs = 0;
  double mdMin = std::numeric_limits<double>::infinity();
  double mdMax = -std::numeric_limits<double>::infinity();
};

void buildRange(std::span<const float> pos, std::span<const float> ten,
                std::span<const std::uint32_t> ids, std::size_t begin, std::size_t end,
                GlyphRecord* out, Partial& p, const GlyphOptions& opt, char* dropped) {
  for (std::size_t i = begin; i < end; ++i) {
    const float* t = &ten[6 * i];
    Eigensystem es = eigensolve({t[0], t[1], t[2], t[3], t[4], t[5]});
    const Anisotropy an = anisotropy(es.values);
    if (dropped && (an.cl < opt.clMin || an.cp < opt.cpMin)) dropped[i] = 1;
    // Clamping keeps the descending order: max(., m) is monotonic.
    if (opt.minEigenvalue) es.values = glm::max(es.values, glm::dvec3(*opt.minEigenvalue));
    GlyphRecord& g = out[i];
    for (int k = 0; k < 3; ++k) {
      g.posWC[k] = pos[3 * i + k];
      g.eigenvalues[k] = static_cast<float>(es.values[k]);
    }
    g.fa = static_cast<float>(an.fa);
    g.id = ids.empty() ? static_cast<std::uint32_t>(i) : ids[i];
    const glm::dmat3 r(es.vectors[0], es.vectors[1], es.vectors[2]);
    const glm::dquat q = glm::normalize(glm::quat_cast(r));
    g.frameWC[0] = static_cast<float>(q.x);
    g.frameWC[1] = static_cast<float>(q.y);
    g.frameWC[2] = static_cast<float>(q.z);
    g.frameWC[3] = static_cast<float>(q.w);
    if (dropped && dropped[i]) continue;  // compacted away; not in the bounds
    const glm::dvec3 c(g.posWC[0], g.posWC[1], g.posWC[2]);
    p.lo = glm::min(p.lo, c);
    p.hi = glm::max(p.hi, c);
    p.maxAbs = std::max({p.maxAbs, std::abs(es.values.x), std::abs(es.values.z)});
    p.mdMin = std::min(p.mdMin, an.md);
    p.mdMax = std::max(p.mdMax, an.md);
  }
}

}  // namespace

GlyphSet buildGlyphs(std::span<const float> positions, std::span<const float> tensors,
                     std::span<const std::uint32_t> ids, unsigned threads, const GlyphOptions& opt) {
  const std::size_t n = positions.size() / 3;
  if (positions.size() != 3 * n || tensors.size() != 6 * n || (!ids.empty() && ids.size() != n))
    throw std::invalid_argument("buildGlyphs: positions, tensors and ids disagree in count");
  GlyphSet set;
  set.glyphs.resize(n);
  const bool filtering = opt.clMin > 0 || opt.cpMin > 0;
  std::vector<char> dropped(filtering ? n : 0);
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  // Below ~64k tensors a thread costs more than it saves.
  const std::size_t chunks = std::clamp<std::size_t>(n / 65536, 1, threads);
  std::vector<Partial> parts(chunks);
  std::vector<std::thread> pool;
  for (std::size_t c = 0; c < chunks; ++c) {
    const std::size_t b = n * c / chunks, e = n * (c + 1) / chunks;
    auto job = [&, b, e, c] {
      buildRange(positions, tensors, ids, b, e, set.glyphs.data(), parts[c], opt, filtering ? dropped.data() : nullptr);
    };
    if (c + 1 == chunks) job();
    else pool.emplace_back(job);
  }
  for (auto& t : pool) t.join();
  if (filtering) {
    std::size_t w = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (!dropped[i]) set.glyphs[w++] = set.glyphs[i];
    set.droppedByShape = n - w;
    set.glyphs.resize(w);
  }
  if (n == 0) return set;
  Partial all = parts[0];
  for (const Partial& p : parts) {
    all.lo = glm::min(all.lo, p.lo);
    all.hi = glm::max(all.hi, p.hi);
    all.maxAbs = std::max(all.maxAbs, p.maxAbs);
    all.mdMin = std::min(all.mdMin, p.mdMin);
    all.mdMax = std::max(all.mdMax, p.mdMax);
  }
  set.boundsMinWC = all.lo;
  set.boundsMaxWC = all.hi;
  set.maxAbsEigenvalue = all.maxAbs;
  set.mdMin = all.mdMin;
  set.mdMax = all.mdMax;
  // Grouped by what a glyph needs, so that dispatch is a pair of draw ranges:
  // spheres (equal eigenvalues, the zero tensor included) are ellipsoids at
  // every gamma; definite tensors are ellipsoids at gamma 0; mixed signs take
  // Schultz-Kindlmann shapes, which do not depend on gamma.
  const auto firstOther = std::partition(set.glyphs.begin(), set.glyphs.end(), [](const GlyphRecord& g) {
    return g.eigenvalues[0] == g.eigenvalues[2];
  });
  const auto firstMixed = std::partition(firstOther, set.glyphs.end(), [](const GlyphRecord& g) {
    return g.eigenvalues[2] > 0.0f || g.eigenvalues[0] < 0.0f;
  });
  set.sphereCount = std::size_t(firstOther - set.glyphs.begin());
  set.definiteCount = std::size_t(firstMixed - firstOther);
  return set;
}

void frameAxes(const GlyphRecord& g, glm::dvec3 axes[3]) {
  const glm::dquat q(g.frameWC[3], g.frameWC[0], g.frameWC[1], g.frameWC[2]);
  const glm::dmat3 r = glm::mat3_cast(glm::normalize(q));
  for (int k = 0; k < 3; ++k) axes[k] = r[k];
}

}  // namespace tg::tensor

namespace tg::tensor {

glm::dvec3 ellipsoidAxes(const GlyphRecord& g, double scale) {
  glm::dvec3 a(std::abs(g.eigenvalues[0]), std::abs(g.eigenvalues[1]), std::abs(g.eigenvalues[2]));
  a *= scale;
  const double floor = kMinAxisRatio * std::max({a.x, a.y, a.z});
  return glm::max(a, glm::dvec3(floor));
}

}  // namespace tg::tensor

namespace tg::tensor {

double defaultScale(const GlyphSet& set, double spacing) {
  const std::size_t n = set.glyphs.size();
  if (n == 0 || !(spacing > 0.0)) return 1.0;
  // A strided sample of at most 65536 glyphs estimates the percentile.
  const std::size_t step = std::max<std::size_t>(1, n / 65536);
  std::vector<double> m;
  for (std::size_t i = 0; i < n; i += step) {
    const float* l = set.glyphs[i].eigenvalues;
    m.push_back(std::max(std::abs(double(l[0])), std::abs(double(l[2]))));
  }
  const std::size_t k = std::min(m.size() - 1, std::size_t(0.99 * double(m.size())));
  std::nth_element(m.begin(), m.begin() + std::ptrdiff_t(k), m.end());
  return m[k] > 0.0 ? 0.5 * spacing / m[k] : 1.0;
}

double resolveScale(ScaleMode mode, double factor, const GlyphSet& set, double spacing) {
  switch (mode) {
    case ScaleMode::Absolute: return factor;
    case ScaleMode::Max:
      return set.maxAbsEigenvalue > 0.0 && spacing > 0.0 ? factor * 0.5 * spacing / set.maxAbsEigenvalue : factor;
    case ScaleMode::Spacing: return factor * defaultScale(set, spacing);
  }
  return factor;
}

BoxWC glyphBoxWC(const GlyphSet& set, double scale) {
  const double pad = scale * set.maxAbsEigenvalue;
  return {set.boundsMinWC - pad, set.boundsMaxWC + pad};
}

}  // namespace tg::tensor
