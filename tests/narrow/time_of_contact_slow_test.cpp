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
