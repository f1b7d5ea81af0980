// SPDX-License-Identifier: MIT
#pragma once

#include "sparsedyn/geometry/pose.hpp"
#include "world/shape_table.hpp"

namespace sparsedyn {

/// A body's solid at one time: a convex polyhedron (shape) or a sphere of `radius` (no shape).
struct Solid {
  const BodyShape* shape = nullptr;
  double radius = 0.0;
  Pose pose;
};

/// The signed gap of two solids (negative: overlap, by the depth the closest-feature walks
/// report), m: cold-started, for the checks (admission, validation), not the hot paths.
double SolidGap(const Solid& a, const Solid& b);

}  // namespace sparsedyn
