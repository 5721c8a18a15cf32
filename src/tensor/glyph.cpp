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
#include "tensor/lanes.h"

namespace tg::tensor {
namespace {

struct Partial {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()};
  glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
  glm::dvec3 sizedLo{std::numeric_limits<double>::infinity()};  // of the glyphs with a size
  glm::dvec3 sizedHi{-std::numeric_limits<double>::infinity()};
  double maxAbs = 0;
  double mdMin = std::numeric_limits<double>::infinity();
  double mdMax = -std::numeric_limits<double>::infinity();
  double eigenMin = std::numeric_limits<double>::infinity();
  double eigenMax = -std::numeric_limits<double>::infinity();
};

// The unit quaternion (x, y, z, w) of the rotation whose columns are the
// eigenvectors v[0..2]: Shepperd's method (J. Guidance 1(3), 1978), from the
// largest of 4w², 4x², 4y², 4z² as glm::quat_cast picks it, with blends
// instead of a switch so that it runs on lanes (lanes.h).
template <class T>
[[gnu::always_inline]] inline void frameQuaternion(const V3<T> v[3], T q[4]) {
  const T fw = v[0].x + v[1].y + v[2].z, fx = v[0].x - v[1].y - v[2].z;
  const T fy = v[1].y - v[0].x - v[2].z, fz = v[2].z - v[0].x - v[1].y;
  const auto sx = fx > fw;
  const T f1 = lmax(fw, fx);
  const auto sy = fy > f1;
  const T f2 = lmax(f1, fy);
  const auto sz = fz > f2;
  const T f = lmax(f2, fz);
  // The last comparison that won picks the case, as glm's sequence of ifs.
  const auto isZ = sz, isY = sy && !sz, isX = sx && !sy && !sz;
  const T b = 0.5 * lsqrt(f + 1.0), mult = 0.25 / b;
  const T wx = (v[1].z - v[2].y) * mult, wy = (v[2].x - v[0].z) * mult, wz = (v[0].y - v[1].x) * mult;
  const T xy = (v[0].y + v[1].x) * mult, xz = (v[2].x + v[0].z) * mult, yz = (v[1].z + v[2].y) * mult;
  const T x = isZ ? xz : isY ? xy : isX ? b : wx;
  const T y = isZ ? yz : isY ? b : isX ? xy : wy;
  const T z = isZ ? b : isY ? yz : isX ? xz : wz;
  const T w = isZ ? wz : isY ? wy : isX ? wx : b;
  const T inv = 1.0 / lsqrt(x * x + y * y + z * z + w * w);
  q[0] = x * inv;
  q[1] = y * inv;
  q[2] = z * inv;
  q[3] = w * inv;
}

// Records for tensors [begin, end), a block of kEigenBlock at a time: the
// eigensystems, the per-glyph scalars and the range statistics run on SIMD
// lanes, then the records are written one by one, each with its group
// (glyphGroup) for groupTiles, which then need not read the records again.
TG_LANE_CLONES void buildRange(std::span<const float> pos, std::span<const float> ten,
                std::span<const std::uint32_t> ids, std::size_t begin, std::size_t end,
                GlyphRecord* out, std::uint8_t* groups, Partial& p, const GlyphOptions& opt, char* dropped) {
  constexpr std::size_t B = kEigenBlock;
  EigenBlock eb;
  alignas(64) double fa[B], quat[4][B];
  bool drop[B];
  const Lanes4 clamp = splat<Lanes4>(opt.minEigenvalue ? *opt.minEigenvalue : -std::numeric_limits<double>::infinity());
  const Lanes4 inf = splat<Lanes4>(std::numeric_limits<double>::infinity()), zero = splat<Lanes4>(0.0);
  Lanes4 mdLo = inf, mdHi = -inf, eLo = inf, eHi = -inf, absHi = zero;
  float lo[3], hi[3], sizedLo[3], sizedHi[3];
  for (int c = 0; c < 3; ++c)
    sizedLo[c] = lo[c] = std::numeric_limits<float>::infinity(), sizedHi[c] = hi[c] = -lo[c];
  for (std::size_t b = begin; b < end; b += B) {
    const std::size_t n = std::min(B, end - b);
    eigensolveBlock(&ten[6 * b], n, eb);
    for (std::size_t k = 0; k < B; k += kLanes) {
      Lanes4 l[3];
      V3<Lanes4> v[3];
      for (int i = 0; i < 3; ++i) {
        l[i] = load4(&eb.values[i][k]);
        v[i] = {load4(&eb.vectors[i][0][k]), load4(&eb.vectors[i][1][k]), load4(&eb.vectors[i][2][k])};
      }
      const AnisotropyOf<Lanes4> an = anisotropy(l[0], l[1], l[2]);
      store4(&fa[k], an.fa);
      const auto dr = an.cl < opt.clMin || an.cp < opt.cpMin;
      for (std::size_t j = 0; j < kLanes; ++j) drop[k + j] = dr[j] != 0;
      // Clamping keeps the descending order: max(., m) is monotonic.
      for (int i = 0; i < 3; ++i) l[i] = lmax(l[i], clamp);
      for (int i = 0; i < 3; ++i) store4(&eb.values[i][k], l[i]);
      // The statistics of the glyphs kept: lanes past the block's end and
      // dropped ones take the neutral values.
      const Lanes4 lane = splat<Lanes4>(double(k)) + Lanes4{0, 1, 2, 3};
      const auto kept = lane < splat<Lanes4>(double(n)) && !dr;
      // MD's colour range leaves out zero tensors, which draw nothing: the
      // background of a DTI volume would pull it to 0.
      const auto sized = kept && (l[0] != zero || l[2] != zero);
      mdLo = lmin(mdLo, sized ? an.md : inf);
      mdHi = lmax(mdHi, sized ? an.md : -inf);
      eLo = lmin(eLo, kept ? l[2] : inf);
      eHi = lmax(eHi, kept ? l[0] : -inf);
      absHi = lmax(absHi, kept ? lmax(labs(l[0]), labs(l[2])) : zero);
      Lanes4 q[4];
      frameQuaternion(v, q);
      for (int c = 0; c < 4; ++c) store4(&quat[c][k], q[c]);
    }
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = b + k;
      GlyphRecord& g = out[i];
      for (int c = 0; c < 3; ++c) {
        g.posWC[c] = pos[3 * i + std::size_t(c)];
        g.eigenvalues[c] = static_cast<float>(eb.values[c][k]);
      }
      g.fa = static_cast<float>(fa[k]);
      g.id = ids.empty() ? static_cast<std::uint32_t>(i) : ids[i];
      for (int c = 0; c < 4; ++c) g.frameWC[c] = static_cast<float>(quat[c][k]);
      groups[i] = static_cast<std::uint8_t>(glyphGroup(g));
      if (dropped) {
        dropped[i] = drop[k];
        if (drop[k]) continue;  // compacted away; not in the bounds
      }
      for (int c = 0; c < 3; ++c) {
        lo[c] = std::min(lo[c], g.posWC[c]);
        hi[c] = std::max(hi[c], g.posWC[c]);
      }
      if (g.eigenvalues[0] != 0.0f || g.eigenvalues[2] != 0.0f)
        for (int c = 0; c < 3; ++c) {
          sizedLo[c] = std::min(sizedLo[c], g.posWC[c]);
          sizedHi[c] = std::max(sizedHi[c], g.posWC[c]);
        }
    }
  }
  for (std::size_t j = 0; j < kLanes; ++j) {
    p.mdMin = std::min(p.mdMin, mdLo[j]);
    p.mdMax = std::max(p.mdMax, mdHi[j]);
    p.eigenMin = std::min(p.eigenMin, eLo[j]);
    p.eigenMax = std::max(p.eigenMax, eHi[j]);
    p.maxAbs = std::max(p.maxAbs, absHi[j]);
  }
  for (int c = 0; c < 3; ++c) {
    p.lo[c] = std::min(p.lo[c], double(lo[c]));
    p.hi[c] = std::max(p.hi[c], double(hi[c]));
    p.sizedLo[c] = std::min(p.sizedLo[c], double(sizedLo[c]));
    p.sizedHi[c] = std::max(p.sizedHi[c], double(sizedHi[c]));
  }
}

// Orders one tile stably by group: a counting scatter through a stack copy,
// skipped when the tile is already in order (the usual case for a volume of
// one kind of tensor).
GlyphTile groupTile(GlyphRecord* g, const std::uint8_t* group, std::size_t n) {
  std::size_t count[3] = {0, 0, 0};
  bool ordered = true;
  for (std::size_t i = 0; i < n; ++i) {
    ordered = ordered && (i == 0 || group[i] >= group[i - 1]);
    ++count[group[i]];
  }
  if (!ordered) {
    GlyphRecord copy[kTileGlyphs];
    std::copy(g, g + n, copy);
    std::size_t next[3] = {0, count[0], count[0] + count[1]};
    for (std::size_t i = 0; i < n; ++i) g[next[group[i]]++] = copy[i];
  }
  return {static_cast<std::uint16_t>(count[0]), static_cast<std::uint16_t>(count[0] + count[1])};
}

void groupTiles(GlyphSet& set, const std::uint8_t* groups, std::size_t threads) {
  const std::size_t n = set.glyphs.size(), tiles = (n + kTileGlyphs - 1) / kTileGlyphs;
  set.tiles.resize(tiles);
  auto job = [&](std::size_t b, std::size_t e) {
    for (std::size_t t = b; t < e; ++t) {
      const std::size_t first = t * kTileGlyphs;
      set.tiles[t] = groupTile(&set.glyphs[first], groups + first, std::min(kTileGlyphs, n - first));
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t c = 0; c + 1 < threads; ++c) pool.emplace_back(job, tiles * c / threads, tiles * (c + 1) / threads);
  job(tiles * (threads - 1) / threads, tiles);
  for (auto& t : pool) t.join();
  for (const GlyphTile& t : set.tiles) {
    set.sphereCount += t.sphereEnd;
    set.definiteCount += std::size_t(t.definiteEnd - t.sphereEnd);
  }
}

}  // namespace

GlyphSet buildGlyphs(std::span<const float> positions, std::span<const float> tensors,
                     std::span<const std::uint32_t> ids, unsigned threads, const GlyphOptions& opt,
                     const util::ProgressSink& progress) {
  const std::size_t n = positions.size() / 3;
  if (positions.size() != 3 * n || tensors.size() != 6 * n || (!ids.empty() && ids.size() != n))
    throw std::invalid_argument("buildGlyphs: positions, tensors and ids disagree in count");
  GlyphSet set;
  set.glyphs.extend(n);  // every record is written by buildRange
  const bool filtering = opt.clMin > 0 || opt.cpMin > 0;
  std::vector<char> dropped(filtering ? n : 0);
  util::MappedArray<std::uint8_t> groups;
  groups.extend(n);  // every entry is written by buildRange
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  // Below ~64k tensors a thread costs more than it saves.
  const std::size_t chunks = std::clamp<std::size_t>(n / 65536, 1, threads);
  std::vector<Partial> parts(chunks);
  std::vector<std::thread> pool;
  for (std::size_t c = 0; c < chunks; ++c) {
    const std::size_t b = n * c / chunks, e = n * (c + 1) / chunks;
    auto job = [&, b, e, c] {
      buildRange(positions, tensors, ids, b, e, set.glyphs.data(), groups.data(), parts[c], opt,
                 filtering ? dropped.data() : nullptr);
    };
    if (c + 1 < chunks) {
      pool.emplace_back(job);
    } else if (!progress) {
      job();
    } else {
      // The other threads run at the same pace: this share stands for all.
      constexpr std::size_t kStep = 65536;
      for (std::size_t s = b; s < e; s += kStep) {
        progress("eigen", double(s - b) * double(n) / double(e - b), double(n), "tensors");
        buildRange(positions, tensors, ids, s, std::min(e, s + kStep), set.glyphs.data(), groups.data(), parts[c],
                   opt, filtering ? dropped.data() : nullptr);
      }
      progress("eigen", double(n), double(n), "tensors");
    }
  }
  for (auto& t : pool) t.join();
  if (filtering) {
    std::size_t w = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (!dropped[i]) {
        groups[w] = groups[i];
        set.glyphs[w++] = set.glyphs[i];
      }
    set.droppedByShape = n - w;
    set.glyphs.resize(w);
  }
  if (n == 0) return set;
  Partial all = parts[0];
  for (const Partial& p : parts) {
    all.lo = glm::min(all.lo, p.lo);
    all.hi = glm::max(all.hi, p.hi);
    all.sizedLo = glm::min(all.sizedLo, p.sizedLo);
    all.sizedHi = glm::max(all.sizedHi, p.sizedHi);
    all.maxAbs = std::max(all.maxAbs, p.maxAbs);
    all.mdMin = std::min(all.mdMin, p.mdMin);
    all.mdMax = std::max(all.mdMax, p.mdMax);
    all.eigenMin = std::min(all.eigenMin, p.eigenMin);
    all.eigenMax = std::max(all.eigenMax, p.eigenMax);
  }
  set.boundsMinWC = all.lo;
  set.boundsMaxWC = all.hi;
  set.sizedBoundsMinWC = all.sizedLo;
  set.sizedBoundsMaxWC = all.sizedHi;
  set.maxAbsEigenvalue = all.maxAbs;
  set.mdMin = all.mdMin;
  set.mdMax = all.mdMax;
  // A field of one MD stored in floats (Kindlmann's dt-helix) varies by
  // rounding alone; mapped onto a colour map, that spread drew noise. A
  // spread single precision cannot resolve against the eigenvalues is one MD.
  if (set.mdMin <= set.mdMax && set.mdMax - set.mdMin <= 1e-6 * all.maxAbs) set.mdMin = set.mdMax = 0.5 * (all.mdMin + all.mdMax);
  set.eigenvalueMin = all.eigenMin;
  set.eigenvalueMax = all.eigenMax;
  groupTiles(set, groups.data(), chunks);
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

BoxWC glyphBoxWC(const GlyphSet& set, double scale) {
  const double pad = kGlyphReach * scale * set.maxAbsEigenvalue;
  return {set.boundsMinWC - pad, set.boundsMaxWC + pad};
}

}  // namespace tg::tensor
