// SPDX-License-Identifier: MIT
#include "dynamics/god_move.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "math/polynomial.hpp"
#include "math/roots.hpp"
#include "sparsedyn/assert.hpp"

namespace sparsedyn {

// One-switch moves (docs/dynamics.md, "God objects"). The first piece has acceleration a1 for
// tau1 = alpha tau, the second a2 for tau2 = (1 - alpha) tau; w is the velocity at the switch:
//   w = v + a1 tau1,   V = w + a2 tau2,   D = (v + w) tau1 / 2 + (w + V) tau2 / 2,
// so w = 2 D / tau - alpha v - (1 - alpha) V. With e = 2 D / tau - v - V and dV = V - v:
//   a1 tau1 = w - v = e + alpha dV,   a2 tau2 = V - w = -e + (1 - alpha) dV.
// |a1| <= A and |a2| <= A read, squared, with K = A^2 tau^2 - |dV|^2, E = |e|^2, s = e . dV:
//   K alpha^2 - 2 s alpha - E >= 0   and   K beta^2 + 2 s beta - E >= 0   (beta = 1 - alpha).
// For K > 0 they hold for alpha >= (s + r) / K and beta >= (-s + r) / K, r = sqrt(s^2 + K E),
// so a split exists iff 2 r <= K, i.e. K^2 - 4 E K - 4 s^2 >= 0. The least A that allows one
// has K = 2 E + 2 R, R = sqrt(E^2 + s^2) (the larger root), hence
//   m(tau)^2 tau^2 = |dV|^2 + 2 E + 2 R,
// and there r = E + R, so the split is unique: alpha = (E + R + s) / (2 (E + R)), where
// |a1| = |a2| = m. (K <= 0 means |dV| >= A tau: too short even for the velocity change.)
// Rest to rest (dV = 0, e = 2 D / tau): m = 4 |D| / tau^2, the bang-bang minimum time
// 2 sqrt(|D| / A) with alpha = 1/2 (Pontryagin: the time-optimal control of the double
// integrator along a line switches once).

namespace {

struct MoveTerms {
  Vec3 e, dv;
  double big_e, s, r;  // E = |e|^2, s = e . dV, R = sqrt(E^2 + s^2)
};

MoveTerms TermsOf(const GodMoveEnds& ends, double duration) {
  MoveTerms t;
  t.e = (2.0 / duration) * ends.displacement - ends.start_velocity - ends.end_velocity;
  t.dv = ends.end_velocity - ends.start_velocity;
  t.big_e = t.e.squaredNorm();
  t.s = t.e.dot(t.dv);
  t.r = std::hypot(t.big_e, t.s);
  return t;
}

// The feasibility polynomial in the duration tau: with u = v + V and e~ = tau e = 2 D - u tau,
//   G(tau) = K^2 tau^2 - 4 K |e~|^2 - 4 (e~ . dV)^2,   K = A^2 tau^2 - |dV|^2,
// of degree 6; a move of duration tau > |dV| / A exists iff G(tau) >= 0.
Polynomial FeasibilityPolynomial(const GodMoveEnds& ends, double max_acceleration) {
  const Vec3& d = ends.displacement;
  const Vec3 u = ends.start_velocity + ends.end_velocity;
  const Vec3 dv = ends.end_velocity - ends.start_velocity;
  const Polynomial k{-dv.squaredNorm(), 0.0, max_acceleration * max_acceleration};
  const Polynomial e_sq{4.0 * d.squaredNorm(), -4.0 * d.dot(u), u.squaredNorm()};
  const Polynomial e_dv{2.0 * d.dot(dv), -u.dot(dv)};
  const Polynomial tau_sq{0.0, 0.0, 1.0};
  return k * k * tau_sq - 4.0 * (k * e_sq) - 4.0 * (e_dv * e_dv);
}

// Within a relative 1e-13 of the bound: the closed form m(tau) is within a few ulps of the
// exact value, and a first root of G is found to about one.
constexpr double kAccelerationSlack = 1e-13;

}  // namespace

double GodMoveAcceleration(const GodMoveEnds& ends, double duration) {
  SPARSEDYN_ASSERT(duration > 0.0, "god move: duration must be > 0");
  const MoveTerms t = TermsOf(ends, duration);
  return std::sqrt(t.dv.squaredNorm() + 2.0 * t.big_e + 2.0 * t.r) / duration;
}

GodMove MakeGodMove(const GodMoveEnds& ends, double duration) {
  SPARSEDYN_ASSERT(duration > 0.0, "god move: duration must be > 0");
  const MoveTerms t = TermsOf(ends, duration);
  GodMove move;
  move.duration = duration;
  if (t.big_e == 0.0) {  // e = 0: one piece at the mean acceleration dV / tau
    move.first = t.dv / duration;
    return move;
  }
  // alpha = (E + R + s) / (2 (E + R)) and 1 - alpha = (E + R - s) / (2 (E + R)), each written
  // without cancellation: R + s = E^2 / (R - s) when s < 0, R - s = E^2 / (R + s) when s > 0.
  const double e2 = t.big_e * t.big_e;
  const double plus = t.big_e + (t.s >= 0.0 ? t.r + t.s : e2 / (t.r - t.s));
  const double minus = t.big_e + (t.s <= 0.0 ? t.r - t.s : e2 / (t.r + t.s));
  const double alpha = plus / (plus + minus);
  const double beta = minus / (plus + minus);
  move.switch_fraction = alpha;
  move.first = (t.e + alpha * t.dv) / (alpha * duration);
  move.second = (beta * t.dv - t.e) / (beta * duration);
  return move;
}

double EarliestGodMoveDuration(const GodMoveEnds& ends, double max_acceleration, double requested) {
  SPARSEDYN_ASSERT(max_acceleration > 0.0 && std::isfinite(max_acceleration),
                   "god move: max_acceleration must be finite and > 0");
  const double a = max_acceleration;
  const double d = ends.displacement.norm();
  const double u = (ends.start_velocity + ends.end_velocity).norm();
  const double dv = (ends.end_velocity - ends.start_velocity).norm();
  if (d == 0.0 && u == 0.0 && dv == 0.0) return std::max(requested, 0.0);  // at rest there
  auto feasible = [&](double tau) {
    return tau > 0.0 && GodMoveAcceleration(ends, tau) <= a * (1.0 + kAccelerationSlack);
  };

  // No move is shorter than the velocity change needs, |dV| / A, nor than the displacement
  // needs: m >= 2 |e| / tau >= 2 (2 |D| / tau - |u|) / tau, so A tau^2 + 2 |u| tau - 4 |D| >= 0,
  // tau >= 4 |D| / (sqrt(|u|^2 + 4 A |D|) + |u|); with D = 0, m >= 2 |u| / tau.
  double floor = std::max(dv / a, 4.0 * d / (std::sqrt(u * u + 4.0 * a * d) + u));
  if (d == 0.0) floor = std::max(floor, 2.0 * u / a);
  double lo = std::max(requested, floor);
  if (feasible(lo)) return lo;

  // Some later duration is feasible (m(tau) -> 0 as tau grows): bracket it.
  double hi = std::max(2.0 * lo, 1e-300);
  for (int i = 0; i < 2100 && !feasible(hi); ++i) hi *= 2.0;
  SPARSEDYN_ASSERT(feasible(hi), "god move: no feasible duration found");

  // The first root of G after lo (EarliestRoot is never late), nudged up by a few ulps where
  // rounding leaves m a hair above A; a root where G only touches 0 and turns back (a single
  // feasible instant lost to rounding) restarts the search after it.
  const Polynomial g = FeasibilityPolynomial(ends, a);
  for (int attempt = 0; attempt < 16 && lo < hi; ++attempt) {
    const std::optional<double> root = EarliestRoot(g, lo, hi);
    if (!root) break;
    double tau = std::max(*root, lo);
    for (int k = 0; k < 8; ++k, tau = std::nextafter(tau, kInfinity)) {
      if (feasible(tau)) return tau;
    }
    lo = tau;
  }
  // Bisection between an infeasible lo and the feasible hi (not reached in the tests).
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (feasible(mid) ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace sparsedyn
