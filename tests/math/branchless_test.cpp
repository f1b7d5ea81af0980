// SPDX-License-Identifier: MIT
// The branch-free selects and extrema against the plain expressions they stand for, bit for bit,
// on values that include signed zeros, infinities, NaNs and subnormals.
#include "math/branchless.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "scenes/random.hpp"
#include "support/fp_traps.hpp"

namespace sparsedyn {
namespace {

std::uint64_t Bits(double x) {
  std::uint64_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

std::vector<double> Values() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::vector<double> v = {0.0,     -0.0,  1.0,          -1.0,
                           inf,     -inf,  std::nan(""), std::numeric_limits<double>::denorm_min(),
                           -1e-310, 1e308, 2.5};
  scenes::Random random(7);
  for (int i = 0; i < 200; ++i) v.push_back(random.Uniform(-10.0, 10.0));
  return v;
}

TEST(Branchless, SelectMaxMinAreThePlainExpressionsBitForBit) {
  // Floating-point traps paused (docs/reliability.md): NaN and
  // infinite operands on purpose (ordered comparisons with NaN are invalid operations).
  const sparsedyn::testing::FloatingPointTrapsPaused traps_paused;
  const std::vector<double> values = Values();
  for (const double a : values) {
    for (const double b : values) {
      EXPECT_EQ(Bits(Select(true, a, b)), Bits(a));
      EXPECT_EQ(Bits(Select(false, a, b)), Bits(b));
      EXPECT_EQ(Bits(MaxOf(a, b)), Bits(std::max(a, b))) << a << " " << b;
      EXPECT_EQ(Bits(MinOf(a, b)), Bits(a < b ? a : b)) << a << " " << b;
    }
  }
}

// SelectPointer picks like `?:`, for pointers of any alignment, null and equal ones included.
TEST(Branchless, SelectPointerIsTheConditionalExpression) {
  std::array<double, 3> values{1, 2, 3};
  const std::array<double*, 4> pointers{&values[0], &values[2], nullptr, &values[0]};
  for (double* a : pointers) {
    for (double* b : pointers) {
      EXPECT_EQ(SelectPointer(true, a, b), a);
      EXPECT_EQ(SelectPointer(false, a, b), b);
    }
  }
  char bytes[3] = {};
  EXPECT_EQ(SelectPointer(true, &bytes[1], &bytes[2]), &bytes[1]);  // odd addresses
  EXPECT_EQ(SelectPointer(false, &bytes[1], &bytes[2]), &bytes[2]);
}

// ZeroUnless keeps the index or gives 0, the largest index and kNoIndex included.
TEST(Branchless, ZeroUnlessIsTheConditionalIndex) {
  for (const std::uint32_t x : {0u, 1u, 7u, 0x7fffffffu, 0xfffffffeu, 0xffffffffu}) {
    EXPECT_EQ(ZeroUnless(true, x), x);
    EXPECT_EQ(ZeroUnless(false, x), 0u);
  }
}

TEST(Branchless, SqrtIsTheLibrarySquareRootForNonNegativeValues) {
  scenes::Random random(8);
  for (int i = 0; i < 100000; ++i) {
    const double x = std::pow(10.0, random.Uniform(-300.0, 300.0)) * random.Uniform(0.5, 1.0);
    ASSERT_EQ(Bits(SqrtOf(x)), Bits(std::sqrt(x))) << x;
  }
  for (const double x : {0.0, -0.0, std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::denorm_min()}) {
    EXPECT_EQ(Bits(SqrtOf(x)), Bits(std::sqrt(x))) << x;
  }
}

TEST(Branchless, RoundNearOneIsTheLibraryRoundBitForBit) {
  // Floating-point traps paused (docs/reliability.md): NaN and infinite
  // operands on purpose (RoundNearOne compares them).
  const sparsedyn::testing::FloatingPointTrapsPaused traps_paused;
  std::vector<double> values = Values();
  for (const double edge : {0.5, 1.5, 2.5, 1.0}) {
    for (const double x : {edge, std::nextafter(edge, 0.0), std::nextafter(edge, 10.0)}) {
      values.push_back(x);
      values.push_back(-x);
    }
  }
  scenes::Random random(9);
  for (int i = 0; i < 100000; ++i) values.push_back(random.Uniform(-2.0, 2.0));
  for (const double q : values) {
    ASSERT_EQ(Bits(RoundNearOne(q)), Bits(std::round(q))) << q;
  }
}

}  // namespace
}  // namespace sparsedyn
