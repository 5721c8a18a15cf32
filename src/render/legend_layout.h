#pragma once
// The legend's content and placement, GL-free: what the legend pass
// (render/legend/legend_pass.h) draws, and what tests measure it against.
// Coordinates are DC pixels with the origin at the image's top-left corner,
// x right, y down (FrameImage rows); pixel (i, j) covers [i, i+1) x [j, j+1).
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "view/camera.h"
#include "render/legend_key.h"
#include "render/legend_params.h"
#include "tensor/glyph_scale.h"

namespace tg::render {

enum class ColorMode;

// What the glyphs were drawn with: the same numbers reach the glyph shaders
// (GlyphRenderer::upload and setParams), so the key cannot disagree with them.
struct LegendInputs {
  ColorMode color{};
  double scale = 1.0;             // world units per eigenvalue unit (FrameParams::scale)
  float mdMin = 0, mdMax = 0;     // the uMdRange uniform
  double eigenMin = 0, eigenMax = 0;  // over the glyphs: the stress range for sign
  tensor::SizeMapping sizing{};       // FrameParams::sizing: magnitude mapping and clamp
  std::vector<UnderlayKey> underlays{};  // the slice planes' underlays, as drawn (UploadedRanges)
  // The map and window the glyphs were drawn with (GlyphRenderer::legendInputs);
  // none: the mode's default map, and MD's range, 0..1 for FA, cl, cp, and
  // for sign -M..M with M the largest |eigenvalue|.
  std::optional<Colormap> colormap{};
  std::optional<glm::dvec2> window{};
  bool windowGiven = false;  // fixed by the user (--color-range): said on the legend
  std::string scalarName{};  // ColorMode::Array's quantity
};

struct LegendRect {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  float width() const { return x1 - x0; }
  float height() const { return y1 - y0; }
};

// Areas the swatch shader fills: values shaders/legend_swatch.frag reads.
enum class SwatchKind { Fill = 0, Viridis = 1, Sign = 2, DecSphere = 3, Gray = 4 };
struct LegendSwatch {
  SwatchKind kind = SwatchKind::Fill;
  LegendRect rect;
  // Bars: the colour function's argument at the rect's left and right edges
  // (viridis and gray t in 0..1; sign's normalised normal stress in -1..1).
  float t0 = 0, t1 = 1;
  glm::vec4 fill{0.0f};  // Fill: straight (not premultiplied) RGBA
};

struct LegendLabel {
  std::string text;
  LegendRect rect;  // the text's box from the font's metrics
};

// A round world length and what it shows under the camera.
struct ScaleBarChoice {
  double lengthWC = 0;    // 1, 2 or 5 x 10^k
  double pixels = 0;      // its length on screen at the look-at point's depth
  double eigenvalue = 0;  // the eigenvalue whose glyph is lengthWC across (diameter 2 S |l|)
};

// For dec: a world axis's pole on the key sphere, on the side facing the eye.
struct LegendAxisMark {
  char axis = 'x';
  glm::vec2 poleDC{0.0f};
};

struct LegendLayout {
  int textScale = 1;
  float fontPx = 13;
  LegendRect panel;
  std::vector<LegendSwatch> swatches;  // in drawing order; the panel's fill first
  std::vector<LegendLabel> labels;
  bool hasColorBar = false, hasSphere = false, hasScaleBar = false;
  LegendRect colorBar, sphere, scaleBar;
  // What the colour bar's left and right edges stand for, as labelled: the
  // window (FA, cl, cp 0..1 by default; sign -M..M in stress units).
  glm::dvec2 barValues{0.0, 1.0};
  ScaleBarChoice scale;
  std::vector<LegendAxisMark> axes;
  // One bar per underlay key, in LegendInputs::underlays' order, and the
  // values its left and right edges stand for (the window, as labelled).
  std::vector<LegendRect> underlayBars;
  std::vector<glm::dvec2> underlayValues;
};

// The largest 1, 2 or 5 x 10^k not above x; 0 for x <= 0 or not finite.
double roundLengthBelow(double x);

// Pixels per world unit on a plane facing the camera through its look-at
// point: what a world length there spans on screen.
double pixelsPerWorldUnit(const Camera& cam);

// The longest round world length that fits in maxPixels (none if even the
// image cannot show a positive length). `glyphScale`: FrameParams::scale.
ScaleBarChoice chooseScaleBar(const Camera& cam, double glyphScale, double maxPixels);

// The text scale a legend on this image uses (LegendParams::textScale, or automatic).
int legendTextScale(const LegendParams& p, int imageHeight);

// Dear ImGui's font atlas (imgui_draw.cpp): its embedded ProggyClean font,
// rasterised at 13 x textScale pixels by ImGui's font builder. Text is laid
// out and drawn from it; nothing here rasterises glyphs by hand.
class LegendFont {
 public:
  explicit LegendFont(int textScale);
  ~LegendFont();
  LegendFont(const LegendFont&) = delete;
  LegendFont& operator=(const LegendFont&) = delete;

  int textScale() const { return textScale_; }
  float pixelSize() const;
  float lineHeight() const;  // a text line's ink, descenders included
  // Width and lineHeight().
  glm::vec2 textSize(std::string_view text) const;
  // The atlas: one coverage byte per texel, row 0 at the top.
  const unsigned char* atlasPixels() const;
  int atlasWidth() const;
  int atlasHeight() const;

  struct Impl;
  const Impl& impl() const { return *impl_; }

 private:
  int textScale_;
  std::unique_ptr<Impl> impl_;
};

// Places the panel in its corner and fills it: title, colour bar or sphere,
// tick labels, the underlays' bars, scale bar. The layout depends on the camera only through
// the image size, the scale bar and the sphere's axes.
LegendLayout layoutLegend(const LegendParams& p, const LegendInputs& in, const Camera& cam, const LegendFont& font);

// Text, tick marks, outlines and the scale bar as textured triangles, built
// by ImGui's ImDrawList from the layout: 3 vertices per triangle, drawn over
// the swatches with straight alpha blending. The texture is the font atlas.
struct LegendVertex {
  float x, y, u, v;  // DC pixels; atlas coordinates
  float r, g, b, a;
};
std::vector<LegendVertex> legendTriangles(const LegendLayout& layout, const LegendFont& font);

}  // namespace tg::render
