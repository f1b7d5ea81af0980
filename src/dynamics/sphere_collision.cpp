// SPDX-License-Identifier: MIT
#include "dynamics/sphere_collision.hpp"

namespace sparsedyn {

ImpulseResult SphereImpulse(const Vec3& v_a, const Vec3& v_b, double inv_mass_a, double inv_mass_b,
                            const Vec3& normal, double restitution, double elastic_below_speed) {
  ImpulseResult result{v_a, v_b, 0.0, false};
  // Relative normal velocity u = (v_b - v_a).n; approaching when u < 0.
  const double u = (v_b - v_a).dot(normal);
  if (u >= 0) return result;
  double e = restitution;
  if (-u < elastic_below_speed && e < 1.0) {
    e = 1.0;
    result.guarded = true;
  }
  // Newton's law of restitution: u' = -e u, with J along n on b and -J on a.
  const double j = -(1.0 + e) * u / (inv_mass_a + inv_mass_b);
  result.v_a = v_a - (j * inv_mass_a) * normal;
  result.v_b = v_b + (j * inv_mass_b) * normal;
  result.impulse = j;
  return result;
}

}  // namespace sparsedyn
