// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>

namespace sparsedyn::bench {

/// Enskog collision rate per particle of the hard-sphere gas (sigma = 1, kT = m = 1) at
/// `packing`, to size a benchmark's simulated stretch in collisions per particle.
inline double CollisionRate(double packing) {
  const double n = 6 * packing / M_PI;
  const double g = (1 - packing / 2) / std::pow(1 - packing, 3);
  return 4 * n * g * std::sqrt(M_PI);
}

}  // namespace sparsedyn::bench
