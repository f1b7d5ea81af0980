// SPDX-License-Identifier: MIT
// The 10^5-case oracle runs (RelWithDebInfo only; the sanitizer job skips *_slow_test).
#include <gtest/gtest.h>

#include "math/root_oracle.hpp"
#include "math/roots.hpp"
#include "support/fp_traps.hpp"

namespace sparsedyn {
namespace {

void RunOracleCheck(const char* name, std::uint64_t seed, int degree, int cases) {
  testing::PolynomialGenerator gen(seed);
  testing::CheckStats stats;
  for (int i = 0; i < cases && stats.failures < 10; ++i) {
    testing::CheckEarliestRoot(testing::MakeCase(gen, degree), stats);
  }
  testing::PrintStats(name, seed, stats);
  EXPECT_EQ(stats.failures, 0);
  EXPECT_LT(stats.inconclusive, cases / 100 + 1);
}

TEST(EarliestRootOracleSlow, HundredThousandQuadratics) {
  // Floating-point traps paused (docs/reliability.md): random quadratics
  // with roots beyond the double range, which SolveQuadratic rounds to infinity and drops.
  const sparsedyn::testing::FloatingPointTrapsPaused traps_paused;
  RunOracleCheck("quadratic", 7001, 2, 100000);
}
TEST(EarliestRootOracleSlow, HundredThousandQuartics) {
  RunOracleCheck("quartic", 7002, 4, 100000);
}
TEST(EarliestRootOracleSlow, TwentyFiveThousandEachOfDegrees5To8) {
  for (int degree = 5; degree <= 8; ++degree) {
    RunOracleCheck("degree5to8", 7000 + static_cast<std::uint64_t>(degree), degree, 25000);
  }
}

}  // namespace
}  // namespace sparsedyn
