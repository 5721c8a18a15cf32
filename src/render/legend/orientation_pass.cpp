#include "render/legend/orientation_pass.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "view/anatomy.h"

namespace tg::render {

namespace {

bool meets(const LegendRect& a, const LegendRect& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

// `box` slid along its edge (vertically when `vertical`) just clear of `avoid`
// by `gap`, to whichever side keeps it in [0, limit] nearer where it was;
// unmoved when neither side has room (the legend then fills that edge).
LegendRect slidClear(const LegendRect& box, const LegendRect& avoid, float gap, bool vertical, float limit) {
  const float lo = vertical ? box.y0 : box.x0, hi = vertical ? box.y1 : box.x1;
  const float alo = vertical ? avoid.y0 : avoid.x0, ahi = vertical ? avoid.y1 : avoid.x1;
  const float before = (alo - gap) - hi, after = (ahi + gap) - lo;  // the moves
  const bool beforeFits = lo + before >= 0, afterFits = hi + after <= limit;
  float move = 0;
  if (beforeFits && afterFits) move = -before < after ? before : after;
  else if (beforeFits) move = before;
  else if (afterFits) move = after;
  LegendRect r = box;
  (vertical ? r.y0 : r.x0) += std::round(move);
  (vertical ? r.y1 : r.x1) += std::round(move);
  return r;
}

}  // namespace

LegendLayout layoutOrientation(const Camera& cam, const LegendFont& font, const LegendRect& avoid) {
  LegendLayout l;
  l.textScale = font.textScale();
  l.fontPx = font.pixelSize();
  // The view's axes in WC: the rows of the world-to-view rotation.
  const glm::dmat4& v = cam.viewWCVC;
  const glm::dvec3 right(v[0][0], v[1][0], v[2][0]), up(v[0][1], v[1][1], v[2][1]);
  const float k = float(l.textScale), inset = 4 * k, pad = 2 * k;
  const float w = float(cam.width), h = float(cam.height);
  struct Edge {
    glm::dvec3 dir;
    float ax, ay;  // where the text's box sits: 0 at the left or top, 0.5 centred, 1 at the right or bottom
  };
  const Edge edges[4] = {{-right, 0, 0.5f}, {right, 1, 0.5f}, {up, 0.5f, 0}, {-up, 0.5f, 1}};
  for (const Edge& e : edges) {
    const std::string text = orientationLetters(e.dir);
    const glm::vec2 size = font.textSize(text);
    // Whole pixels, so the atlas's texels land on pixels one to one.
    const float x0 = std::round(inset + pad + e.ax * (w - size.x - 2 * (inset + pad)));
    const float y0 = std::round(inset + pad + e.ay * (h - size.y - 2 * (inset + pad)));
    LegendRect box{x0, y0, x0 + size.x, y0 + size.y};
    const LegendRect backed{box.x0 - pad, box.y0 - pad, box.x1 + pad, box.y1 + pad};
    if (avoid.x0 < avoid.x1 && meets(backed, avoid)) {
      // Left and right letters slide up or down; top and bottom ones sideways.
      const bool vertical = e.ax != 0.5f;
      const LegendRect moved = slidClear(backed, avoid, inset, vertical, vertical ? h : w);
      box = {moved.x0 + pad, moved.y0 + pad, moved.x1 - pad, moved.y1 - pad};
    }
    LegendSwatch backing;
    backing.rect = {box.x0 - pad, box.y0 - pad, box.x1 + pad, box.y1 + pad};
    backing.fill = {0.0f, 0.0f, 0.0f, 0.55f};
    l.swatches.push_back(backing);
    l.labels.push_back({text, box});
  }
  return l;
}

void OrientationPass::run(const PassFrame& f) {
  const int textScale = legendTextScale(f.p.legend, f.cam.height);
  LegendRect panel{1, 1, 0, 0};
  if (f.p.legend.enabled)
    panel = layoutLegend(f.p.legend, legendInputs(f.p, f.ranges), f.cam, painter_.font(textScale)).panel;
  draw(f.cam, textScale, panel);
}

void OrientationPass::draw(const Camera& cam, int textScale, const LegendRect& avoid) {
  layout_ = layoutOrientation(cam, painter_.font(textScale), avoid);
  painter_.draw(cam, layout_);
}

std::span<const Attachment> OrientationPass::writes() const {
  static constexpr Attachment kWrites[] = {Attachment::Color};
  return kWrites;
}

std::unique_ptr<FramePass> makeOrientationPass(const gl::Api& gl, const gl::ShaderLibrary& lib) {
  return std::make_unique<OrientationPass>(gl, lib);
}

}  // namespace tg::render
