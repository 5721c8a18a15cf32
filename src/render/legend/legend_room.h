#pragma once
// Room for the legend: a default camera moved (panned, and pulled back when
// panning is not enough) so that the legend's panel covers none of the
// glyphs. GL-free; the application applies it to cameras it chose, never to
// one the user gave (app/render_session.h).
#include <vector>

#include "view/camera.h"
#include "render/legend_layout.h"
#include "tensor/glyph.h"
#include "tensor/glyph_scale.h"

namespace tg::render {

// Where the glyphs lie, coarsely: the occupied cells of a grid of up to
// kRoomCells^3 over their centres, each with the largest FA, |eigenvalue|
// and ratio of a glyph's box half-diagonal to its largest semi-axis. Made once from the records (O(N)), it gives each frame the
// boxes its FA threshold and glyph size fill, without the records.
inline constexpr int kRoomCells = 16;
struct GlyphCell {
  glm::dvec3 lo, hi;  // of the centres in the cell
  float maxFa = 0;    // of the glyphs with a finite FA
  double maxAbsEigenvalue = 0;
  // |eigenvalues| / max |eigenvalue|, at most sqrt(3): every glyph kind lies
  // in the box of its semi-axes, a prolate one barely beyond its length.
  double maxReachRatio = 0;
};
std::vector<GlyphCell> glyphCells(const tensor::GlyphSet& set);

// The cells a frame draws (the FA threshold keeps a glyph there), each grown
// by how far a glyph of it can reach at `scale` and `sizing`.
std::vector<tensor::BoxWC> drawnCellBoxes(const std::vector<GlyphCell>& cells, double faMin, double scale,
                                          const tensor::SizeMapping& sizing);

// The pixel rectangle the corners of `boxes` project into (row 0 at the
// top); empty (x0 > x1) when there are none or a corner lies at or behind
// the eye.
LegendRect projectedBoxes(const Camera& cam, const std::vector<tensor::BoxWC>& boxes);

// `d` unchanged when the image of the boxes `d` shows (those whose image
// meets the picture) already clears `panel` by `gapPx`; else the camera,
// looking the same way, that shows them at the largest size not above
// today's, beside the panel or above/below it, whichever leaves them larger.
// On the image's other sides they stay within gapPx of the edge, or beyond
// it as far as `d` had them, shrunk as the picture shrinks. `depthLoWC`, `depthHiWC`: the scene box for makeCamera.
CameraDesc leaveRoom(const CameraDesc& d, int width, int height, const glm::dvec3& depthLoWC,
                     const glm::dvec3& depthHiWC, const std::vector<tensor::BoxWC>& boxes, const LegendRect& panel,
                     LegendCorner corner, float gapPx);

// leaveRoom with the panel the legend draws: laid out for `p` and `in`
// under each camera tried, since the scale bar's text depends on it.
CameraDesc frameBesideLegend(const CameraDesc& d, int width, int height, const glm::dvec3& depthLoWC,
                             const glm::dvec3& depthHiWC, const std::vector<tensor::BoxWC>& boxes,
                             const LegendParams& p, const LegendInputs& in);

}  // namespace tg::render
