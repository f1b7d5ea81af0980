// SPDX-License-Identifier: MIT
#include "broadphase/cell_crossing.hpp"

#include <array>

#include "math/roots.hpp"

namespace sparsedyn {
namespace {

// Earliest dt >= 0 with x(dt) = bound while moving in `sign` direction (sign * x' > 0).
double CrossingTime(double x0, double v, double a, double bound, double sign) {
  if (a == 0.0) {
    if (sign * v <= 0) return kInfinity;
    return std::max(0.0, (bound - x0) / v);
  }
  std::array<double, 2> roots{};
  const int count = SolveQuadratic(0.5 * a, v, x0 - bound, roots);
  for (int i = 0; i < count; ++i) {
    const double slope = v + a * roots[i];
    if (roots[i] >= 0 && sign * slope > 0) return roots[i];
  }
  // Round-off: already beyond the bound and moving further out.
  if (sign * (x0 - bound) >= 0 && sign * v > 0) return 0.0;
  return kInfinity;
}

}  // namespace

double SlabExitTime(double x0, double v, double a, double lo, double hi, int& direction) {
  const double up = std::isfinite(hi) ? CrossingTime(x0, v, a, hi, +1.0) : kInfinity;
  const double down = std::isfinite(lo) ? CrossingTime(x0, v, a, lo, -1.0) : kInfinity;
  direction = up <= down ? +1 : -1;
  return std::min(up, down);
}

}  // namespace sparsedyn
