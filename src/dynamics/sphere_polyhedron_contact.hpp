// SPDX-License-Identifier: MIT
// What the impulse of a sphere-polyhedron contact needs (issue #36): the one-point contact
// geometry from the closest feature of the polyhedron to the sphere's centre, and a solid
// sphere's body state. The impulse itself is ApplyRigidImpulse's (rigid_impulse.cpp).
#pragma once

#include <Eigen/Core>

#include "dynamics/rigid_collision.hpp"
#include "narrow/point_features.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// The contact of the polyhedron (body A) and the sphere of radius `radius` (body B) whose
/// centre is the query point of `closest` (FindClosestFeatureToPoint, or a
/// SphereContactPrediction's `closest`): the normal from the polyhedron towards the sphere,
/// one point halfway between the polyhedron's surface point and the sphere's surface point
/// along it (the centre less the radius along the normal), and the gap as the distance.
inline ContactGeometry SphereContactGeometry(const PointClosest& closest, double radius) {
  ContactGeometry contact;
  contact.normal = closest.normal;
  contact.distance = closest.distance - radius;
  contact.points = {closest.point + (0.5 * contact.distance) * closest.normal};
  return contact;
}

/// The state of a solid sphere of uniform density for ApplyRigidImpulse: inverse mass 1/m and
/// inverse inertia 5 / (2 m r^2) times the identity (I = 2/5 m r^2 about any axis through the
/// centre), in any frame. `mass` and `radius` > 0.
inline RigidBodyState SolidSphereState(const Vec3& centre, const Vec3& velocity,
                                       const Vec3& angular_velocity, double mass, double radius) {
  RigidBodyState state;
  state.centre = centre;
  state.velocity = velocity;
  state.angular_velocity = angular_velocity;
  state.inv_mass = 1.0 / mass;
  state.inv_inertia = (2.5 / (mass * radius * radius)) * Eigen::Matrix3d::Identity();
  return state;
}

}  // namespace sparsedyn
