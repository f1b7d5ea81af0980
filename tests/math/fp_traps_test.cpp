// SPDX-License-Identifier: MIT
// The floating-point traps of every test binary (tests/support/fp_traps.hpp, issue #39 part 3)
// are really on, and a test can pause them.
#include "support/fp_traps.hpp"

#include <fenv.h>
#include <gtest/gtest.h>

#include <limits>

namespace sparsedyn::testing {
namespace {

constexpr int kTrapped = FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW;

TEST(FloatingPointTraps, AreOnInEveryTestBinary) {
  const int on = fegetexcept() & kTrapped;  // as test_main_support.cpp left them
  if (on == 0 && !EnableFloatingPointTraps()) {
    GTEST_SKIP() << "this CPU cannot trap (feenableexcept fails)";
  }
  EXPECT_EQ(on, kTrapped);
}

TEST(FloatingPointTraps, AnInvalidOperationStopsTheTest) {
  if (!EnableFloatingPointTraps()) GTEST_SKIP() << "this CPU cannot trap (feenableexcept fails)";
  volatile double nan = std::numeric_limits<double>::quiet_NaN();
  volatile double one = 1.0;
  EXPECT_DEATH({ [[maybe_unused]] volatile bool less = nan < one; }, "");
}

TEST(FloatingPointTraps, PausedForAScopeAndBackAfter) {
  if (!EnableFloatingPointTraps()) GTEST_SKIP() << "this CPU cannot trap (feenableexcept fails)";
  {
    const FloatingPointTrapsPaused paused;
    EXPECT_EQ(fegetexcept() & kTrapped, 0);
    volatile double zero = 0.0;
    volatile double inf = 1.0 / zero;  // would trap
    EXPECT_GT(inf, 1.0);
  }
  EXPECT_EQ(fegetexcept() & kTrapped, kTrapped);
}

}  // namespace
}  // namespace sparsedyn::testing
