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
  volatile double inf = std::numeric_limits<double>::infinity();
  EXPECT_DEATH({ [[maybe_unused]] volatile double difference = inf - inf; }, "");
  volatile double zero = 0.0;
  EXPECT_DEATH({ [[maybe_unused]] volatile double ratio = zero / zero; }, "");
}

// An ordered comparison with a quiet NaN is invalid in IEEE 754, but whether it raises the flag
// is the compiler's choice of instruction on x86-64: GCC 12 emits comisd (signalling: it
// traps), clang 14 ucomisd (quiet: it does not, unless -ffp-exception-behavior=strict). So
// under clang the traps do not see NaN comparisons (docs/reliability.md).
TEST(FloatingPointTraps, AComparisonWithNanTrapsWithGcc) {
  if (!EnableFloatingPointTraps()) GTEST_SKIP() << "this CPU cannot trap (feenableexcept fails)";
  volatile double nan = std::numeric_limits<double>::quiet_NaN();
  volatile double one = 1.0;
#if defined(__clang__)
  volatile bool less = nan < one;  // quiet: no trap, and false
  EXPECT_FALSE(less);
#else
  EXPECT_DEATH({ [[maybe_unused]] volatile bool less = nan < one; }, "");
#endif
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
