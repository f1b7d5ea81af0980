// SPDX-License-Identifier: MIT
#include "broadphase/cell_crossing.hpp"

#include <array>

#include "math/roots.hpp"

namespace sparsedyn {
namespace {

// Earliest dt >= min_dt with x(dt) = bound while moving in `sign` direction (sign * x' > 0).
double CrossingTime(double x0, double v, double a, double bound, double sign, double min_dt) {
  if (a == 0.0) {
    if (sign * v <= 0) return kInfinity;
    return std::max(min_dt, (bound - x0) / v);
  }
  std::array<double, 2> roots{};
  const int count = SolveQuadratic(0.5 * a, v, x0 - bound, roots);
  for (int i = 0; i < count; ++i) {
    const double slope = v + a * roots[i];
    if (roots[i] >= min_dt && sign * slope > 0) return roots[i];
  }
  // Round-off: already beyond the bound at min_dt and moving further out.
  const double x = x0 + min_dt * (v + 0.5 * a * min_dt);
  if (sign * (x - bound) >= 0 && sign * (v + a * min_dt) > 0) return min_dt;
  return kInfinity;
}

}  // namespace

double SlabExitTime(double x0, double v, double a, double lo, double hi, double min_dt,
                    int& direction) {
  const double up = std::isfinite(hi) ? CrossingTime(x0, v, a, hi, +1.0, min_dt) : kInfinity;
  const double down = std::isfinite(lo) ? CrossingTime(x0, v, a, lo, -1.0, min_dt) : kInfinity;
  direction = up <= down ? +1 : -1;
  return std::min(up, down);
}

}  // namespace sparsedyn
