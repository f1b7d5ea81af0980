// SPDX-License-Identifier: MIT
// A 3-vector whose components are polynomials in a time variable: the moving witness points of
// the zone-event prediction (App. K), where positions are at most quadratic in time.
#pragma once

#include <array>

#include "math/polynomial.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn::narrow {

struct PolyVec3 {
  std::array<Polynomial, 3> c;

  /// The constant vector v.
  static PolyVec3 Constant(const Vec3& v) { return Motion(v, Vec3::Zero(), Vec3::Zero()); }
  /// p + v t + a t^2 / 2.
  static PolyVec3 Motion(const Vec3& p, const Vec3& v, const Vec3& a) {
    PolyVec3 out;
    for (int i = 0; i < 3; ++i) out.c[Slot(i)] = Polynomial{p[i], v[i], 0.5 * a[i]};
    return out;
  }
  /// The constant direction u times the scalar polynomial s.
  static PolyVec3 Along(const Vec3& u, const Polynomial& s) {
    PolyVec3 out;
    for (int i = 0; i < 3; ++i) out.c[Slot(i)] = u[i] * s;
    return out;
  }

  /// The vector at time t.
  Vec3 operator()(double t) const { return {c[0](t), c[1](t), c[2](t)}; }

  friend PolyVec3 operator+(const PolyVec3& x, const PolyVec3& y) {
    PolyVec3 out;
    for (std::size_t i = 0; i < 3; ++i) out.c[i] = x.c[i] + y.c[i];
    return out;
  }
  friend PolyVec3 operator-(const PolyVec3& x, const PolyVec3& y) {
    PolyVec3 out;
    for (std::size_t i = 0; i < 3; ++i) out.c[i] = x.c[i] - y.c[i];
    return out;
  }

  static std::size_t Slot(int i) { return static_cast<std::size_t>(i); }
};

/// m . w(t) for a constant m.
inline Polynomial Dot(const Vec3& m, const PolyVec3& w) {
  return m.x() * w.c[0] + m.y() * w.c[1] + m.z() * w.c[2];
}

/// |w(t)|^2.
inline Polynomial SquaredNorm(const PolyVec3& w) {
  return w.c[0] * w.c[0] + w.c[1] * w.c[1] + w.c[2] * w.c[2];
}

}  // namespace sparsedyn::narrow
