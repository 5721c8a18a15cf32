// render::toUnorm8, the one rounding of every 8-bit output (PNG, TIFF, the
// viewer's screenshots, Python's 8-bit frames).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "view/frame_image.h"

using tg::render::toUnorm8;

TEST(ToUnorm8, RoundsToNearestAndClampsTheRange) {
  EXPECT_EQ(toUnorm8(0.0f), 0);
  EXPECT_EQ(toUnorm8(1.0f), 255);
  EXPECT_EQ(toUnorm8(0.5f), 128);  // 127.5 rounds up
  EXPECT_EQ(toUnorm8(1.4f / 255.0f), 1);
  EXPECT_EQ(toUnorm8(1.6f / 255.0f), 2);
  EXPECT_EQ(toUnorm8(-0.25f), 0);
  EXPECT_EQ(toUnorm8(7.0f), 255);
  EXPECT_EQ(toUnorm8(std::numeric_limits<float>::infinity()), 255);
  EXPECT_EQ(toUnorm8(-std::numeric_limits<float>::infinity()), 0);
}

// NaN has no place in [0, 1]; converting it to an integer is undefined, so
// it must never reach the cast. Evaluated as a constant, undefined behaviour
// does not compile, whatever the hardware's conversion happens to return.
static_assert(toUnorm8(std::numeric_limits<float>::quiet_NaN()) == 0);
static_assert(toUnorm8(0.5f) == 128);

TEST(ToUnorm8, NanIsBlack) {
  EXPECT_EQ(toUnorm8(std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(toUnorm8(-std::nanf("")), 0);
}
