// SPDX-License-Identifier: MIT
// EventTime's rounding: NextDown against std::nextafter, and t - now <= dt as computed in
// double precision (its check). Not asserted: t <= now + dt exactly, which fails when t - now
// is itself rounded (noted on issue #2).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "world/world_impl.hpp"

namespace sparsedyn {
namespace {

TEST(EventTime, NextDownIsNextafterTowardMinusInfinity) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> values = {0.0,
                                -0.0,
                                std::numeric_limits<double>::denorm_min(),
                                -std::numeric_limits<double>::denorm_min(),
                                std::numeric_limits<double>::min(),
                                -std::numeric_limits<double>::min(),
                                1.0,
                                -1.0,
                                std::numeric_limits<double>::max(),
                                -std::numeric_limits<double>::max(),
                                inf};
  std::mt19937_64 rng(20261125);
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  std::uniform_int_distribution<int> exponent(-1074, 1023);
  for (int i = 0; i < 100000; ++i) {
    const double v = std::ldexp(mantissa(rng), exponent(rng));
    values.push_back(v);
    values.push_back(-v);
  }
  for (const double t : values) {
    const double expected = std::nextafter(t, -inf);
    const double got = NextDown(t);
    // Bit for bit (the sign of a zero result included).
    EXPECT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(expected)) << t;
  }
}

TEST(EventTime, DifferenceFromNowNeverExceedsDt) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> now(0.0, 1e6);
  std::uniform_int_distribution<int> exponent(-60, 10);
  int rounded_down = 0;
  for (int i = 0; i < 100000; ++i) {
    const double t0 = now(rng);
    const double dt = std::ldexp(1.0 + 0.5 * now(rng) / 1e6, exponent(rng));
    const double t = EventTime(t0, dt);
    EXPECT_LE(t - t0, dt) << t0 << " + " << dt;
    // Rounded down by at most one step from the nearest sum.
    const double sum = t0 + dt;
    EXPECT_TRUE(t == sum || t == std::nextafter(sum, 0.0)) << t0 << " + " << dt;
    rounded_down += t != sum;
  }
  EXPECT_GT(rounded_down, 1000);  // the rounding-down branch is exercised
  EXPECT_EQ(EventTime(1.0, std::numeric_limits<double>::infinity()),
            std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace sparsedyn
