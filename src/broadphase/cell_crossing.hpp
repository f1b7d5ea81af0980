// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>

#include "sparse/mover.hpp"

namespace sparsedyn {

/// When a point on x(dt) = x0 + v dt + a dt^2 / 2 (one axis) first leaves the slab [lo, hi]:
/// the earliest dt >= 0 at which it reaches `hi` moving up or `lo` moving down. `direction`
/// is set to +1 or -1. A point already outside by round-off and moving out leaves now; one
/// moving back in is not leaving. kInfinity when it never leaves.
double SlabExitTime(double x0, double v, double a, double lo, double hi, int& direction);

}  // namespace sparsedyn
