// SPDX-License-Identifier: MIT
// EventTime's rounding: NextDown against std::nextafter, and the event time as the largest
// double not after the exact sum now + dt (checked in 128-bit integers).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "math/event_time.hpp"
#include "support/fp_traps.hpp"

namespace sparsedyn {
namespace {

TEST(EventTime, NextDownIsNextafterTowardMinusInfinity) {
  // Floating-point traps paused (docs/reliability.md): the next double
  // down from -DBL_MAX is -infinity (an overflow), on purpose.
  const sparsedyn::testing::FloatingPointTrapsPaused traps_paused;
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

// Doubles in [2^-40, 2^21) as exact integers in units of 2^-92 (113 bits at most), so that
// now + dt is compared with t exactly, independently of any floating-point rounding.
__extension__ using Exact = __int128;
Exact ToExact(double x) {
  if (x == 0) return 0;
  int e = 0;
  const auto mantissa = static_cast<std::int64_t>(std::ldexp(std::frexp(x, &e), 53));
  return static_cast<Exact>(mantissa) << (e - 53 + 92);
}

// The rule EventTime used before 2026-11-25: round down only when t - now > dt in double.
double OldEventTime(double now, double dt) {
  const double t = now + dt;
  return (t - now > dt) ? NextDown(t) : t;
}

TEST(EventTime, IsTheLargestDoubleNotAfterTheExactSum) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> now_exponent(-30, 19);
  std::uniform_int_distribution<int> dt_exponent(-40, 19);
  const double inf = std::numeric_limits<double>::infinity();
  int rounded_down = 0, old_rule_late = 0;
  for (int i = 0; i < 400000; ++i) {
    const double now = i % 16 == 0 ? 0.0 : std::ldexp(1.0 + unit(rng), now_exponent(rng));
    const double dt = std::ldexp(1.0 + unit(rng), dt_exponent(rng));
    const Exact sum = ToExact(now) + ToExact(dt);
    const double t = EventTime(now, dt);
    ASSERT_LE(ToExact(t), sum) << now << " + " << dt;
    ASSERT_GT(ToExact(std::nextafter(t, inf)), sum) << now << " + " << dt;
    rounded_down += t != now + dt;
    old_rule_late += ToExact(OldEventTime(now, dt)) > sum;
  }
  EXPECT_GT(rounded_down, 10000);  // the rounding-down branch is exercised
  // The sample holds cases the old rule got wrong (one step late), so it can catch that defect.
  EXPECT_GT(old_rule_late, 0);
  EXPECT_EQ(EventTime(1.0, inf), inf);
  EXPECT_EQ(EventTime(1.0, 0.0), 1.0);
}

}  // namespace
}  // namespace sparsedyn
