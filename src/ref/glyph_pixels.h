#pragma once
// How readable a frame is: how much of it the glyphs cover and how many of
// them are drawn large enough to see (docs/guide.md, "Scale and framing"). Shared by
// the framing tests and the figures docs/guide.md reports, so both count alike.
#include <cstddef>
#include <cstdint>
#include <span>

namespace tg::ref {

struct GlyphPixels {
  std::size_t pixels = 0, covered = 0;
  std::size_t visibleGlyphs = 0;  // ids with at least one pixel
  std::size_t readableGlyphs = 0;  // of those, at least kReadablePx across
  double coveredFraction() const { return pixels ? double(covered) / double(pixels) : 0.0; }
  double readableFraction() const { return visibleGlyphs ? double(readableGlyphs) / double(visibleGlyphs) : 0.0; }
};

// A glyph's width is estimated as the diameter of the disc of its visible
// pixel count: 2 sqrt(n / pi) >= 3 px means n >= 8 pixels. Area rather than
// a bounding box, so that a one-pixel needle many pixels long does not count.
inline constexpr double kReadablePx = 3.0;

// `id`: one glyph id per pixel, `empty` where no glyph is.
GlyphPixels countGlyphPixels(std::span<const std::uint32_t> id, std::uint32_t empty);

}  // namespace tg::ref
