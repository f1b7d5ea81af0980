// SPDX-License-Identifier: MIT
// The slow twin of contact prediction: the first time a distance function of time drops to a
// level, found by sampling it and bisecting. The sampling is made rigorous by a Lipschitz bound
// L (the distance changes at most L per second): a sample with d > level + L h proves that
// the distance stays above the level for the next h seconds.
#pragma once

#include <algorithm>
#include <functional>
#include <optional>

namespace sparsedyn::testing {

struct SampledFirstTime {
  std::optional<double> time;  // first time distance <= level, or none in [t0, t1]
  long samples = 0;
};

/// First time in [t0, t1] at which distance(t) <= level. Steps of (d - level) / L are rigorous;
/// below `min_step` the march takes min_step (a dip of the distance narrower than that could be
/// missed there). A crossing is bisected to an interval of width <= 1e-15 * max(1, |t|).
inline SampledFirstTime FirstTimeBelow(const std::function<double(double)>& distance,
                                       double lipschitz, double level, double t0, double t1,
                                       double min_step) {
  SampledFirstTime out;
  double t = t0;
  double d = distance(t);
  ++out.samples;
  if (d <= level) {
    out.time = t0;
    return out;
  }
  while (t < t1) {
    const double next = std::min(t1, t + std::max((d - level) / lipschitz, min_step));
    const double d_next = distance(next);
    ++out.samples;
    if (d_next <= level) {
      double lo = t, hi = next;  // d(lo) > level >= d(hi)
      while (hi - lo > 1e-15 * std::max(1.0, std::abs(hi))) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (distance(mid) <= level ? hi : lo) = mid;
        ++out.samples;
      }
      out.time = hi;
      return out;
    }
    t = next;
    d = d_next;
  }
  return out;
}

}  // namespace sparsedyn::testing
