// Tier 1: util::MappedArray, the storage of a field's arrays.
#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <vector>

#include "util/mapped_array.h"

using tg::util::MappedArray;

TEST(MappedArray, BehavesLikeAVector) {
  MappedArray<float> a;
  EXPECT_TRUE(a.empty());
  std::vector<float> expect;
  // Past several doublings and one mremap move at least.
  for (int i = 0; i < 300000; ++i) {
    a.push_back(float(i) * 0.5f);
    expect.push_back(float(i) * 0.5f);
  }
  EXPECT_EQ(a, expect);
  float* r = a.extend(3);
  r[0] = 1, r[1] = 2, r[2] = 3;
  expect.insert(expect.end(), {1, 2, 3});
  EXPECT_EQ(a, expect);
  a.resize(5);
  expect.resize(5);
  EXPECT_EQ(a, expect);
  a.resize(8);  // grown elements are zero, whatever the storage held before
  expect.resize(8);
  EXPECT_EQ(a, expect);
  const MappedArray<float> copy = a;
  a[0] = 42;
  EXPECT_EQ(copy, expect) << "a copy has storage of its own";
  MappedArray<float> moved = std::move(a);
  EXPECT_TRUE(a.empty());
  EXPECT_EQ(moved[0], 42);
  EXPECT_EQ((MappedArray<std::uint32_t>{2, 3}), (std::vector<std::uint32_t>{2, 3}));
  EXPECT_FALSE((MappedArray<std::uint32_t>{2, 3}) == (std::vector<std::uint32_t>{2, 4}));
}

TEST(MappedArray, ReserveKeepsContentAndCapacity) {
  MappedArray<std::uint32_t> a{7, 8, 9};
  a.reserve(1 << 20);
  EXPECT_GE(a.capacity(), std::size_t(1) << 20);
  EXPECT_EQ(a, (std::vector<std::uint32_t>{7, 8, 9}));
}

// Growth past a huge page moves the pages into an aligned region of their
// own (mremap), not a copy that could drop or shift a value.
TEST(MappedArray, GrowthAcrossHugePagesKeepsEveryValue) {
  MappedArray<std::uint32_t> a;
  a.resize(1000);
  std::iota(a.begin(), a.end(), 0u);
  for (const std::size_t n : {std::size_t(600000), std::size_t(3) << 20, std::size_t(9) << 20}) {
    const std::size_t old = a.size();
    a.reserve(n);
    EXPECT_GE(a.capacity(), n);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(a.data()) % (std::uintptr_t(2) << 20), 0u)
        << "storage of a huge page or more starts on a huge-page boundary";
    a.resize(n);
    std::iota(a.begin() + std::ptrdiff_t(old), a.end(), std::uint32_t(old));
  }
  for (std::size_t i = 0; i < a.size(); i += 4099) ASSERT_EQ(a[i], i);
  EXPECT_EQ(a[a.size() - 1], a.size() - 1);
}
