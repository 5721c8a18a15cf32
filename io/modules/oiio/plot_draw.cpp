// Plot drawing with OpenImageIO's ImageBufAlgo (lines, boxes, text); part of
// the OpenImageIO module (io/core/oiio_module.h), so that only `bench` loads it.
#include "io/core/plot_panels.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace tg::io {
namespace {

namespace IBA = OIIO::ImageBufAlgo;

constexpr float kInk[3] = {0.1f, 0.1f, 0.1f};
constexpr float kGrid[3] = {0.85f, 0.85f, 0.85f};
// Plot area inside a panel: room for tick labels left and below, the title
// above and the legend on the right.
constexpr int kLeft = 78, kRight = 150, kTop = 36, kBottom = 56;

// Axis ticks at 1, 2 or 5 times a power of ten, about `n` of them.
std::vector<double> niceTicks(double lo, double hi, int n) {
  const double raw = (hi - lo) / n, mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double step = raw / mag < 1.5 ? mag : raw / mag < 3.5 ? 2 * mag : raw / mag < 7.5 ? 5 * mag : 10 * mag;
  std::vector<double> t;
  for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) t.push_back(v);
  return t;
}

std::string format(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

class Canvas {
 public:
  Canvas(int w, int h) : buf_(OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT)) {
    const float white[3] = {1, 1, 1};
    IBA::fill(buf_, white);
  }
  void line(double x0, double y0, double x1, double y1, const float* rgb) {
    IBA::render_line(buf_, int(std::lround(x0)), int(std::lround(y0)), int(std::lround(x1)), int(std::lround(y1)),
                     {rgb, 3});
  }
  void box(double x0, double y0, double x1, double y1, const float* rgb, bool fill) {
    IBA::render_box(buf_, int(std::lround(x0)), int(std::lround(y0)), int(std::lround(x1)), int(std::lround(y1)),
                    {rgb, 3}, fill);
  }
  void text(double x, double y, const std::string& s, int size, IBA::TextAlignX ax, IBA::TextAlignY ay) {
    if (!fonts_) return;
    fonts_ = IBA::render_text(buf_, int(std::lround(x)), int(std::lround(y)), s, size, "DejaVuSans", {kInk, 3}, ax, ay);
  }
  bool labelled() const { return fonts_; }
  OIIO::ImageBuf& buf() { return buf_; }

 private:
  OIIO::ImageBuf buf_;
  bool fonts_ = true;
};

void drawPanel(Canvas& c, const PlotPanel& p, int ox, int w, int h) {
  using AX = IBA::TextAlignX;
  using AY = IBA::TextAlignY;
  const double x0 = ox + kLeft, x1 = ox + w - kRight, y0 = kTop, y1 = h - kBottom;
  double xl = INFINITY, xh = -INFINITY, yl = INFINITY, yh = -INFINITY;
  for (const auto& s : p.series) {
    for (const auto& q : s.points) {
      xl = std::min(xl, q.x), xh = std::max(xh, q.x);
      if (!p.logY || q.y > 0) yl = std::min(yl, q.y), yh = std::max(yh, q.y);
    }
    for (const auto& r : s.xSpread) xl = std::min(xl, r.x), xh = std::max(xh, r.y);
  }
  if (!(xl <= xh)) xl = 0, xh = 1;
  if (xh - xl < 1e-12 * std::max(1.0, std::abs(xh))) xl -= 0.5, xh += 0.5;
  const double xpad = 0.05 * (xh - xl);
  xl -= xpad, xh += xpad;
  // Log axes span whole decades; the floor (for zeros) is the lowest one.
  if (!(yl <= yh)) yl = yh = 1.0;
  const double dl = p.logY ? std::floor(std::log10(yl)) - (yl == yh ? 1 : 0) : yl;
  const double dh = p.logY ? std::ceil(std::log10(yh)) + (yl == yh ? 1 : 0) : yh + (yh == yl ? 1 : 0);
  auto X = [&](double v) { return x0 + (v - xl) / (xh - xl) * (x1 - x0); };
  auto Y = [&](double v) {
    const double u = p.logY ? (v > 0 ? std::max(std::log10(v), dl) : dl) : v;
    return y1 - (u - dl) / (dh - dl) * (y1 - y0);
  };
  for (double t : niceTicks(xl, xh, 6)) {
    c.line(X(t), y0, X(t), y1, kGrid);
    c.text(X(t), y1 + 6, format(t), 13, AX::Center, AY::Top);
  }
  if (p.logY) {
    for (double d = dl; d <= dh + 1e-9; d += 1.0) {
      c.line(x0, Y(std::pow(10.0, d)), x1, Y(std::pow(10.0, d)), kGrid);
      const std::string label = (d == dl ? "<= 1e" : "1e") + format(d);
      c.text(x0 - 6, Y(std::pow(10.0, d)), label, 13, AX::Right, AY::Center);
    }
  } else {
    for (double t : niceTicks(dl, dh, 6)) {
      c.line(x0, Y(t), x1, Y(t), kGrid);
      c.text(x0 - 6, Y(t), format(t), 13, AX::Right, AY::Center);
    }
  }
  c.box(x0, y0, x1, y1, kInk, false);
  for (const auto& s : p.series) {
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      const double px = X(s.points[k].x), py = Y(s.points[k].y);
      c.box(px - 2, py - 2, px + 2, py + 2, s.rgb.data(), true);
      if (k > 0) c.line(X(s.points[k - 1].x), Y(s.points[k - 1].y), px, py, s.rgb.data());
      if (k < s.xSpread.size() && s.xSpread[k].y > s.xSpread[k].x) {
        // The spread: a bar with end ticks (none where there is no spread).
        const double a = X(s.xSpread[k].x), b = X(s.xSpread[k].y);
        c.line(a, py, b, py, s.rgb.data());
        c.line(a, py - 3, a, py + 3, s.rgb.data());
        c.line(b, py - 3, b, py + 3, s.rgb.data());
      }
      if (k < s.pointLabels.size()) c.text(px + 4, py - 4, s.pointLabels[k], 10, AX::Left, AY::Bottom);
      if (int(k) == s.marked) {
        c.box(px - 6, py - 6, px + 6, py + 6, kInk, false);
        c.text(px + 8, py + 4, s.markLabel, 12, AX::Left, AY::Top);
      }
    }
  }
  c.text(0.5 * (x0 + x1), y0 - 12, p.title, 15, AX::Center, AY::Baseline);
  c.text(0.5 * (x0 + x1), h - 10, p.xLabel, 14, AX::Center, AY::Baseline);
  c.text(ox + 8, y0 - 12, p.yLabel, 14, AX::Left, AY::Baseline);
  double ly = y0 + 10;
  for (const auto& s : p.series) {
    c.box(x1 + 12, ly - 5, x1 + 28, ly + 5, s.rgb.data(), true);
    c.text(x1 + 34, ly, s.label, 13, AX::Left, AY::Center);
    ly += 20;
  }
}

}  // namespace

bool drawPlot(const std::vector<PlotPanel>& panels, int w, int h, std::vector<float>& rgb) {
  Canvas c(w * int(panels.size()), h);
  for (std::size_t k = 0; k < panels.size(); ++k) drawPanel(c, panels[k], int(k) * w, w, h);
  rgb.resize(std::size_t(c.buf().spec().width) * std::size_t(h) * 3);
  c.buf().get_pixels(c.buf().roi(), OIIO::TypeDesc::FLOAT, rgb.data());
  return c.labelled();
}

}  // namespace tg::io
