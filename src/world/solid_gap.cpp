// SPDX-License-Identifier: MIT
#include "world/solid_gap.hpp"

#include "narrow/point_features.hpp"
#include "sparsedyn/narrow/closest_features.hpp"

namespace sparsedyn {

double SolidGap(const Solid& a, const Solid& b) {
  if (a.shape == nullptr && b.shape == nullptr) {
    return (b.pose.translation - a.pose.translation).norm() - a.radius - b.radius;
  }
  if (a.shape != nullptr && b.shape != nullptr) {
    return FindClosestFeatures(*a.shape->tracked, a.pose, *b.shape->tracked, b.pose).distance;
  }
  const Solid& polyhedron = a.shape != nullptr ? a : b;
  const Solid& sphere = a.shape != nullptr ? b : a;
  return FindClosestFeatureToPoint(*polyhedron.shape->tracked, polyhedron.pose,
                                   sphere.pose.translation)
             .distance -
         sphere.radius;
}

}  // namespace sparsedyn
