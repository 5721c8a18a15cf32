#include "render/legend_layout.h"

#include <imgui.h>
#include <imgui_internal.h>  // ImDrawListSharedData: a draw list without an ImGui context

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "render/color_scalar.h"
#include "render/frame_params.h"

namespace tg::render {

struct LegendFont::Impl {
  ImFontAtlas atlas;
  ImFont* font = nullptr;
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
};

LegendFont::LegendFont(int textScale) : textScale_(std::clamp(textScale, 1, kMaxLegendTextScale)), impl_(std::make_unique<Impl>()) {
  ImFontConfig cfg;
  cfg.SizePixels = 13.0f * float(textScale_);  // ProggyClean's design size, times an integer
  // As AddFontDefault() without a template: glyphs on whole pixels, no oversampling blur.
  cfg.OversampleH = cfg.OversampleV = 1;
  cfg.PixelSnapH = true;
  impl_->font = impl_->atlas.AddFontDefault(&cfg);
  // One texture; the draw list checks text against the atlas's id.
  impl_->atlas.TexID = reinterpret_cast<ImTextureID>(std::intptr_t(1));
  impl_->atlas.GetTexDataAsAlpha8(&impl_->pixels, &impl_->width, &impl_->height);
}

LegendFont::~LegendFont() = default;

float LegendFont::pixelSize() const { return impl_->font->FontSize; }

// AddFontDefault moves ProggyClean's glyphs down by one pixel per 13, so its
// descenders reach one row below FontSize.
float LegendFont::lineHeight() const { return pixelSize() + impl_->font->ConfigData->GlyphOffset.y; }

glm::vec2 LegendFont::textSize(std::string_view text) const {
  const ImVec2 s = impl_->font->CalcTextSizeA(pixelSize(), 1e9f, 0.0f, text.data(), text.data() + text.size());
  return {s.x, lineHeight()};
}

const unsigned char* LegendFont::atlasPixels() const { return impl_->pixels; }
int LegendFont::atlasWidth() const { return impl_->width; }
int LegendFont::atlasHeight() const { return impl_->height; }

double roundLengthBelow(double x) {
  if (!(x > 0.0) || !std::isfinite(x)) return 0.0;
  const double decade = std::pow(10.0, std::floor(std::log10(x)));
  // log10 may land a hair off an exact power of ten; the steps guard both sides.
  for (const double step : {10.0, 5.0, 2.0, 1.0, 0.5})
    if (step * decade <= x * (1.0 + 1e-12)) return step * decade;
  return 0.2 * decade;
}

double pixelsPerWorldUnit(const Camera& cam) {
  if (cam.desc.projection == Projection::Orthographic) return cam.height / cam.desc.orthoHeight;
  const double d = glm::length(cam.desc.lookAtWC - cam.desc.eyeWC);
  return cam.height / (2.0 * d * std::tan(glm::radians(cam.desc.fovYDeg) * 0.5));
}

ScaleBarChoice chooseScaleBar(const Camera& cam, double glyphScale, double maxPixels) {
  ScaleBarChoice c;
  const double ppw = pixelsPerWorldUnit(cam);
  if (!(ppw > 0.0) || !std::isfinite(ppw)) return c;
  c.lengthWC = roundLengthBelow(maxPixels / ppw);
  c.pixels = c.lengthWC * ppw;
  // A glyph's semi-axis is scale * |eigenvalue|, so one lengthWC across
  // has |eigenvalue| = lengthWC / (2 scale).
  c.eigenvalue = glyphScale > 0.0 ? c.lengthWC / (2.0 * glyphScale) : 0.0;
  return c;
}

int legendTextScale(const LegendParams& p, int imageHeight) {
  if (p.textScale > 0) return std::min(p.textScale, kMaxLegendTextScale);
  return std::clamp(imageHeight / 700, 1, kMaxLegendTextScale);
}

namespace {

std::string number(double v, int digits = 3) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string withUnits(const std::string& text, const std::string& units) {
  return units.empty() ? text : text + " " + units;
}

// Stacks the panel's rows top-down in panel-local pixels, then moves all to the corner.
class Builder {
 public:
  Builder(LegendLayout& out, const LegendFont& font) : out_(out), font_(font), k_(float(font.textScale())) {}

  float k() const { return k_; }
  float y() const { return y_; }
  void skip(float dy) { y_ += dy; }
  void widen(float w) { width_ = std::max(width_, w); }
  float width() const { return width_; }

  LegendRect text(const std::string& s, float x, float y, float align) {
    const glm::vec2 size = font_.textSize(s);
    const float x0 = std::round(x - align * size.x);
    LegendRect r{x0, y, x0 + size.x, y + size.y};
    out_.labels.push_back({s, r});
    widen(r.x1);
    return r;
  }
  void line(const std::string& s) {
    text(s, 0, y_, 0);
    y_ += font_.lineHeight();
  }

 private:
  LegendLayout& out_;
  const LegendFont& font_;
  float k_;
  float y_ = 0, width_ = 0;
};

void offset(LegendRect& r, float dx, float dy) {
  r.x0 += dx, r.x1 += dx, r.y0 += dy, r.y1 += dy;
}

// The quantity, its units where it has the tensor's, and the map it is drawn on.
std::string colorTitle(const LegendInputs& in, const LegendParams& p) {
  std::string t = in.color == ColorMode::Array && !in.scalarName.empty() ? in.scalarName : colorQuantityName(in.color);
  if (colorHasTensorUnits(in.color) && !p.units.empty()) t += " [" + p.units + "]";
  if (colorIsScalar(in.color)) t += std::string(" (") + colormapName(in.colormap.value_or(defaultColormap(in.color))) + ")";
  return t;
}

// The window a bar spans when the inputs give none (LegendInputs::window).
glm::dvec2 defaultWindow(const LegendInputs& in) {
  if (in.color == ColorMode::MD) return {in.mdMin, in.mdMax};
  if (in.color == ColorMode::Sign) {
    const double m = std::max(std::abs(in.eigenMin), std::abs(in.eigenMax));
    return {-m, m};
  }
  return {0.0, 1.0};
}

// The values at a bar's ends, and its middle where that clears both ends by a character.
void tickLabels(Builder& b, const LegendFont& font, glm::dvec2 values, float barLen) {
  const float y = b.y();
  const double lo = values[0], hi = values[1];
  // Three significant digits, or as many more as tell the ends apart (up to
  // a float's 9): a window of 1 to 1.0000001 read "1 1 1".
  int digits = 3;
  while (digits < 9 && number(lo, digits) == number(hi, digits)) ++digits;
  const std::string loText = number(lo, digits), hiText = number(hi, digits), mid = number(0.5 * (lo + hi), digits);
  const LegendRect left = b.text(loText, 0, y, 0);
  const LegendRect right = b.text(hiText, barLen, y, 1);
  const float half = 0.5f * font.textSize(mid).x, gap = font.textSize(" ").x;
  if (left.x1 + gap <= 0.5f * barLen - half && 0.5f * barLen + half + gap <= right.x0 && mid != loText &&
      mid != hiText)
    b.text(mid, 0.5f * barLen, y, 0.5f);
  b.skip(font.lineHeight());
}

void colorBar(Builder& b, LegendLayout& out, const LegendParams& p, const LegendInputs& in, const LegendFont& font,
              float barLen) {
  const float k = b.k();
  // The bar is the glyphs' own map over their window (shaders/lib/color.glsl,
  // windowColor): the sign colour's is the diverging ramp over -M..M, so
  // that its ticks read the normal stress itself.
  const bool sign = in.color == ColorMode::Sign;
  const Colormap map = sign ? Colormap::Diverging : in.colormap.value_or(defaultColormap(in.color));
  const glm::dvec2 w = in.window.value_or(defaultWindow(in));
  b.line(colorTitle(in, p));
  b.skip(4 * k);
  LegendSwatch s;
  s.kind = map == Colormap::Diverging ? SwatchKind::Sign : map == Colormap::Gray ? SwatchKind::Gray : SwatchKind::Viridis;
  s.rect = {0, b.y(), barLen, b.y() + 12 * k};
  if (map == Colormap::Diverging) s.t0 = -1.0f, s.t1 = 1.0f;
  // A flat window draws the map's middle everywhere (a field of one MD).
  const bool flat = !(float(0.5 * w.y) - float(0.5 * w.x) > 0.0f);
  if (flat) s.t0 = s.t1 = 0.5f * (s.t0 + s.t1);
  out.swatches.push_back(s);
  out.hasColorBar = true;
  out.colorBar = s.rect;
  out.barValues = w;
  b.widen(barLen);
  b.skip(s.rect.height() + 5 * k);  // room for the tick marks
  const float y = b.y();
  if (flat) {
    b.text(number(w.x), 0.5f * barLen, y, 0.5f);
    b.skip(font.lineHeight());
  } else {
    tickLabels(b, font, out.barValues, barLen);
  }
  if (sign) {
    b.text("compression", 0, b.y(), 0);
    b.text("tension", barLen, b.y(), 1);
    b.skip(font.lineHeight());
  }
  if (in.windowGiven) b.line("window fixed; clamped beyond");
}

void decKey(Builder& b, LegendLayout& out, const LegendFont& font, const Camera& cam, float width,
            const LegendInputs& in) {
  const float k = b.k(), f = font.pixelSize();
  const bool weighted = in.color == ColorMode::DecFA;
  b.line(colorQuantityName(in.color));
  const float d = 56 * k, margin = 4 * k + f;
  const float cx = std::round(0.5f * std::max(width, d + 2 * margin)), cy = b.y() + margin + 0.5f * d;
  LegendSwatch s;
  s.kind = SwatchKind::DecSphere;
  s.rect = {cx - 0.5f * d, cy - 0.5f * d, cx + 0.5f * d, cy + 0.5f * d};
  out.swatches.push_back(s);
  out.hasSphere = true;
  out.sphere = s.rect;
  b.widen(2 * cx);
  const glm::dmat3 rot(cam.viewWCVC);
  for (int i = 0; i < 3; ++i) {
    glm::dvec3 e(0.0);
    e[i] = 1.0;
    glm::dvec3 pole = rot * e;
    if (pole.z < 0) pole = -pole;  // the visible pole: |e1| colours both alike
    const glm::vec2 dir(float(pole.x), float(-pole.y));
    const glm::vec2 c(cx, cy);
    LegendAxisMark m{char('x' + i), c + 0.5f * d * dir};
    out.axes.push_back(m);
    // The letter outside the sphere, along the pole; beside the pole when it faces the eye.
    const float len = glm::length(dir);
    const glm::vec2 at = len > 0.35f ? c + (0.5f * d + 2 * k + 0.5f * f) * dir / len
                                     : m.poleDC + glm::vec2(4 * k + 0.5f * f, -4 * k - 0.5f * f);
    b.text(std::string(1, m.axis), std::round(at.x), std::round(at.y - 0.5f * f), 0.5f);
  }
  b.skip(d + 2 * margin);
  // What decColor (shaders/lib/color.glsl) does: |e1| mixed with white by
  // 1 - FA. The sphere shows FA 1.
  b.line("RGB = |x|,|y|,|z| of e1");
  b.line(weighted ? "darker as FA falls: black at 0" : "paler as FA falls: white at 0");
}

// A file underlay by its file name alone: a long path would widen the panel.
// Control characters show as '?' (a newline in a file name started a second
// line over the bar), and a long name is cut between UTF-8 characters, not
// inside one.
std::string underlayTitle(const UnderlayKey& key) {
  std::string name = key.name;
  if (const std::size_t slash = name.find_last_of('/'); slash != std::string::npos && slash + 1 < name.size())
    name = name.substr(slash + 1);
  for (char& c : name)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  std::vector<std::size_t> starts;  // where characters begin: not at continuation bytes 10xxxxxx
  for (std::size_t i = 0; i < name.size(); ++i)
    if ((static_cast<unsigned char>(name[i]) & 0xC0) != 0x80) starts.push_back(i);
  constexpr std::size_t kMax = 28;
  if (starts.size() > kMax)
    name = name.substr(0, starts[kMax / 2 - 1]) + "..." + name.substr(starts[starts.size() - (kMax / 2 - 2)]);
  return "underlay: " + name;
}

// The plane's colormap over its window, as slice_plane.frag maps values.
void underlayBar(Builder& b, LegendLayout& out, const UnderlayKey& key, const LegendFont& font, float barLen) {
  const float k = b.k();
  b.line(underlayTitle(key));
  b.skip(4 * k);
  LegendSwatch s;
  s.kind = key.colormap == Colormap::Viridis ? SwatchKind::Viridis
          : key.colormap == Colormap::Diverging ? SwatchKind::Sign : SwatchKind::Gray;
  s.rect = {0, b.y(), barLen, b.y() + 12 * k};
  if (key.colormap == Colormap::Diverging) s.t0 = -1.0f, s.t1 = 1.0f;
  out.swatches.push_back(s);
  out.underlayBars.push_back(s.rect);
  out.underlayValues.emplace_back(key.lo, key.hi);
  b.widen(barLen);
  b.skip(s.rect.height() + 5 * k);
  tickLabels(b, font, out.underlayValues.back(), barLen);
}

// A world length in the positions' units: "2.28 mm", "2.28 world units".
std::string lengthText(double lengthWC, const LegendParams& p) {
  const std::string unit = p.lengthUnits.empty() ? (lengthWC == 1.0 ? "world unit" : "world units") : p.lengthUnits;
  return number(lengthWC) + " " + unit;
}

// What the bar's length means for the glyphs, under the magnitude mapping
// (tensor::mappedMagnitude, inverted) and the clamp.
std::string barMeaning(const ScaleBarChoice& c, const LegendInputs& in, const LegendParams& p) {
  const tensor::SizeMapping& s = in.sizing;
  const std::string& units = p.units;
  if (s.maxRadiusWC > 0.0 && 0.5 * c.lengthWC > s.maxRadiusWC)
    return "glyphs at most " + lengthText(2.0 * s.maxRadiusWC, p) + " across";  // the clamp
  const double mapped = c.eigenvalue;  // the mapped size f(m) whose glyph is the bar
  switch (s.magnitude) {
    case tensor::Magnitude::Linear: break;
    case tensor::Magnitude::Log: {
      const double m = s.lambda0 * std::expm1(mapped / s.lambda0);  // f(m) = l0 ln(1 + m/l0)
      if (!std::isfinite(m)) return "no glyph is this long (log sizes)";
      return withUnits("bar = glyph of eigenvalue " + number(m) + " (log sizes)", units);
    }
    case tensor::Magnitude::Shape:
      return "shape only: every glyph " + lengthText(2.0 * in.scale * s.lambda0, p) + " across";
  }
  return withUnits("bar = glyph of eigenvalue " + number(mapped), units);
}

void scaleBar(Builder& b, LegendLayout& out, const LegendParams& p, const LegendInputs& in, const Camera& cam,
              float barLen) {
  // Under a clamp, a bar no glyph can reach says little: at most the
  // clamped diameter, where that still leaves a bar to see.
  float len = barLen;
  if (const double clampPx = 2.0 * in.sizing.maxRadiusWC * pixelsPerWorldUnit(cam); clampPx >= 24.0)
    len = float(std::min(double(barLen), clampPx));
  const ScaleBarChoice c = chooseScaleBar(cam, in.scale, len);
  if (!(c.lengthWC > 0.0)) return;
  const float k = b.k();
  b.line(lengthText(c.lengthWC, p));
  b.skip(3 * k);
  out.hasScaleBar = true;
  out.scale = c;
  out.scaleBar = {0, b.y(), float(std::round(c.pixels)), b.y() + 8 * k};
  b.widen(out.scaleBar.x1);
  b.skip(out.scaleBar.height() + 3 * k);
  b.line(barMeaning(c, in, p));
}

}  // namespace

LegendLayout layoutLegend(const LegendParams& p, const LegendInputs& in, const Camera& cam, const LegendFont& font) {
  LegendLayout out;
  out.textScale = font.textScale();
  out.fontPx = font.pixelSize();
  Builder b(out, font);
  const float k = b.k();
  const float barLen = 160 * k;
  out.swatches.push_back({});  // the panel's fill, placed below
  if (p.colorKey) {
    if (in.color == ColorMode::DEC || in.color == ColorMode::DecFA) decKey(b, out, font, cam, barLen, in);
    else colorBar(b, out, p, in, font, barLen);
  }
  for (const UnderlayKey& key : in.underlays) {
    if (b.y() > 0) b.skip(8 * k);
    underlayBar(b, out, key, font, barLen);
  }
  if (p.scaleBar) {
    if (b.y() > 0) b.skip(8 * k);
    scaleBar(b, out, p, in, cam, barLen);
  }
  const float pad = 6 * k, margin = 8 * k;
  const float w = std::ceil(b.width()) + 2 * pad, h = std::ceil(b.y()) + 2 * pad;
  const bool left = p.corner == LegendCorner::TopLeft || p.corner == LegendCorner::BottomLeft;
  const bool top = p.corner == LegendCorner::TopLeft || p.corner == LegendCorner::TopRight;
  // A panel larger than the image keeps its top-left corner in view.
  const float x0 = std::max(0.0f, left ? margin : float(cam.width) - margin - w);
  const float y0 = std::max(0.0f, top ? margin : float(cam.height) - margin - h);
  out.panel = {x0, y0, x0 + w, y0 + h};
  const float dx = x0 + pad, dy = y0 + pad;
  for (std::size_t i = 1; i < out.swatches.size(); ++i) offset(out.swatches[i].rect, dx, dy);
  for (LegendLabel& l : out.labels) offset(l.rect, dx, dy);
  for (LegendAxisMark& m : out.axes) m.poleDC += glm::vec2(dx, dy);
  offset(out.colorBar, dx, dy);
  offset(out.sphere, dx, dy);
  offset(out.scaleBar, dx, dy);
  for (LegendRect& r : out.underlayBars) offset(r, dx, dy);
  out.swatches[0] = {SwatchKind::Fill, out.panel, 0, 1, glm::vec4(0.02f, 0.02f, 0.03f, 0.72f)};
  return out;
}

namespace {

constexpr ImU32 kText = IM_COL32(236, 236, 236, 255);
constexpr ImU32 kDark = IM_COL32(20, 20, 24, 255);

ImVec2 v(float x, float y) { return ImVec2(x, y); }

// A one-pixel-aligned frame of filled rectangles around r: no anti-aliased
// fringe spills into the swatch it frames.
void frame(ImDrawList& dl, const LegendRect& r, float t, ImU32 col) {
  dl.AddRectFilled(v(r.x0 - t, r.y0 - t), v(r.x1 + t, r.y0), col);
  dl.AddRectFilled(v(r.x0 - t, r.y1), v(r.x1 + t, r.y1 + t), col);
  dl.AddRectFilled(v(r.x0 - t, r.y0), v(r.x0, r.y1), col);
  dl.AddRectFilled(v(r.x1, r.y0), v(r.x1 + t, r.y1), col);
}

// A bar's frame and its tick marks at both ends and the middle.
void bar(ImDrawList& dl, const LegendRect& r, float k) {
  frame(dl, r, k, kText);
  for (const float t : {0.0f, 0.5f, 1.0f}) {
    const float x = std::clamp(std::round(r.x0 + t * r.width() - 0.5f * k), r.x0, r.x1 - k);
    dl.AddRectFilled(v(x, r.y1 + k), v(x + k, r.y1 + 4 * k), kText);
  }
}

}  // namespace

std::vector<LegendVertex> legendTriangles(const LegendLayout& layout, const LegendFont& font) {
  const ImFontAtlas& atlas = font.impl().atlas;
  ImDrawListSharedData shared;
  shared.TexUvWhitePixel = atlas.TexUvWhitePixel;
  shared.TexUvLines = atlas.TexUvLines;
  shared.Font = font.impl().font;
  shared.FontSize = font.pixelSize();
  shared.CurveTessellationTol = 1.25f;
  shared.SetCircleTessellationMaxError(0.3f);
  shared.ClipRectFullscreen = ImVec4(-1e6f, -1e6f, 1e6f, 1e6f);
  shared.InitialFlags = ImDrawListFlags_AntiAliasedLines | ImDrawListFlags_AntiAliasedFill;
  ImDrawList dl(&shared);
  dl._ResetForNewFrame();
  dl.PushTextureID(atlas.TexID);
  dl.PushClipRectFullScreen();

  const float k = float(layout.textScale);
  if (layout.hasColorBar) bar(dl, layout.colorBar, k);
  for (const LegendRect& r : layout.underlayBars) bar(dl, r, k);
  if (layout.hasSphere) {
    const LegendRect& r = layout.sphere;
    dl.AddCircle(v(0.5f * (r.x0 + r.x1), 0.5f * (r.y0 + r.y1)), 0.5f * r.width() + 0.5f * k, kText, 0, k);
    for (const LegendAxisMark& m : layout.axes) {
      dl.AddCircleFilled(v(m.poleDC.x, m.poleDC.y), 2.5f * k, kDark);
      dl.AddCircle(v(m.poleDC.x, m.poleDC.y), 2.5f * k, kText, 0, k);
    }
  }
  if (layout.hasScaleBar) {
    const LegendRect& r = layout.scaleBar;
    // The bar's full extent is its length: end stops inside it, a thinner bar between.
    const float mid = std::round(0.5f * (r.y0 + r.y1));
    dl.AddRectFilled(v(r.x0, mid - k), v(r.x1, mid + k), kText);
    dl.AddRectFilled(v(r.x0, r.y0), v(r.x0 + k, r.y1), kText);
    dl.AddRectFilled(v(r.x1 - k, r.y0), v(r.x1, r.y1), kText);
  }
  for (const LegendLabel& l : layout.labels) {
    const std::string& s = l.text;
    dl.AddText(font.impl().font, font.pixelSize(), v(l.rect.x0, l.rect.y0), kText, s.data(), s.data() + s.size());
  }

  std::vector<LegendVertex> out;
  for (const ImDrawCmd& cmd : dl.CmdBuffer) {
    for (unsigned e = 0; e < cmd.ElemCount; ++e) {
      const ImDrawVert& w = dl.VtxBuffer[int(cmd.VtxOffset + dl.IdxBuffer[int(cmd.IdxOffset + e)])];
      auto channel = [&](int shift) { return float((w.col >> shift) & 0xFFu) / 255.0f; };
      out.push_back({w.pos.x, w.pos.y, w.uv.x, w.uv.y, channel(IM_COL32_R_SHIFT), channel(IM_COL32_G_SHIFT),
                     channel(IM_COL32_B_SHIFT), channel(IM_COL32_A_SHIFT)});
    }
  }
  return out;
}

}  // namespace tg::render
