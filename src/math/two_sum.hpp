// SPDX-License-Identifier: MIT
#pragma once

namespace sparsedyn {

/// The exact rounding error of `sum` = fl(a + b): a + b = sum + TwoSumError(a, b, sum) exactly
/// (Knuth's two-sum; round to nearest, no overflow). Six operations, no branch.
inline double TwoSumError(double a, double b, double sum) {
  const double b_part = sum - a;
  return (a - (sum - b_part)) + (b - b_part);
}

}  // namespace sparsedyn
