#pragma once
// A rendered frame on the CPU, in the output channels of the CLI contract.
// depth, normalWC and id are empty when only colour was read back; rgba is
// empty and rgba8 filled when only the 8-bit colour was (Channels::Rgba8).
#include <algorithm>
#include <cstdint>
#include <vector>

namespace tg::render {

// One linear colour channel as the 8 bits every 8-bit output stores: clamped
// to 0..1 and rounded. The one home of this rounding (io::toRgba8, readback).
// NaN (a pixel whose normal was zero) rounds to 0: std::clamp would pass it
// on, and converting NaN to an integer is undefined.
constexpr std::uint8_t toUnorm8(float v) {
  return static_cast<std::uint8_t>((v > 0.0f ? std::min(v, 1.0f) : 0.0f) * 255.0f + 0.5f);
}

struct FrameImage {
  int width = 0, height = 0;  // row 0 is the top row in every channel
  std::vector<float> rgba;    // 4 per pixel, linear, unclamped
  std::vector<float> depth;   // along the view axis from the eye; +inf where empty
  std::vector<float> normalWC;  // 3 per pixel; 0 where empty
  std::vector<std::uint32_t> id;  // input index; 0xFFFFFFFF where empty
  std::vector<std::uint8_t> rgba8;  // 4 per pixel, toUnorm8 of rgba
};

}  // namespace tg::render
