// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>

#include "sparse/mover.hpp"

namespace sparsedyn {

/// When a point on x(dt) = x0 + v dt + a dt^2 / 2 (one axis) first leaves the slab [lo, hi]
/// after `min_dt`: the earliest dt >= min_dt at which it reaches `hi` moving up or `lo` moving
/// down. `direction` is set to +1 or -1. A point already outside by round-off and moving out
/// leaves at min_dt; one moving back in is not leaving. kInfinity when it never leaves.
/// (Callers pass the path's segment start as dt = 0 and the current time as min_dt, so that
/// the result does not depend on when it is computed.)
double SlabExitTime(double x0, double v, double a, double lo, double hi, double min_dt,
                    int& direction);

}  // namespace sparsedyn
