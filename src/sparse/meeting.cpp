// SPDX-License-Identifier: MIT
#include "sparse/meeting.hpp"

#include <array>
#include <cfloat>
#include <cmath>
#include <optional>

#include "math/cap_counters.hpp"
#include "math/polynomial.hpp"
#include "math/roots.hpp"
#include "math/two_sum.hpp"

namespace sparsedyn {
namespace {

// The certification steps a candidate time back (or forward) by doubling steps that start at a
// few ulps; 90 doublings cover any double range, after which we give up and fall back.
constexpr int kMaxCertifySteps = 90;

// The relative motion of b with respect to a and their summed radius polynomial, in long double
// for certification: g(dt) = |dp + dv dt + da dt^2/2|^2 - R(dt)^2 and its derivative.
struct Gap {
  long double dp[3], dv[3], da[3];
  long double r0, r1, r2;

  Gap(const Mover& a, const Mover& b, const Vec3& shift_b) {
    for (int k = 0; k < 3; ++k) {
      dp[k] = static_cast<long double>(b.p[k]) + shift_b[k] - a.p[k];
      dv[k] = static_cast<long double>(b.v[k]) - a.v[k];
      da[k] = static_cast<long double>(b.a[k]) - a.a[k];
    }
    r0 = static_cast<long double>(a.r0) + b.r0;
    r1 = static_cast<long double>(a.r1) + b.r1;
    r2 = static_cast<long double>(a.r2) + b.r2;
  }

  // Value, derivative and a bound on the rounding error of the value at dt.
  void Evaluate(long double t, long double& g, long double& dg, long double& error) const {
    long double q2 = 0, qdq = 0, scale = 0;
    for (int k = 0; k < 3; ++k) {
      const long double q = dp[k] + t * (dv[k] + 0.5L * t * da[k]);
      const long double dq = dv[k] + t * da[k];
      q2 += q * q;
      qdq += q * dq;
      scale += dp[k] * dp[k] + t * t * (dv[k] * dv[k] + 0.25L * t * t * da[k] * da[k]);
    }
    const long double r = r0 + t * (r1 + 0.5L * t * r2);
    const long double dr = r1 + t * r2;
    g = q2 - r * r;
    dg = 2 * (qdq - r * dr);
    error = 32 * LDBL_EPSILON * (scale + r0 * r0 + t * t * (r1 * r1 + 0.25L * t * t * r2 * r2));
  }
};

// Gap for straight lines at a constant reach (da = 0, r1 = r2 = 0), the hot certification of
// a gas: Gap::Evaluate's values without the terms that are then +0 (adding them changes at most
// the sign of a zero, which no comparison of the certification sees).
struct LinearGap {
  long double dp[3], dv[3];
  long double r0;

  LinearGap(const Vec3& pa, const Vec3& va, const Vec3& pb, const Vec3& vb, const Vec3& shift_b,
            double reach)
      : r0(reach) {
    for (int k = 0; k < 3; ++k) {
      dp[k] = static_cast<long double>(pb[k]) + shift_b[k] - pa[k];
      dv[k] = static_cast<long double>(vb[k]) - va[k];
    }
  }

  void Evaluate(long double t, long double& g, long double& dg, long double& error) const {
    long double q2 = 0, qdq = 0, scale = 0;
    for (int k = 0; k < 3; ++k) {
      const long double q = dp[k] + t * dv[k];
      q2 += q * q;
      qdq += q * dv[k];
      scale += dp[k] * dp[k] + t * t * (dv[k] * dv[k]);
    }
    g = q2 - r0 * r0;
    dg = 2 * qdq;
    error = 32 * LDBL_EPSILON * (scale + r0 * r0);
  }
};

// Moves `dt` back until the gap is certainly open and closing (g > error, g' < 0): then no
// meeting of these paths lies in [dt, true root), so the prediction is never late.
template <typename Function>
double CertifyNotLate(double dt, const Function& evaluate) {
  double step = std::max(std::abs(dt) * 4 * DBL_EPSILON, DBL_MIN);
  for (int i = 0; i < kMaxCertifySteps && dt > 0; ++i) {
    long double g, dg, error;
    evaluate(static_cast<long double>(dt), g, dg, error);
    if (g > error && dg < 0) return dt;
    dt -= step;
    step *= 2;
  }
  if (dt > 0) caps::Count(caps::meeting_certification);  // not certified: 0 is never late
  return std::max(dt, 0.0);
}

// Moves `dt` forward until the gap is certainly open and opening (an engagement end that is
// never early).
template <typename Function>
double CertifyNotEarly(double dt, const Function& evaluate) {
  double step = std::max(std::abs(dt) * 4 * DBL_EPSILON, DBL_MIN);
  for (int i = 0; i < kMaxCertifySteps; ++i) {
    long double g, dg, error;
    evaluate(static_cast<long double>(dt), g, dg, error);
    if (g > error && dg > 0) return dt;
    // From a root at 0 the steps start at DBL_MIN and 90 doublings reach only ~1e-281 s, still
    // inside the overlap (an early end, found by CapHits): start instead from the time the
    // gap's slope takes to clear the error bound, then double.
    if (i == 0 && dg > 0) step = std::max(step, static_cast<double>((error - g) / dg));
    dt += step;
    step *= 2;
  }
  caps::Count(caps::meeting_certification);
  return dt;
}

// f(dt) = |dp + dv dt + da dt^2/2|^2 - R(dt)^2 as a polynomial of degree <= 4 (App. F.3).
Polynomial GapPolynomial(const Vec3& dp, const Vec3& dv, const Vec3& da, double r0, double r1,
                         double r2) {
  Polynomial f;
  f.SetCoefficient(0, dp.dot(dp) - r0 * r0);
  f.SetCoefficient(1, 2 * (dp.dot(dv) - r0 * r1));
  f.SetCoefficient(2, dv.dot(dv) + dp.dot(da) - r1 * r1 - r0 * r2);
  f.SetCoefficient(3, dv.dot(da) - r1 * r2);
  f.SetCoefficient(4, 0.25 * (da.dot(da) - r2 * r2));
  return f;
}

// The first dt in (0, horizon] at which f turns: starts decreasing (f' crosses to < 0, a
// maximum) or, with `minimum`, starts increasing (a minimum). kInfinity if it never does.
double NextTurn(const Polynomial& f, double horizon, bool minimum) {
  const Polynomial df = f.Derivative();
  const Polynomial ddf = df.Derivative();
  std::array<double, 3> roots{};
  int count = 0;
  if (df.Degree() >= 3) {
    count = SolveCubic(df, roots);
  } else {
    std::array<double, 2> r2{};
    count = SolveQuadratic(df.Coefficient(2), df.Coefficient(1), df.Coefficient(0), r2);
    roots[0] = r2[0];
    roots[1] = r2[1];
  }
  for (int i = 0; i < count; ++i) {
    if (roots[i] <= 0 || roots[i] > horizon) continue;
    const double curvature = ddf(roots[i]);
    if (minimum ? curvature >= 0 : curvature < 0) return roots[i];
  }
  return kInfinity;
}

// The earliest dt in [0, horizon] with f(dt) <= 0 reached from above, for a gap polynomial f
// (Bannerman et al. 2014 for the overlapping-by-round-off start).
double EarliestEntry(const Polynomial& f, double horizon) {
  if (f(0.0) <= 0) {
    if (f.Coefficient(1) < 0) return 0.0;
    if (f.Coefficient(1) == 0 && f.Coefficient(2) < 0) return 0.0;
    const double turn = NextTurn(f, horizon, /*minimum=*/false);
    if (turn == kInfinity) return kInfinity;
    if (f(turn) <= 0) return turn;
    const std::optional<double> root = EarliestRoot(f, turn, horizon);
    return root ? *root : kInfinity;
  }
  const std::optional<double> root = EarliestRoot(f, 0.0, horizon);
  return root ? *root : kInfinity;
}

}  // namespace

double PredictMeeting(const Mover& a, const Mover& b, const Vec3& shift_b, double horizon) {
  const Vec3 dp = b.p + shift_b - a.p;
  const Vec3 dv = b.v - a.v;
  const Vec3 da = b.a - a.a;
  const double r0 = a.r0 + b.r0;
  const double r1 = a.r1 + b.r1;
  const double r2 = a.r2 + b.r2;
  if (OnStraightLines(a, b)) {
    return PredictLinearMeeting(a.p, a.v, b.p, b.v, shift_b, r0, horizon);
  }
  const double dt = EarliestEntry(GapPolynomial(dp, dv, da, r0, r1, r2), horizon);
  if (!(dt <= horizon)) return kInfinity;
  if (dt == 0.0) return 0.0;

  const Gap gap(a, b, shift_b);
  return CertifyNotLate(dt, [&gap](long double t, long double& g, long double& dg, long double& e) {
    gap.Evaluate(t, g, dg, e);
  });
}

bool CertainlyApartWithin(const Mover& a, const Mover& b, const Vec3& shift_b, double h) {
  return ApartBound(a, b).Within(shift_b, h);
}

ApartBound::ApartBound(const Mover& a, const Mover& b)
    : pa_(a.p),
      pb_(b.p),
      abs_sum_(a.p.cwiseAbs() + b.p.cwiseAbs()),
      r0_(a.r0 + b.r0),
      r1_(std::max(a.r1 + b.r1, 0.0)),
      r2_(std::max(a.r2 + b.r2, 0.0)) {
  const Vec3 dv = b.v - a.v;
  const Vec3 da = b.a - a.a;
  abs_dv_ = dv.cwiseAbs();
  abs_da_ = da.cwiseAbs();
  speed_ = dv.norm();
  acceleration_ = da.norm();
}

bool ApartBound::Within(const Vec3& shift_b, double h) const {
  if (!(h >= 0) || h == kInfinity) return false;
  const Vec3 dp = pb_ + shift_b - pa_;
  // The radii's growth over [0, h] is at most r1+ h + r2+ h^2 / 2, the distance's shrinking
  // at most |dv| h + |da| h^2 / 2 (overall, or along one axis with its components).
  const double reach = Reach(h);
  const double size = Size(shift_b, reach);
  if (Apart(dp.norm(), speed_, acceleration_, reach, size, h)) return true;
  for (int k = 0; k < 3; ++k) {
    if (Apart(std::abs(dp[k]), abs_dv_[k], abs_da_[k], reach, size, h)) return true;
  }
  return false;
}

ApartBound::SlabVerdicts ApartBound::ApartAlongEach(const std::array<Vec3, 3>& along,
                                                    const Vec3& largest_shift, double h) const {
  SlabVerdicts apart{};
  if (!(h >= 0) || h == kInfinity) return apart;
  const double reach = Reach(h);
  const double size = Size(largest_shift, reach);
  for (int k = 0; k < 3; ++k) {
    for (std::size_t s = 0; s < 3; ++s) apart[k][s] = ApartAt(k, along[s][k], reach, size, h);
  }
  return apart;
}

// CertifyLinearMeeting in doubles, for the pairs whose gap is clearly closing at the root dt (all
// but grazing ones): one evaluation of the gap g and its slope g' at dt with rigorous bounds on
// their rounding errors, then a step back along the tangent. The gap is a convex quadratic in
// time, so it lies above its tangent: g(dt - step) >= g(dt) - g'(dt) step > 0 once the step
// covers g's possible deficit, and g' only falls going back, so the gap is open and closing at
// dt - step, which is then before the first root. Returns -1 when the bounds do not allow it
// (the slope is not certainly negative, or the step would be long); the long-double
// loop then decides. u is the unit roundoff, 2^-53; the bounds are first order in u and
// multiplied by 1.01, which covers the second-order terms and the rounding of the bounds.
double CertifyLinearInDoubles(const Vec3& pa, const Vec3& va, const Vec3& pb, const Vec3& vb,
                              const Vec3& shift_b, double reach, double dt) {
  constexpr double u = DBL_EPSILON / 2;
  double q2 = 0, qdv = 0, error_q2 = 0, error_qdv = 0, size_qdv = 0;
  for (int k = 0; k < 3; ++k) {
    // The computed relative position q at dt, and a bound e on its distance from the exact one:
    // the exact rounding errors of the two sums of dp (mostly zero: neighbours' coordinates
    // are close), u |dv t| from dv's rounding carried over dt, u |dv t| from the product and
    // u |q| from the last sum. With a and b swapped, q and dv change sign and e stays, so that
    // without a shift the certified time does not depend on which of the two predicts (the
    // broad phases agree to the bit).
    const double s = pb[k] + shift_b[k];
    const double dp = s - pa[k];
    const double dv = vb[k] - va[k];
    const double q = dp + dv * dt;
    const double e =
        (std::abs(TwoSumError(pb[k], shift_b[k], s)) + std::abs(TwoSumError(s, -pa[k], dp))) +
        u * (2 * std::abs(dv * dt) + std::abs(q));
    q2 += q * q;
    qdv += q * dv;
    // |q^2 - Q^2| <= e (2 |q| + e); |q dv - Q DV| <= e |dv| + (|q| + e) u |dv|.
    error_q2 += e * (2 * std::abs(q) + e);
    error_qdv += (e + u * (std::abs(q) + e)) * std::abs(dv);
    size_qdv += std::abs(q * dv);
  }
  const double r2 = reach * reach;
  const double g = q2 - r2;
  // The squares and products, the two sums and the difference round too (3u of the sizes);
  // DBL_MIN covers what the dozen operations may lose to underflow.
  const double error_g = 1.01 * (error_q2 + 3 * u * q2 + u * r2 + u * std::abs(g)) + DBL_MIN;
  const double slope = 2 * qdv;  // g'(dt)
  const double error_slope = 2.02 * (error_qdv + 3 * u * size_qdv) + DBL_MIN;
  const double slope_high = slope + error_slope;
  if (!(slope_high < 0)) return -1.0;  // not certainly closing: a graze, or NaN
  const double deficit = error_g - g;  // how far below zero g may truly be
  if (deficit < 0) return dt;          // open and closing at dt already
  // Twice the tangent's step (for the division's rounding) and 2u dt (for the subtraction's).
  const double step = 2 * deficit / -slope_high + 2 * u * dt;
  // A step of more than 2^-30 dt means a nearly grazing pair, which the loop certifies
  // closer to its root (an event much too early costs a prediction more).
  if (!(step <= 0x1p-30 * dt)) return -1.0;
  return dt - step;
}

double CertifyLinearMeeting(const Vec3& pa, const Vec3& va, const Vec3& pb, const Vec3& vb,
                            const Vec3& shift_b, double reach, double dt) {
  const double fast = CertifyLinearInDoubles(pa, va, pb, vb, shift_b, reach, dt);
  if (fast >= 0.0) return fast;
  const LinearGap gap(pa, va, pb, vb, shift_b, reach);
  return CertifyNotLate(dt, [&gap](long double t, long double& g, long double& dg, long double& e) {
    gap.Evaluate(t, g, dg, e);
  });
}

double PredictWallMeeting(const Mover& a, const Vec3& n, double d, double horizon) {
  // s(dt) = n.p(dt) - d - R(dt) = s0 + s1 dt + s2 dt^2 / 2; meeting when s reaches 0 from above.
  const double s0 = n.dot(a.p) - d - a.r0;
  const double s1 = n.dot(a.v) - a.r1;
  const double s2 = n.dot(a.a) - a.r2;
  double dt = kInfinity;
  if (s0 <= 0) {
    if (s1 < 0 || (s1 == 0 && s2 < 0)) return 0.0;
    if (s2 >= 0) return kInfinity;
    // Moving away now but decelerating towards the plane: after the turn at -s1/s2, the larger
    // root of s (or the turn itself if still touching there).
    const double turn = -s1 / s2;
    const double s_turn = s0 + turn * (s1 + 0.5 * s2 * turn);
    if (s_turn <= 0) return turn <= horizon ? turn : kInfinity;
    std::array<double, 2> roots{};
    const int count = SolveQuadratic(0.5 * s2, s1, s0, roots);
    dt = count == 2 ? roots[1] : kInfinity;
  } else if (s2 == 0) {
    if (s1 >= 0) return kInfinity;
    dt = -s0 / s1;
  } else {
    std::array<double, 2> roots{};
    const int count = SolveQuadratic(0.5 * s2, s1, s0, roots);
    for (int i = 0; i < count; ++i) {
      if (roots[i] >= 0) {
        dt = roots[i];
        break;
      }
    }
  }
  if (!(dt <= horizon)) return kInfinity;

  // Certify in long double: the gap must be open (s > error) and closing (s' < 0).
  const long double n0 = n[0], n1 = n[1], n2 = n[2];
  const long double ls0 = n0 * a.p[0] + n1 * a.p[1] + n2 * a.p[2] - d - a.r0;
  const long double ls1 = n0 * a.v[0] + n1 * a.v[1] + n2 * a.v[2] - a.r1;
  const long double ls2 = n0 * a.a[0] + n1 * a.a[1] + n2 * a.a[2] - a.r2;
  const long double scale = std::abs(static_cast<long double>(d)) + a.p.norm() + a.r0;
  return CertifyNotLate(dt, [&](long double t, long double& g, long double& dg, long double& e) {
    g = ls0 + t * (ls1 + 0.5L * t * ls2);
    dg = ls1 + t * ls2;
    e = 16 * LDBL_EPSILON * (scale + std::abs(t * ls1) + std::abs(t * t * ls2));
  });
}

double PredictSeparation(const Mover& a, const Mover& b, const Vec3& shift_b, double horizon) {
  const Vec3 dp = b.p + shift_b - a.p;
  const Vec3 dv = b.v - a.v;
  const Vec3 da = b.a - a.a;
  const Polynomial f = GapPolynomial(dp, dv, da, a.r0 + b.r0, a.r1 + b.r1, a.r2 + b.r2);
  const double slope = f.Coefficient(1);
  if (f(0.0) > 0 && slope >= 0) return 0.0;  // Apart and opening: the engagement is over.
  // While closing, the spheres (just met, or overlapping) can only come apart after the gap's
  // next minimum; the exit is the first root of f after it.
  double start = 0.0;
  if (slope < 0 || (slope == 0 && f.Coefficient(2) < 0)) {
    start = NextTurn(f, horizon, /*minimum=*/true);
    if (start == kInfinity) return kInfinity;
    if (f(start) > 0) return start;  // They only grazed: apart again at the minimum.
  }
  const std::optional<double> root = EarliestRoot(f, start, horizon);
  if (!root) return kInfinity;
  const Gap gap(a, b, shift_b);
  return CertifyNotEarly(*root, [&gap](long double t, long double& g, long double& dg,
                                       long double& e) { gap.Evaluate(t, g, dg, e); });
}

}  // namespace sparsedyn
