// SPDX-License-Identifier: MIT
// The full brute-force cross-check of issue #3: 2e4 random and degenerate pairs (slow: the long
// double oracle is O(F^2 V) per overlapping pair).
#include <gtest/gtest.h>

#include "oracle_check.hpp"

namespace sparsedyn {
namespace {

TEST(ClosestFeaturesSlow, AgreesWithBruteForceOnTwentyThousandPairs) {
  const testing::OracleFigures figures = testing::RunOracleCheck(/*seed=*/20261123, 20000);
  testing::PrintFigures("slow brute-force check", figures);
  EXPECT_GE(figures.pairs, 20000);
  testing::ExpectFiguresInRange(figures);
}

}  // namespace
}  // namespace sparsedyn
