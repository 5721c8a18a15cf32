#include "render/cpu_blobs.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include "render/glsl_cpp.h"

namespace tg::render {
namespace {

// One bump along one ray: q(t) = q0 + (t - tc) dq in its GC, inside its
// region for t in [t0, t1], nearest its centre (in GC) at tPeak.
struct Span {
  float t0, t1, tPeak, tc;
  glsl::vec3 q0, dq;
  std::uint32_t k;
};

// The sum over the spans that hold t (sorted by t0: those before `end`).
struct Sum {
  glsl::Shaders& sh;  // its functions write nothing: shared by the threads
  const std::vector<Span>& spans;
  const std::vector<BlobCandidate>& bumps;
  float bound;
  // With `slope`, the sum's derivative along the ray too.
  float at(float t, std::size_t end, float* slope = nullptr) const {
    float d = 0.0f, ds = 0.0f;
    glsl::vec3 grad;
    for (std::size_t j = 0; j < end; ++j) {
      const Span& s = spans[j];
      if (t < s.t0 || t > s.t1) continue;
      d += sh.blobField(bumps[s.k].shape, s.q0 + (t - s.tc) * s.dq, bound, slope != nullptr, grad);
      if (slope) ds += dot(grad, s.dq);
    }
    if (slope) *slope = ds;
    return d;
  }
  // Whether the sum at t is surely below `level`, from a bound on each
  // superquadric bump that needs no gauge: its shape lies in its cube and
  // within its reach of the centre, so g >= max(max |q_k|, |q| / reach) and
  // D'_i is at most its value there. Most samples before a hit are far
  // below T, so most are decided without one.
  bool surelyBelow(float t, std::size_t end, float level) const {
    float d = 0.0f;
    const float b2 = bound * bound, cut = sh.uBlobCutoff * sh.uBlobThreshold, norm = 1.0f / (1.0f - sh.uBlobCutoff);
    for (std::size_t j = 0; j < end; ++j) {
      const Span& s = spans[j];
      if (t < s.t0 || t > s.t1) continue;
      const BlobCandidate& c = bumps[s.k];
      const glsl::vec3 q = s.q0 + (t - s.tc) * s.dq, aq = abs(q);
      float g2 = dot(q, q);
      if (!(c.shape.x == 1.0f && c.shape.y == 1.0f && c.shape.z == 1.0f)) {
        const float reach = c.reachGC / bound, lo = std::max(std::max(aq.x, std::max(aq.y, aq.z)), std::sqrt(g2) / reach);
        g2 = lo * lo;
      }
      if (g2 < b2) d += std::max(std::exp(sh.uBlobBlobbiness * (g2 - 1.0f)) - cut, 0.0f) * norm;
      if (!(d < level)) return false;
    }
    return true;
  }
};

bool blobIsQuadricShape(const glsl::vec4& shape) { return shape.x == 1.0f && shape.y == 1.0f && shape.z == 1.0f; }

// Where a superquadric bump peaks along its span: the gauge's minimum, by
// golden section. Its level sets are the shape scaled, convex for every
// definite shape, so the gauge is unimodal along a line there; a ray's
// closest approach in the quadric's metric can lie far from it on a boxy
// shape, and a grazing ray's short chord inside the surface between samples.
float gaugeMinimum(glsl::Shaders& sh, const glsl::vec4& shape, const Span& s) {
  constexpr float r = 0.618034f;
  float a = s.t0, b = s.t1;
  auto g = [&](float t) { return sh.superquadricGaugeValue(glsl::vec3(shape), s.q0 + (t - s.tc) * s.dq); };
  float c = b - r * (b - a), d = a + r * (b - a), gc = g(c), gd = g(d);
  for (int k = 0; k < 9; ++k) {
    if (gc < gd) {
      b = d, d = c, gd = gc, c = b - r * (b - a), gc = g(c);
    } else {
      a = c, c = d, gc = gd, d = a + r * (b - a), gd = g(d);
    }
  }
  return 0.5f * (a + b);
}

}  // namespace

std::uint64_t castBlobs(std::span<const tensor::GlyphRecord> records, const Camera& cam, const FrameParams& p,
                        bool hitGC, int threads, CpuCasts& out, std::vector<BlobCandidate>& bumps) {
  glsl::Shaders sh;
  sh.setCamera(cam);
  sh.setGlyph(p);
  const float gamma = float(p.gamma), bound = sh.blobBoundGauge(), threshold = float(p.blob.threshold);
  const int steps = std::max(1, p.blob.steps);
  const int w = cam.width, h = cam.height;
  beginCasts(out, w, h, hitGC);

  // Set-up: part k writes its bumps, in record order, from its first record's slot on.
  const std::size_t m = records.size();
  if (bumps.size() < m) bumps.resize(m);
  if (out.rects.size() < m) out.rects.resize(m);
  const auto setUp = [&](std::size_t i, std::size_t at) {
    glsl::GlyphRecord g;
    std::memcpy(&g, &records[i], sizeof g);
    glsl::BlobBump b;
    if (!sh.blobBump(g, gamma, bound, b) || !pixelsOf(b.rectNDC, w, h, out.rects[at])) return false;
    bumps[at] = {b.centreVC, b.gcFromVC, b.shape, b.reachGC, b.nearVC, std::uint32_t(i)};
    return true;
  };
  const std::size_t count = keepInParts(threads, m, setUp, &bumps, &out.rects);
  out.count = count;
  binToTiles(std::span(out.rects.data(), count), w, h, threads, out.bins);
  const TileBins& bins = out.bins;
  const std::vector<PixelRect>& rects = out.rects;
  const bool masked = out.masked();

  std::atomic<std::size_t> nextTile{0};
  runParts(threads, [&](int, int) {
    std::vector<Span> spans;
    std::vector<float> marks;
    for (std::size_t t; (t = nextTile.fetch_add(1)) < bins.tiles();) {
      const std::uint32_t e0 = bins.start[t], e1 = bins.start[t + 1];
      if (e0 == e1) continue;
      const int tx = int(t % std::size_t(bins.tilesX)), ty = int(t / std::size_t(bins.tilesX));
      const int x0 = tx * kTilePx, y0 = ty * kTilePx;
      const int x1 = std::min(w, x0 + kTilePx) - 1, y1 = std::min(h, y0 + kTilePx) - 1;
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          if (masked && !out.only[std::size_t(y) * std::size_t(w) + std::size_t(x)]) continue;
          // The z-active list: the bumps whose regions this ray crosses.
          glsl::vec3 originVC, dirVC;
          sh.rayThroughFragment(glsl::vec2(float(x) + 0.5f, float(y) + 0.5f), originVC, dirVC);
          spans.clear();
          for (std::uint32_t e = e0; e < e1; ++e) {
            const std::uint32_t k = bins.items[e];
            const PixelRect& r = rects[k];
            if (x < r.x0 || x > r.x1 || y < r.y0 || y > r.y1) continue;
            const BlobCandidate& c = bumps[k];
            // From the ray's closest approach to the centre, as castEllipsoid: GC values stay O(1).
            const float tc = dot(c.centreVC - originVC, dirVC) / dot(dirVC, dirVC);
            const glsl::vec3 q0 = c.gcFromVC * (originVC + tc * dirVC - c.centreVC), dq = c.gcFromVC * dirVC;
            float u0, u1;
            if (!sh.unitSphereRoots(q0 / c.reachGC, dq / c.reachGC, u0, u1)) continue;
            Span s{std::max(tc + u0, sh.uNearVC), tc + u1, 0.0f, tc, q0, dq, k};
            const bool quadric = blobIsQuadricShape(c.shape);
            // A superquadric bump's region also lies in its cube |q_k| <= bound (g >= max |q_k|).
            for (int a = 0; a < 3 && !quadric; ++a) {
              if (dq[a] == 0.0f) {
                if (!(std::abs(q0[a]) < bound)) s.t1 = -1.0f;
                continue;
              }
              const float ua = (-bound - q0[a]) / dq[a], ub = (bound - q0[a]) / dq[a];
              s.t0 = std::max(s.t0, tc + std::min(ua, ub));
              s.t1 = std::min(s.t1, tc + std::max(ua, ub));
            }
            if (!(s.t1 > s.t0) || (sh.uOrtho == 1 && s.t0 > sh.uFarVC)) continue;
            spans.push_back(s);
          }
          if (spans.empty()) continue;
          // Quadric bumps cost no more exactly than bounded.
          const bool superquadrics = std::any_of(spans.begin(), spans.end(), [&](const Span& e) {
            return !blobIsQuadricShape(bumps[e.k].shape);
          });
          std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) { return a.t0 < b.t0 || (a.t0 == b.t0 && a.k < b.k); });
          // Sample points: every entry, peak and exit, and `steps` between
          // neighbours, in order; a bump's peak and exit are found once the
          // sweep enters it, so that bumps behind the hit cost no more than their entry.
          marks.clear();
          std::size_t opened = 0;
          auto nextMark = [&](float& mark) {
            const bool entry = opened < spans.size() && (marks.empty() || spans[opened].t0 <= marks.front());
            if (entry) {
              Span& e = spans[opened++];
              mark = e.t0;
              e.tPeak = blobIsQuadricShape(bumps[e.k].shape)
                            ? std::clamp(e.tc - dot(e.q0, e.dq) / dot(e.dq, e.dq), e.t0, e.t1)
                            : gaugeMinimum(sh, bumps[e.k].shape, e);
              for (const float at : {e.tPeak, e.t1}) {
                marks.push_back(at);
                std::push_heap(marks.begin(), marks.end(), std::greater<>());
              }
              return true;
            }
            if (marks.empty()) return false;
            std::pop_heap(marks.begin(), marks.end(), std::greater<>());
            mark = marks.back();
            marks.pop_back();
            return true;
          };
          const Sum sum{sh, spans, bumps, bound};
          std::size_t end = 0;  // spans with t0 <= the sample
          // sum - T at u; `bounded`: where the sum is surely below T, any
          // negative value (the sweep needs only the sign there).
          auto value = [&](float u, bool bounded = false) {
            while (end < spans.size() && spans[end].t0 <= u) ++end;
            if (bounded && superquadrics && sum.surelyBelow(u, end, threshold)) return -threshold;
            return sum.at(u, end) - threshold;
          };
          float from = 0.0f, to = 0.0f;
          nextMark(from);
          float ta = from, fa = value(ta);
          const bool inside = fa >= 0.0f;  // the near plane inside the surface: its exit, as castEllipsoid
          float tb = ta, fb = fa;
          bool found = false;
          while (!found && nextMark(to)) {
            if (!(to > from)) continue;
            for (int s = 1; s <= steps; ++s) {
              tb = s == steps ? to : from + (to - from) * float(s) / float(steps);
              fb = value(tb, true);
              if ((fb >= 0.0f) != inside) {
                found = true;
                break;
              }
              ta = tb, fa = fb;
            }
            from = to;
          }
          if (!found) continue;
          // The bracket's values exactly (the sweep may have bounded them).
          end = 0;
          fa = value(ta);
          end = 0;
          fb = value(tb);
          // Blinn's hybrid (§3.3) on [ta, tb], whose ends' sums lie either
          // side of T: a Newton step on the sum and its slope, regula falsi
          // where the step would leave the bracket, the bracket kept.
          float r = std::abs(fa) < std::abs(fb) ? ta : tb;
          for (int it = 0; it < 24; ++it) {
            float slope;
            end = 0;
            while (end < spans.size() && spans[end].t0 <= r) ++end;
            const float ft = sum.at(r, end, &slope) - threshold;
            ((ft >= 0.0f) == (fb >= 0.0f) ? tb : ta) = r;
            ((ft >= 0.0f) == (fb >= 0.0f) ? fb : fa) = ft;
            float next = r - ft / slope;
            if (!(next > ta && next < tb)) next = tb - fb * (tb - ta) / (fb - fa);
            if (!(next > ta && next < tb)) next = 0.5f * (ta + tb);
            const bool done = std::abs(next - r) <= 1e-6f * r || tb - ta <= 1e-6f * tb;
            r = next;
            if (done) break;
          }
          const float tHit = r;
          if (sh.uOrtho == 1 && tHit > sh.uFarVC) continue;
          // The gradient and the dominant bump at the hit.
          glsl::vec3 gradVC(0.0f), bestQ(0.0f);
          float bestD = -1.0f;
          std::uint32_t bestK = 0;
          for (const Span& s : spans) {
            if (tHit < s.t0 || tHit > s.t1) continue;
            const BlobCandidate& c = bumps[s.k];
            const glsl::vec3 q = s.q0 + (tHit - s.tc) * s.dq;
            glsl::vec3 g;
            const float d = sh.blobField(c.shape, q, bound, true, g);
            gradVC += transpose(c.gcFromVC) * g;
            if (d > bestD || (d == bestD && c.record < bumps[bestK].record)) bestD = d, bestK = s.k, bestQ = q;
          }
          const glsl::vec3 normalVC = -gradVC;  // outward: the sum falls
          const std::size_t px = std::size_t(y) * std::size_t(w) + std::size_t(x);
          out.windowDepth[px] = sh.windowDepthFromViewDepth(tHit);
          out.record[px] = bumps[bestK].record + 1;
          const float len = length(normalVC);
          if (!out.normalWC.empty())
            out.normalWC[px] = len > 0.0f ? transpose(glsl::mat3(sh.uViewWCVC)) * (normalVC / len) : glsl::vec3(0.0f, 0.0f, 1.0f);
          if (!out.hitGC.empty()) {
            // In the ellipsoid's axis order (GC axis k is eigenvector (axis + 1 + k) % 3), for the sign colour.
            const int axis = int(bumps[bestK].shape.w);
            glsl::vec3 e(0.0f);
            e[(axis + 1) % 3] = bestQ.x;
            e[(axis + 2) % 3] = bestQ.y;
            e[axis] = bestQ.z;
            out.hitGC[px] = glsl::vec4(e, 0.0f);
          }
        }
    }
  });
  return count;
}

}  // namespace tg::render
