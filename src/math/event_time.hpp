// SPDX-License-Identifier: MIT
#pragma once

#include <bit>
#include <cstdint>
#include <limits>

#include "math/two_sum.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// std::nextafter(t, -kInfinity) for t not NaN and not -kInfinity, without the library call
/// (it is on the path of every prediction): the next double below t.
inline double NextDown(double t) {
  if (t == 0.0) return -std::numeric_limits<double>::denorm_min();
  const auto bits = std::bit_cast<std::uint64_t>(t);
  return std::bit_cast<double>(t > 0 ? bits - 1 : bits + 1);
}

/// Absolute event time now + dt rounded down: the largest double not after the exact sum, so
/// that rounding never makes an event late. The rounding error of the sum is exact (Knuth's
/// two-sum); comparing t - now with dt instead misses the cases where t - now is rounded too.
inline double EventTime(double now, double dt) {
  if (dt == kInfinity) return kInfinity;
  const double t = now + dt;
  const double error = TwoSumError(now, dt, t);
  // Rounded up half the time: a select, not a branch the predictor would miss half the time.
  // A negative error means the exact sum is not zero, so t = 0 (NextDown's special case) can
  // only come with error >= 0 and the bit step below is NextDown's for t != 0.
  const auto bits = std::bit_cast<std::uint64_t>(t);
  const std::uint64_t down = t > 0 ? bits - 1 : bits + 1;
  return std::bit_cast<double>(error < 0 ? down : bits);
}

}  // namespace sparsedyn
