// SPDX-License-Identifier: MIT
// The contact-prediction oracle cross-check on larger samples than time_of_contact_test.cpp.
#include <gtest/gtest.h>

#include "toi_check.hpp"

namespace sparsedyn {
namespace {

TEST(TimeOfContactSlow, TwentyThousandTranslatingPairsMatchTheOracleExactly) {
  const testing::ToiFigures f =
      testing::RunPairCheck(/*seed=*/20261201, 20000, /*spin=*/0.0, /*accelerate=*/true);
  testing::ExpectNoErrors(f, "slow translating pairs", /*exact=*/true);
  const testing::ToiFigures aligned = testing::RunPairCheck(
      /*seed=*/20261202, 5000, /*spin=*/0.0, /*accelerate=*/false, /*aligned=*/true);
  testing::ExpectNoErrors(aligned, "slow aligned translating pairs", /*exact=*/true);
}

// The World's tolerance is 1e-9 x the radii: the same checks with a tolerance 1e4 times smaller.
TEST(TimeOfContactSlow, TinyToleranceKeepsTheGuarantees) {
  for (const bool aligned : {false, true}) {
    const testing::ToiFigures f =
        testing::RunPairCheck(/*seed=*/20261206, 3000, /*spin=*/0.0, /*accelerate=*/!aligned,
                              aligned, /*tolerance=*/1e-8);
    testing::ExpectNoErrors(f, aligned ? "tol 1e-8 aligned pairs" : "tol 1e-8 translating pairs",
                            /*exact=*/true);
  }
  const testing::ToiFigures f = testing::RunPairCheck(/*seed=*/20261207, 2000, /*spin=*/10.0,
                                                      /*accelerate=*/true, false, 1e-8);
  testing::ExpectNoErrors(f, "tol 1e-8 rotating pairs", /*exact=*/false);
}

TEST(TimeOfContactSlow, TenThousandRotatingPairsAreNeverLate) {
  const testing::ToiFigures f =
      testing::RunPairCheck(/*seed=*/20261203, 10000, /*spin=*/10.0, /*accelerate=*/true);
  testing::ExpectNoErrors(f, "slow rotating pairs", /*exact=*/false);
}

TEST(TimeOfContactSlow, TenThousandWallsMatchTheOracle) {
  const testing::ToiFigures still =
      testing::RunWallCheck(/*seed=*/20261204, 5000, /*spin=*/0.0, /*accelerate=*/true);
  testing::ExpectNoErrors(still, "slow translating walls", /*exact=*/true);
  const testing::ToiFigures spinning =
      testing::RunWallCheck(/*seed=*/20261205, 5000, /*spin=*/10.0, /*accelerate=*/true);
  testing::ExpectNoErrors(spinning, "slow rotating walls", /*exact=*/false);
}

}  // namespace
}  // namespace sparsedyn
