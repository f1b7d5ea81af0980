// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

namespace sparsedyn {

/// The conventional method's convergence on a collision (App. I.2): `touching(lo)` is false and
/// `touching(hi)` true; halves [lo, hi] until it is no longer than `resolution` and returns the
/// final hi, the earliest time known to touch. A pair that touches and parts again inside the
/// interval may be located at either crossing: the method cannot tell. Counts evaluations.
template <typename Touching>
double BisectToTouch(double lo, double hi, double resolution, Touching&& touching,
                     std::uint64_t& evaluations) {
  while (hi - lo > resolution) {
    const double mid = lo + 0.5 * (hi - lo);
    // Round-off: an interval that cannot be split any more is as located as it can be.
    if (mid <= lo || mid >= hi) break;
    ++evaluations;
    if (touching(mid)) {
      hi = mid;
    } else {
      lo = mid;
    }
  }
  return hi;
}

}  // namespace sparsedyn
