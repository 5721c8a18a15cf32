#pragma once
// Names of render choices shared by the command line and viewer scripts.
#include <optional>
#include <string_view>

#include "render/renderer.h"

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

inline constexpr const char* kGlyphKindNames = "ellipsoid, superquadric, cylinder or box";

inline std::optional<render::GlyphKind> glyphKindNamed(std::string_view k) {
  if (k == "ellipsoid") return render::GlyphKind::Ellipsoid;
  if (k == "superquadric") return render::GlyphKind::Superquadric;
  if (k == "cylinder") return render::GlyphKind::Cylinder;
  if (k == "box") return render::GlyphKind::Box;
  return std::nullopt;
}

}  // namespace tg::app
