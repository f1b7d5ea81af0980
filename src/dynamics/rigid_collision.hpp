// SPDX-License-Identifier: MIT
// Impulse response of rigid bodies at a contact (thesis §6): the contact geometry from the
// closest feature pair, and the impulse with rotation, restitution and Coulomb friction.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/geometry/pose.hpp"
#include "sparsedyn/narrow/closest_features.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// Where two touching polyhedra touch: a point (vertex-face, edge-edge, vertex-edge,
/// vertex-vertex) or a convex region (edge-face, face-face: the overlap of the two features
/// projected on the contact plane), with the normal from A towards B.
struct ContactGeometry {
  Vec3 normal = Vec3::UnitX();  // unit, world frame, from A towards B
  std::vector<Vec3> points;     // world frame: 1 point, 2 (a segment) or a convex polygon
  double distance = 0.0;        // signed distance of the features (negative = overlap)
};

/// The contact geometry of A at X_WA and B at X_WB whose closest features are `features`
/// (distance within `tolerance`: features whose distance differs from the closest by less than
/// it count as touching, which is how parallel edges and faces give a region).
ContactGeometry ContactFromFeatures(const ConvexPolyhedron& a, const Pose& X_WA,
                                    const ConvexPolyhedron& b, const Pose& X_WB,
                                    const ClosestFeatures& features, double tolerance);

/// The dynamic state of one body at the instant of a collision. A static body (a wall) has
/// inv_mass 0 and a zero inverse inertia.
struct RigidBodyState {
  Vec3 centre = Vec3::Zero();  // centre of mass, world frame
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();                       // world frame
  double inv_mass = 0.0;
  Eigen::Matrix3d inv_inertia = Eigen::Matrix3d::Zero();       // world frame
};

struct RigidImpulseOptions {
  double restitution = 1.0;          // e in [0, 1]
  double friction = 0.0;             // Coulomb coefficient mu >= 0
  double elastic_below_speed = 1e-6; // collapse guard: slower approaches are made elastic
};

struct RigidImpulseResult {
  Vec3 impulse = Vec3::Zero();   // total impulse applied to B (A receives the opposite), N s
  Vec3 point = Vec3::Zero();     // where (the impulse-weighted contact point), world frame
  double normal_impulse = 0.0;   // along the normal (>= 0)
  bool guarded = false;          // restitution raised to 1 by the collapse guard
  bool sliding = false;          // friction saturated (|j_t| = mu j_n)
  int rounds = 0;                // impulses applied (a region may need several points)
};

/// Applies the collision impulse to `a` and `b` (their velocities and angular velocities are
/// updated in place) so that no point of the contact approaches any more. Frictionless and
/// e = 1: kinetic energy, momentum and angular momentum are conserved to round-off; otherwise
/// energy never increases. Does nothing (rounds = 0) when no contact point approaches.
RigidImpulseResult ApplyRigidImpulse(RigidBodyState& a, RigidBodyState& b,
                                     const ContactGeometry& contact,
                                     const RigidImpulseOptions& options);

}  // namespace sparsedyn
