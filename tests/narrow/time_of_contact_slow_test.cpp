// SPDX-License-Identifier: MIT
// The contact-prediction oracle cross-check on larger samples than time_of_contact_test.cpp.
#include <gtest/gtest.h>

#include "toi_check.hpp"

namespace sparsedyn {
namespace {

TEST(TimeOfContactSlow, TwentyThousandTranslatingPairsMatchTheOracleExactly) {
  const testing::ToiFigures f =
      testing::RunPairCheck(/*seed=*/20261201, 20000, /*spin=*/0.0, /*accelerate=*/true);
  f.Print("slow translating pairs");
  EXPECT_EQ(f.missed + f.late + f.mismatched + f.too_far, 0);
  const testing::ToiFigures aligned = testing::RunPairCheck(
      /*seed=*/20261202, 5000, /*spin=*/0.0, /*accelerate=*/false, /*aligned=*/true);
  aligned.Print("slow aligned translating pairs");
  EXPECT_EQ(aligned.missed + aligned.late + aligned.mismatched + aligned.too_far, 0);
}

TEST(TimeOfContactSlow, TenThousandRotatingPairsAreNeverLate) {
  const testing::ToiFigures f =
      testing::RunPairCheck(/*seed=*/20261203, 10000, /*spin=*/10.0, /*accelerate=*/true);
  f.Print("slow rotating pairs");
  EXPECT_EQ(f.missed + f.late + f.too_far, 0);
}

TEST(TimeOfContactSlow, TenThousandWallsMatchTheOracle) {
  const testing::ToiFigures still =
      testing::RunWallCheck(/*seed=*/20261204, 5000, /*spin=*/0.0, /*accelerate=*/true);
  still.Print("slow translating walls");
  EXPECT_EQ(still.missed + still.late + still.mismatched + still.too_far, 0);
  const testing::ToiFigures spinning =
      testing::RunWallCheck(/*seed=*/20261205, 5000, /*spin=*/10.0, /*accelerate=*/true);
  spinning.Print("slow rotating walls");
  EXPECT_EQ(spinning.missed + spinning.late + spinning.too_far, 0);
}

}  // namespace
}  // namespace sparsedyn
