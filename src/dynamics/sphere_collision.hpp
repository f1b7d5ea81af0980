// SPDX-License-Identifier: MIT
#pragma once

#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// The outcome of an impulsive collision (§6) along a contact normal.
struct ImpulseResult {
  Vec3 v_a = Vec3::Zero();   // velocities after the collision
  Vec3 v_b = Vec3::Zero();
  double impulse = 0.0;      // magnitude of the impulse applied to b along +normal (>= 0)
  bool guarded = false;      // restitution was raised to 1 by the collapse guard
};

/// Frictionless impulse between two spheres (or a sphere and a static wall when
/// inv_mass_b == 0) along unit `normal` pointing from a to b. Restitution e in [0, 1]; when the
/// approach speed is below `elastic_below_speed` the collision is made elastic, which prevents
/// inelastic collapse (infinitely many collisions in finite time; McNamara & Young 1994).
ImpulseResult SphereImpulse(const Vec3& v_a, const Vec3& v_b, double inv_mass_a,
                            double inv_mass_b, const Vec3& normal, double restitution,
                            double elastic_below_speed);

}  // namespace sparsedyn
