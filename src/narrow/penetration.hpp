// SPDX-License-Identifier: MIT
// Penetration depth of two convex polyhedra by the separating axis test over the faces of their
// Minkowski difference: the face normals of A, of B, and the cross products of the edge pairs
// whose Gauss-map arcs cross (Gregorius, "The Separating Axis Test between Convex Polyhedra",
// GDC 2013). The largest separation over these axes is the signed distance when it is <= 0,
// so its negative is the exact penetration depth (the smallest translation that separates them).
#pragma once

#include <Eigen/Core>

#include "narrow/pair_frame.hpp"
#include "sparsedyn/geometry/convex_polyhedron.hpp"

namespace sparsedyn::narrow {

/// The axis of largest separation, in A's frame: normal from A towards B, witness points on A and
/// on B with normal.dot(p_b - p_a) == separation, and the features that realise it.
struct SeparatingAxis {
  double separation = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();
  Eigen::Vector3d p_a = Eigen::Vector3d::Zero(), p_b = Eigen::Vector3d::Zero();
  FeatureId feature_a, feature_b;
};

/// O(F_A V_B + F_B V_A + E_A E_B). Positive separation means the polyhedra are disjoint (then it
/// is a lower bound of the distance, not the distance).
SeparatingAxis DeepestSeparatingAxis(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                                     const PairFrame& frame);

}  // namespace sparsedyn::narrow
