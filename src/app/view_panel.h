#pragma once
// The viewer's Dear ImGui panel and mouse/keyboard handling, between
// ImGui::NewFrame and ImGui::Render. Changes go to the ViewState only; the
// viewer turns them into uniforms.
#include <cstdint>
#include <optional>
#include <string>

#include "app/pick.h"
#include "app/view_script.h"
#include "tensor/glyph.h"

namespace tg::app {

struct PanelStatus {
  double fps = 0, lastChangeUs = 0;
  std::uint64_t drawn = 0, total = 0;
  render::IterationStats newton;
  double aoRadiusWC = 0;  // the radius ambient occlusion uses (GlyphRenderer::aoRadiusWC)
  std::optional<std::string> picked;  // describePick of the last click or script pick
  std::string glyphPath = "raster";   // the session's glyph path: the kinds it draws are offered
};

struct PanelActions {
  bool screenshot = false, quit = false;
  // A click (press and release without a drag) outside the panel: the
  // framebuffer pixel under it, row 0 at the top.
  std::optional<PixelIJ> pick;
};

// `meta`: the glyph set's bounds and ranges (its records may be freed).
PanelActions drawPanel(ViewState& v, const PanelStatus& status, const tensor::GlyphSet& meta);

}  // namespace tg::app
