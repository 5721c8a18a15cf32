#include "render/legend/legend_room.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace tg::render {
namespace {

bool empty(const LegendRect& r) { return !(r.x0 <= r.x1 && r.y0 <= r.y1); }

bool overlaps(const LegendRect& a, const LegendRect& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

bool contains(const LegendRect& outer, const LegendRect& r, float tol) {
  return r.x0 >= outer.x0 - tol && r.x1 <= outer.x1 + tol && r.y0 >= outer.y0 - tol && r.y1 <= outer.y1 + tol;
}

LegendRect grown(const LegendRect& r, float by) { return {r.x0 - by, r.y0 - by, r.x1 + by, r.y1 + by}; }

LegendRect unite(const LegendRect& a, const LegendRect& b) {
  if (empty(a)) return b;
  if (empty(b)) return a;
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

constexpr LegendRect kEmpty{1, 1, 0, 0};

// A box's image; empty when a corner lies at or behind the eye.
LegendRect projected(const Camera& cam, const glm::dmat4& wcToCC, const tensor::BoxWC& b) {
  LegendRect r{INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 p((k & 1) ? b.hi.x : b.lo.x, (k & 2) ? b.hi.y : b.lo.y, (k & 4) ? b.hi.z : b.lo.z);
    const glm::dvec4 c = wcToCC * glm::dvec4(p, 1.0);
    if (!(c.w > 0.0)) return kEmpty;
    const auto x = float((c.x / c.w + 1.0) * 0.5 * cam.width), y = float((1.0 - c.y / c.w) * 0.5 * cam.height);
    r = {std::min(r.x0, x), std::min(r.y0, y), std::max(r.x1, x), std::max(r.y1, y)};
  }
  return r;
}

// How much the boxes' image must shrink to fit `t`: at most 1 (never larger
// than the framing chosen without a legend); 0 when `t` has no room.
double fitScale(const LegendRect& t, const LegendRect& r) {
  if (!(t.width() > 0 && t.height() > 0)) return 0.0;
  return std::min({1.0, double(t.width()) / std::max(double(r.width()), 1e-9),
                   double(t.height()) / std::max(double(r.height()), 1e-9)});
}

// How far the boxes' image lay beyond the image less its margin, side by
// side (x0, y0, x1, y1), without a legend. The boxes are loose (a cell's
// centres grown by a glyph's semi-axis box), so they may stay out only as
// far as they shrink: at scale s, s times as far. Held where they were, the
// loose part shrank away and the glyphs themselves crossed the edge.
struct Overshoot {
  double x0, y0, x1, y1;
};

// The image less its margin, widened by the overshoot at scale `s`.
LegendRect region(const Overshoot& o, double s, int width, int height, float gap) {
  return {float(gap - s * o.x0), float(gap - s * o.y0), float(double(width) - gap + s * o.x1),
          float(double(height) - gap + s * o.y1)};
}

// The largest scale, at most 1, at which [lo, hi] shrunk by s fits in
// [tlo, thi] widened by s times olo and ohi; 0 when there is no room.
double fitAxis(double lo, double hi, double tlo, double thi, double olo, double ohi) {
  const double need = (hi - lo) - olo - ohi, room = thi - tlo;
  if (!(room > 0.0)) return 0.0;
  return need <= room ? 1.0 : room / need;
}

// The least move that brings [lo, hi] into [tlo, thi] (no longer than it).
double into(double lo, double hi, double tlo, double thi) {
  if (lo < tlo) return tlo - lo;
  if (hi > thi) return thi - hi;
  return 0.0;
}

}  // namespace

std::vector<GlyphCell> glyphCells(const tensor::GlyphSet& set) {
  const glm::dvec3 lo = set.boundsMinWC, hi = set.boundsMaxWC;
  if (set.glyphs.empty() || !glm::all(glm::lessThanEqual(lo, hi))) return {};
  const glm::dvec3 step = glm::max((hi - lo) / double(kRoomCells), glm::dvec3(1e-300));
  std::vector<GlyphCell> grid(std::size_t(kRoomCells) * kRoomCells * kRoomCells);
  std::vector<bool> used(grid.size(), false);
  for (const tensor::GlyphRecord& g : set.glyphs) {
    const glm::dvec3 l(g.eigenvalues[0], g.eigenvalues[1], g.eigenvalues[2]);
    const double m = std::max(std::abs(l.x), std::abs(l.z));
    if (!(m > 0.0)) continue;  // a zero tensor draws nothing
    const glm::dvec3 p(g.posWC[0], g.posWC[1], g.posWC[2]);
    std::size_t idx = 0;
    for (int a = 2; a >= 0; --a)
      idx = idx * kRoomCells + std::size_t(std::clamp(int((p[a] - lo[a]) / step[a]), 0, kRoomCells - 1));
    GlyphCell& c = grid[idx];
    if (!used[idx]) {
      c = {p, p, -INFINITY, 0.0, 0.0};
      used[idx] = true;
    }
    c.lo = glm::min(c.lo, p);
    c.hi = glm::max(c.hi, p);
    if (std::isfinite(g.fa)) c.maxFa = std::max(c.maxFa, g.fa);
    c.maxAbsEigenvalue = std::max(c.maxAbsEigenvalue, m);
    c.maxReachRatio = std::min(std::max(c.maxReachRatio, glm::length(l) / m), tensor::kGlyphReach);
  }
  std::vector<GlyphCell> cells;
  for (std::size_t i = 0; i < grid.size(); ++i)
    if (used[i]) cells.push_back(grid[i]);
  return cells;
}

std::vector<tensor::BoxWC> drawnCellBoxes(const std::vector<GlyphCell>& cells, double faMin, double scale,
                                          const tensor::SizeMapping& sizing) {
  std::vector<tensor::BoxWC> boxes;
  for (const GlyphCell& c : cells) {
    if (!(double(c.maxFa) >= faMin)) continue;  // as glyphSelected (shaders/lib/selection.glsl)
    // Semi-axes are factor(m) |l_i| with m = max |l_i|, and m's radius is
    // monotonic in m: the cell's largest m and ratio bound every glyph's box.
    const double reach = c.maxReachRatio * tensor::glyphRadiusWC(scale, sizing, c.maxAbsEigenvalue);
    boxes.push_back({c.lo - reach, c.hi + reach});
  }
  return boxes;
}

LegendRect projectedBoxes(const Camera& cam, const std::vector<tensor::BoxWC>& boxes) {
  const glm::dmat4 wcToCC = cam.projVCCC * cam.viewWCVC;
  LegendRect r = kEmpty;
  for (const tensor::BoxWC& b : boxes) {
    const LegendRect one = projected(cam, wcToCC, b);
    if (empty(one)) return kEmpty;
    r = unite(r, one);
  }
  return r;
}

CameraDesc leaveRoom(const CameraDesc& d, int width, int height, const glm::dvec3& depthLo, const glm::dvec3& depthHi,
                     const std::vector<tensor::BoxWC>& all, const LegendRect& panel, LegendCorner corner, float gapPx) {
  // The boxes in the picture: glyphs already out of it (a scattered field's
  // outliers) do not move the camera.
  const Camera cam0 = makeCamera(d, width, height, depthLo, depthHi);
  const glm::dmat4 wcToCC = cam0.projVCCC * cam0.viewWCVC;
  const LegendRect image{0, 0, float(width), float(height)};
  std::vector<tensor::BoxWC> boxes;
  for (const tensor::BoxWC& b : all) {
    const LegendRect r = projected(cam0, wcToCC, b);
    if (empty(r)) return d;
    if (overlaps(r, image)) boxes.push_back(b);
  }
  const LegendRect r0 = projectedBoxes(cam0, boxes);
  const LegendRect p = grown(panel, gapPx);
  // Box by box, not by their bounding rectangle: a helix seen obliquely
  // leaves its rectangle's corners empty.
  const auto clear = [&](const CameraDesc& c) {
    const Camera cam = makeCamera(c, width, height, depthLo, depthHi);
    const glm::dmat4 toCC = cam.projVCCC * cam.viewWCVC;
    return std::none_of(boxes.begin(), boxes.end(), [&](const tensor::BoxWC& b) {
      const LegendRect r = projected(cam, toCC, b);
      return empty(r) || overlaps(r, p);
    });
  };
  if (empty(r0) || clear(d)) return d;
  // Where the glyphs may lie: the image less an edge margin, and beyond it
  // as far as they reached without a legend, shrunk with them (Overshoot);
  // beside the panel or above/below it.
  const double w = width, h = height, g = gapPx;
  const Overshoot o{std::max(0.0, g - r0.x0), std::max(0.0, g - r0.y0), std::max(0.0, r0.x1 - (w - g)),
                    std::max(0.0, r0.y1 - (h - g))};
  const bool left = corner == LegendCorner::TopLeft || corner == LegendCorner::BottomLeft;
  const bool top = corner == LegendCorner::TopLeft || corner == LegendCorner::TopRight;
  const double fitX = fitAxis(r0.x0, r0.x1, g, w - g, o.x0, o.x1), fitY = fitAxis(r0.y0, r0.y1, g, h - g, o.y0, o.y1);
  const double sBeside = std::min(fitY, left ? fitAxis(r0.x0, r0.x1, p.x1, w - g, 0.0, o.x1)
                                             : fitAxis(r0.x0, r0.x1, g, p.x0, o.x0, 0.0));
  const double sAcross = std::min(fitX, top ? fitAxis(r0.y0, r0.y1, p.y1, h - g, 0.0, o.y1)
                                            : fitAxis(r0.y0, r0.y1, g, p.y0, o.y0, 0.0));
  if (!(std::max(sBeside, sAcross) > 0.0)) return d;  // a panel as large as the image: nothing helps
  LegendRect t = region(o, std::max(sBeside, sAcross), width, height, gapPx);
  if (sBeside >= sAcross)
    (left ? t.x0 : t.x1) = left ? p.x1 : p.x0;
  else
    (top ? t.y0 : t.y1) = top ? p.y1 : p.y0;
  // A camera on the way keeps the glyphs in the region for its own scale.
  const auto inRegion = [&](const CameraDesc& c) {
    const LegendRect r = projectedBoxes(makeCamera(c, width, height, depthLo, depthHi), boxes);
    const double s = std::min(1.0, double(r.width()) / std::max(double(r0.width()), 1e-9));
    return !empty(r) && contains(region(o, s, width, height, gapPx), r, 0.5f);
  };

  // Under perspective, pulling back shrinks near corners less than far ones
  // and panning moves them more: repeated on the boxes' new image.
  CameraDesc c = d;
  const double cx = 0.5 * width, cy = 0.5 * height;
  for (int it = 0; it < 64; ++it) {
    const LegendRect r = projectedBoxes(makeCamera(c, width, height, depthLo, depthHi), boxes);
    if (empty(r)) return d;
    if (contains(t, r, 0.01f)) break;
    // Shrunk about the image centre (what pulling back does), then moved into t.
    const double s = fitScale(t, r);
    const double dx = into(cx + s * (r.x0 - cx), cx + s * (r.x1 - cx), t.x0, t.x1);
    const double dy = into(cy + s * (r.y0 - cy), cy + s * (r.y1 - cy), t.y0, t.y1);
    const glm::dvec3 view = c.lookAtWC - c.eyeWC;
    const glm::dvec3 f = glm::normalize(view);
    const glm::dvec3 right = glm::normalize(glm::cross(f, c.upWC)), up = glm::cross(right, f);
    double pixelsPerWC;
    if (c.projection == Projection::Orthographic) {
      c.orthoHeight /= s;
      pixelsPerWC = height / c.orthoHeight;
    } else {
      const double dist = glm::length(view) / s;
      c.eyeWC = c.lookAtWC - f * dist;
      pixelsPerWC = height / (2.0 * dist * std::tan(glm::radians(c.fovYDeg) * 0.5));
    }
    // The picture moves right and down as the camera moves left and up.
    const glm::dvec3 move = (-dx * right + dy * up) / pixelsPerWC;
    c.eyeWC += move;
    c.lookAtWC += move;
  }
  // c holds the boxes' whole rectangle beside the panel; the least part of
  // the way there that clears the panel box by box moves the picture least.
  // Both look the same way, so the eye and look-at points interpolate.
  const auto partWay = [&](double a) {
    CameraDesc m = d;
    m.eyeWC = glm::mix(d.eyeWC, c.eyeWC, a);
    m.lookAtWC = glm::mix(d.lookAtWC, c.lookAtWC, a);
    m.orthoHeight = d.orthoHeight * std::pow(c.orthoHeight / d.orthoHeight, a);
    return m;
  };
  if (!clear(c) || !inRegion(c)) return c;
  double blocked = 0.0, free = 1.0;
  for (int it = 0; it < 16; ++it) {
    const double a = 0.5 * (blocked + free);
    const CameraDesc m = partWay(a);
    (clear(m) && inRegion(m) ? free : blocked) = a;
  }
  return partWay(free);
}

CameraDesc frameBesideLegend(const CameraDesc& d, int width, int height, const glm::dvec3& depthLo,
                             const glm::dvec3& depthHi, const std::vector<tensor::BoxWC>& boxes,
                             const LegendParams& p, const LegendInputs& in) {
  const LegendFont font(legendTextScale(p, height));
  const float gap = 4.0f * float(font.textScale());
  // The panel's width follows the scale bar's text, which follows the
  // camera: room is left for every panel met on the way.
  LegendRect room = kEmpty;
  CameraDesc c = d;
  for (int round = 0; round < 4; ++round) {
    const LegendRect panel = layoutLegend(p, in, makeCamera(c, width, height, depthLo, depthHi), font).panel;
    if (!empty(room) && contains(room, panel, 0.0f)) break;
    room = unite(room, panel);
    c = leaveRoom(d, width, height, depthLo, depthHi, boxes, room, p.corner, gap);
  }
  return c;
}

}  // namespace tg::render
