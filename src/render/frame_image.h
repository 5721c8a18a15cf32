#pragma once
// A rendered frame on the CPU, in the output channels of the CLI contract.
// depth, normalWC and id are empty when only colour was read back.
#include <cstdint>
#include <vector>

namespace tg::render {

struct FrameImage {
  int width = 0, height = 0;  // row 0 is the top row in every channel
  std::vector<float> rgba;    // 4 per pixel, linear, unclamped
  std::vector<float> depth;   // along the view axis from the eye; +inf where empty
  std::vector<float> normalWC;  // 3 per pixel; 0 where empty
  std::vector<std::uint32_t> id;  // input index; 0xFFFFFFFF where empty
};

}  // namespace tg::render
