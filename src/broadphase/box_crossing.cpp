// SPDX-License-Identifier: MIT
#include "broadphase/box_crossing.hpp"

#include <algorithm>
#include <cmath>

namespace sparsedyn {
namespace {

// The unit round-off of doubles: a sum, product, quotient or square root, rounded to nearest,
// is within u times its magnitude of the exact result (Higham, "Accuracy and Stability of
// Numerical Algorithms", §2.2).
constexpr double kU = 0x1.0p-53;

// At least one ulp up or down: for a value within half an ulp of an exact one, Up is >= it and
// Down <= it. The exact x + |x| 2^-52 is at least x + ulp(x) (|x| >= 2^e, ulp(x) = 2^(e-52)),
// a double, so rounding to nearest cannot fall below it; no call to nextafter (this runs six
// times per box). The absolute 1e-300 covers underflow, far below any time or length here.
double Up(double x) { return x + (std::abs(x) * 0x1.0p-52 + 1e-300); }
double Down(double x) { return x - (std::abs(x) * 0x1.0p-52 + 1e-300); }

// x raised by its bound e, no smaller than the exact sum (exactly x when e is 0).
double Raised(double x, double e) { return e == 0.0 ? x : Up(x + e); }

DtIntervals Everything() { return {{0.0, kInfinity}, {kInfinity, -kInfinity}}; }
DtIntervals Nothing() { return {}; }
DtIntervals One(double lo, double hi) {
  if (hi < 0.0 || lo > hi) return Nothing();
  return {{std::max(lo, 0.0), kInfinity}, {hi, -kInfinity}};
}

}  // namespace

DtIntervals NonNegativeSet(double A, double b, double c, double eA, double eb, double ec) {
  // For dt >= 0 each term of g = c' + b' dt + A' dt^2 with the raised coefficients is at least
  // the exact one, so {g >= 0} holds the exact set. Up() makes each raised sum no smaller than
  // the exact sum; from here on g's coefficients are taken as exact.
  A = Raised(A, eA);
  b = Raised(b, eb);
  c = Raised(c, ec);
  if (A == 0.0) {
    if (b == 0.0) return c >= 0.0 ? Everything() : Nothing();
    const double root = -c / b;  // one rounding: Up / Down are on the safe side of the exact
    return b > 0.0 ? One(Down(root), kInfinity) : One(0.0, Up(root));
  }
  // The discriminant with one rounding of 4 A c and one of the fma: within dD of the exact.
  const double p = 4.0 * A * c;
  const double D = std::fma(b, b, -p);
  const double dD = 4.0 * kU * (b * b + std::abs(p));
  // The roots (-b -+ s) / (2 A) by the stable pair q / A and c / q, q = -(b + sign(b) s) / 2
  // (no cancellation). Both move monotonically with s, and each has a relative rounding error
  // below 4u, moved outwards below.
  auto roots = [&](double s, double& r_lo, double& r_hi) {
    const double q = b >= 0.0 ? -0.5 * (b + s) : 0.5 * (s - b);
    const double r0 = q / A, r1 = q == 0.0 ? 0.0 : c / q;
    r_lo = std::min(r0, r1);
    r_hi = std::max(r0, r1);
  };
  double r_lo = 0.0, r_hi = 0.0;
  if (A > 0.0) {
    // g >= 0 outside (r_lo, r_hi); a smaller s shrinks that gap, so the lower bound of sqrt(D)
    // gives a superset, and the ends are moved inwards. No certain gap: everything.
    const double D_low = Down(D - dD);
    if (!(D_low > 0.0)) return Everything();
    roots(Down(std::sqrt(D_low)), r_lo, r_hi);
    r_lo = Up(r_lo + 4.0 * kU * std::abs(r_lo));
    r_hi = Down(r_hi - 4.0 * kU * std::abs(r_hi));
    if (r_lo >= r_hi || r_hi <= 0.0) return Everything();
    if (r_lo < 0.0) return One(r_hi, kInfinity);
    return {{0.0, r_hi}, {r_lo, kInfinity}};
  }
  // A < 0: g >= 0 on [r_lo, r_hi]; a larger s widens it, so the upper bound of sqrt(D), and
  // the ends are moved outwards. A certainly negative discriminant: nothing.
  if (D + dD < 0.0) return Nothing();
  roots(Up(std::sqrt(Up(std::max(D, 0.0) + dD))), r_lo, r_hi);
  return One(Down(r_lo - 4.0 * kU * std::abs(r_lo)), Up(r_hi + 4.0 * kU * std::abs(r_hi)));
}

BoxCrossing::BoxCrossing(const Mover& mover) : m_(mover) {
  // Each coefficient below is one or two roundings from the exact one; twice that bound.
  for (std::size_t k = 0; k < 3; ++k) {
    const int i = static_cast<int>(k);
    const double v = m_.v[i], a = m_.a[i];
    b_lo_[k] = v + m_.r1;
    b_hi_[k] = m_.r1 - v;
    A_lo_[k] = 0.5 * (a + m_.r2);
    A_hi_[k] = 0.5 * (m_.r2 - a);
    eb_lo_[k] = eb_hi_[k] = 2.0 * kU * (std::abs(v) + std::abs(m_.r1));
    eA_lo_[k] = eA_hi_[k] = kU * (std::abs(a) + std::abs(m_.r2));
  }
}

std::array<DtIntervals, 6> BoxCrossing::Sets(const Aabb& box) const {
  std::array<DtIntervals, 6> sets;
  for (std::size_t k = 0; k < 3; ++k) {
    const int i = static_cast<int>(k);
    const double p = m_.p[i], lo = box.lo[i], hi = box.hi[i];
    // x - lo + R >= 0 and hi + R - x >= 0 at dt = 0, each with two roundings.
    const double c_lo = (p - lo) + m_.r0, c_hi = (hi - p) + m_.r0;
    const double e_lo = 4.0 * kU * (std::abs(p) + std::abs(lo) + std::abs(m_.r0));
    const double e_hi = 4.0 * kU * (std::abs(p) + std::abs(hi) + std::abs(m_.r0));
    sets[2 * k] = NonNegativeSet(A_lo_[k], b_lo_[k], c_lo, eA_lo_[k], eb_lo_[k], e_lo);
    sets[2 * k + 1] = NonNegativeSet(A_hi_[k], b_hi_[k], c_hi, eA_hi_[k], eb_hi_[k], e_hi);
  }
  return sets;
}

double BoxCrossing::Entry(const Aabb& box, double horizon) const {
  const std::array<DtIntervals, 6> sets = Sets(box);
  // The intersection of closed intervals starts at the start of one of them (or at 0): the
  // earliest such start that every set holds.
  auto all_hold = [&](double dt) {
    return std::all_of(sets.begin(), sets.end(),
                       [dt](const DtIntervals& s) { return s.Holds(dt); });
  };
  if (all_hold(0.0)) return 0.0;
  double best = kInfinity;
  for (const DtIntervals& s : sets) {
    for (const double start : s.lo) {
      if (start > 0.0 && start < best && start <= horizon && all_hold(start)) best = start;
    }
  }
  return best;
}

double BoxCrossing::Exit(const Aabb& box) const {
  double exit = kInfinity;
  for (const DtIntervals& s : Sets(box)) {
    // The interval that holds 0 (its slots are disjoint and do not touch).
    const int slot =
        s.lo[0] <= 0.0 && 0.0 <= s.hi[0] ? 0 : (s.lo[1] <= 0.0 && 0.0 <= s.hi[1] ? 1 : -1);
    if (slot < 0) return 0.0;
    exit = std::min(exit, s.hi[static_cast<std::size_t>(slot)]);
  }
  return exit;
}

Aabb BoxCrossing::Swept(double horizon) const {
  // The radius at its largest over [0, horizon]: at an end, or where R' = r1 + r2 dt = 0.
  auto radius = [&](double dt) { return m_.r0 + dt * (m_.r1 + 0.5 * m_.r2 * dt); };
  auto radius_error = [&](double dt) {
    return 4.0 * kU * (std::abs(m_.r0) + dt * (std::abs(m_.r1) + 0.5 * std::abs(m_.r2) * dt));
  };
  double reach = radius(0.0) + radius_error(0.0);
  const bool grows_forever = m_.r2 > 0.0 || (m_.r2 == 0.0 && m_.r1 > 0.0);
  if (!std::isfinite(horizon) && grows_forever)
    return Aabb{Vec3::Constant(-kInfinity), Vec3::Constant(kInfinity)};
  if (std::isfinite(horizon)) reach = std::max(reach, radius(horizon) + radius_error(horizon));
  if (m_.r2 < 0.0) {
    const double top = -m_.r1 / m_.r2;
    if (top > 0.0 && top < horizon) reach = std::max(reach, radius(top) + radius_error(top));
  }
  Aabb out;
  for (int k = 0; k < 3; ++k) {
    const double p = m_.p[k], v = m_.v[k], a = m_.a[k];
    auto x = [&](double dt) { return p + dt * (v + 0.5 * a * dt); };
    auto x_error = [&](double dt) {
      return 4.0 * kU * (std::abs(p) + dt * (std::abs(v) + 0.5 * std::abs(a) * dt));
    };
    double lo = p - x_error(0.0), hi = p + x_error(0.0);
    auto offer = [&](double dt) {
      lo = std::min(lo, x(dt) - x_error(dt));
      hi = std::max(hi, x(dt) + x_error(dt));
    };
    if (std::isfinite(horizon)) offer(horizon);
    if (a != 0.0) {
      const double turn = -v / a;
      if (turn > 0.0 && turn < horizon) offer(turn);
    }
    // Open-ended: the side the path heads to is unbounded.
    if (!std::isfinite(horizon)) {
      if (a > 0.0 || (a == 0.0 && v > 0.0)) hi = kInfinity;
      if (a < 0.0 || (a == 0.0 && v < 0.0)) lo = -kInfinity;
    }
    out.lo[k] = lo - reach;
    out.hi[k] = hi + reach;
  }
  return out;
}

}  // namespace sparsedyn
