#pragma once
// Names of render choices shared by the command line and viewer scripts.
#include <optional>
#include <string>
#include <string_view>

#include "render/frame_params.h"

namespace tg::app {

// The --color names, in render::ColorMode's order ("array" comes with --color-array).
inline constexpr std::string_view kColorModeList[render::kColorModeCount] = {
    "dec", "fa", "md", "cl", "cp", "sign", "vonmises", "tresca", "pressure", "s1", "s2", "s3", "trace", "decfa",
    "array"};
inline constexpr const char* kColorModeNames =
    "dec, fa, md, cl, cp, sign, vonmises, tresca, pressure, s1, s2, s3, trace, decfa or array";

inline std::optional<render::ColorMode> colorModeNamed(std::string_view c) {
  for (int k = 0; k < render::kColorModeCount; ++k)
    if (c == kColorModeList[k]) return render::ColorMode(k);
  return std::nullopt;
}

// From the kind table (render/glyph_kind.h).
inline const std::string kGlyphKindNames = render::glyphKindNames();
using render::glyphKindNamed;

}  // namespace tg::app
