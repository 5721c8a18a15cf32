#include "render/legend/orientation_pass.h"

#include <cmath>
#include <string>

#include "view/anatomy.h"

namespace tg::render {

LegendLayout layoutOrientation(const Camera& cam, const LegendFont& font) {
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
    const LegendRect box{x0, y0, x0 + size.x, y0 + size.y};
    LegendSwatch backing;
    backing.rect = {box.x0 - pad, box.y0 - pad, box.x1 + pad, box.y1 + pad};
    backing.fill = {0.0f, 0.0f, 0.0f, 0.55f};
    l.swatches.push_back(backing);
    l.labels.push_back({text, box});
  }
  return l;
}

void OrientationPass::draw(const Camera& cam, int textScale) {
  layout_ = layoutOrientation(cam, painter_.font(textScale));
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
