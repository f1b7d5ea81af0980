// SPDX-License-Identifier: MIT
// FastDivisor against the processor's integer division and remainder: every divisor up to 3000
// (grids have at most a few thousand cells per axis) and random ones up to 2^32 - 1, on the
// numerators where a quotient changes (multiples of d and their neighbours), the extremes and
// random ones.
#include "math/fast_divisor.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>

namespace sparsedyn {
namespace {

void ExpectExact(std::uint32_t d, std::mt19937_64& rng) {
  const FastDivisor divisor(d);
  ASSERT_EQ(divisor.Divisor(), d);
  auto check = [&](std::uint64_t n) {
    if (n > UINT32_MAX) return;
    const auto value = static_cast<std::uint32_t>(n);
    ASSERT_EQ(divisor.Divide(value), value / d) << value << " / " << d;
    ASSERT_EQ(divisor.Remainder(value), value % d) << value << " % " << d;
  };
  for (const std::uint64_t n : {0ull, 1ull, 0xffffffffull, 0xfffffffeull, 0x80000000ull}) check(n);
  // Around multiples of d, near 0 and near the top of the range.
  for (std::uint64_t k : {1ull, 2ull, 3ull, 1000ull, 0xffffffffull / d, 0xffffffffull / d - 1}) {
    for (int delta = -1; delta <= 1; ++delta) check(k * d + static_cast<std::uint64_t>(delta));
  }
  std::uniform_int_distribution<std::uint32_t> any;
  for (int i = 0; i < 200; ++i) check(any(rng));
}

TEST(FastDivisor, AgreesWithIntegerDivision) {
  std::mt19937_64 rng(20261126);
  for (std::uint32_t d = 1; d <= 3000; ++d) ExpectExact(d, rng);
  std::uniform_int_distribution<std::uint32_t> any(2, UINT32_MAX);
  for (int i = 0; i < 3000; ++i) ExpectExact(any(rng), rng);
  ExpectExact(UINT32_MAX, rng);
  ExpectExact(0x80000000u, rng);
  ExpectExact(0x80000001u, rng);
}

}  // namespace
}  // namespace sparsedyn
