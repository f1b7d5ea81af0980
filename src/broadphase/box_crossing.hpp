// SPDX-License-Identifier: MIT
// When does a moving element's sphere reach an axis-aligned box, and when does it leave it
// (the static bodies' broad phase, issue #36)? The centre x(dt) = p + v dt + a dt^2/2 is within
// the box inflated by the radius R(dt) = r0 + r1 dt + r2 dt^2/2 when, along each axis k,
//   x_k - lo_k + R >= 0  and  hi_k + R - x_k >= 0,
// six quadratics in dt. Each one's set {dt >= 0 : f >= 0} is at most two intervals; their
// intersection is where the test holds. The sets are computed as supersets (coefficients
// raised by their rounding bounds, roots moved outwards by theirs, then rounded outwards), so
// an entry is never later and an exit never earlier than the exact one.
#pragma once

#include <array>
#include <cstdint>

#include "sparse/mover.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// An axis-aligned box {x : lo <= x <= hi} (closed), world frame.
struct Aabb {
  Vec3 lo = Vec3::Constant(kInfinity);
  Vec3 hi = Vec3::Constant(-kInfinity);

  bool Overlaps(const Aabb& other) const {
    return (lo.array() <= other.hi.array()).all() && (other.lo.array() <= hi.array()).all();
  }
  bool Contains(const Aabb& other) const {
    return (lo.array() <= other.lo.array()).all() && (other.hi.array() <= hi.array()).all();
  }
  void Grow(const Aabb& other) {
    lo = lo.cwiseMin(other.lo);
    hi = hi.cwiseMax(other.hi);
  }
  /// Half the surface area (the SAH cost measure); 0 for an empty box.
  double HalfArea() const {
    const Vec3 d = (hi - lo).cwiseMax(0.0);
    return d.x() * d.y() + d.y() * d.z() + d.z() * d.x();
  }
};

/// A set {dt >= 0 : f(dt) >= 0} of one quadratic, as at most two closed intervals (an empty
/// slot has lo > hi); a superset of the exact set.
struct DtIntervals {
  std::array<double, 2> lo{kInfinity, kInfinity};
  std::array<double, 2> hi{-kInfinity, -kInfinity};
  bool Holds(double dt) const {
    return (lo[0] <= dt && dt <= hi[0]) || (lo[1] <= dt && dt <= hi[1]);
  }
};

/// {dt >= 0 : c + b dt + A dt^2 >= 0}, a superset of the exact set of the polynomial whose
/// coefficients lie within [c - ec, c + ec] etc. (the caller's rounding bounds, >= 0).
DtIntervals NonNegativeSet(double A, double b, double c, double eA, double eb, double ec);

/// A mover seen against boxes: what does not depend on the box worked out once.
class BoxCrossing {
 public:
  explicit BoxCrossing(const Mover& mover);

  /// The earliest dt in [0, horizon] (horizon may be infinity) at which the centre is within
  /// `box` inflated by the radius; never later than the exact time. kInfinity if none.
  double Entry(const Aabb& box, double horizon) const;
  /// For a mover within the inflated box now: the first dt after which it is not (the end of
  /// the interval of the test's set that holds dt = 0); never earlier than the exact time.
  /// kInfinity if it stays; 0 if the test does not hold at 0.
  double Exit(const Aabb& box) const;
  /// A box that holds the centre inflated by the radius for every dt in [0, horizon]
  /// (horizon may be infinity): what any box entered within the horizon overlaps.
  Aabb Swept(double horizon) const;

 private:
  // The six sets for `box`: [2k] lower face of axis k, [2k + 1] upper face.
  std::array<DtIntervals, 6> Sets(const Aabb& box) const;

  Mover m_;
  // Per axis: the lower face's dt and dt^2 coefficients (v + r1, (a + r2) / 2), the upper
  // face's (r1 - v, (r2 - a) / 2), and their rounding bounds.
  std::array<double, 3> b_lo_, A_lo_, b_hi_, A_hi_, eb_lo_, eA_lo_, eb_hi_, eA_hi_;
};

}  // namespace sparsedyn
