#pragma once
// Names of render choices shared by the command line and viewer scripts.
#include <optional>
#include <string>
#include <string_view>

#include "render/frame_params.h"

namespace tg::app {

inline constexpr const char* kColorModeNames = "dec, fa, md, cl, cp or sign";

inline std::optional<render::ColorMode> colorModeNamed(std::string_view c) {
  if (c == "dec") return render::ColorMode::DEC;
  if (c == "fa") return render::ColorMode::FA;
  if (c == "md") return render::ColorMode::MD;
  if (c == "cl") return render::ColorMode::CL;
  if (c == "cp") return render::ColorMode::CP;
  if (c == "sign") return render::ColorMode::Sign;
  return std::nullopt;
}

// From the kind table (render/glyph_kind.h).
inline const std::string kGlyphKindNames = render::glyphKindNames();
using render::glyphKindNamed;

}  // namespace tg::app
