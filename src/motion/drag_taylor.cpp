// SPDX-License-Identifier: MIT
#include "motion/drag_taylor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sparsedyn/assert.hpp"

namespace sparsedyn {

namespace {

constexpr int kN = kDragTaylorOrder;

double RoundedDown(double x) { return x * (1.0 - 0x1p-40); }

// The largest step sigma = q rho for deviation bound r and the tail tolerance: the tail is
// r q^(n+1) / (1 - q) (EvaluateDragTaylor), so q = (tolerance (1 - q_max) / r)^(1/(n+1)),
// capped at q_max. pow's own error only moves the step; the tail is bounded again from the
// step actually taken.
double StepShare(double r, double tolerance) {
  const double q = std::pow(tolerance * (1.0 - kDragTaylorMaxShare) / r, 1.0 / (kN + 1));
  return std::min(q, kDragTaylorMaxShare);
}

}  // namespace

// The Cauchy estimate (Hille, "Ordinary Differential Equations in the Complex Domain", 1976,
// §2.3; Cauchy's majorant method). Let s0 = |V| > 0 and D_r = {v in C^3 : ||v - V|| <= r}
// (Hermitian norm) with r <= 0.4 s0. Extend |v| to S(v) = sqrt(v . v) (principal root, v . v
// the bilinear product): on D_r, v . v = s0^2 + 2 V . w + w . w with ||w|| <= r lies in the
// disc about s0^2 of radius 2 s0 r + r^2 <= 0.96 s0^2, away from the cut (-inf, 0], so f is
// analytic there, with |S| <= ||v|| <= s0 + r. Hence F = sup ||f|| on D_r is at most
//   F1 = |g| + c1 (s0 + r) + c2 (s0 + r)^2,
// and for r <= s0 / 4 also at most F2 = ||f(V)|| + L r, with the Lipschitz constant
// L = sup ||Df|| <= c1 + c2 (|S| + ||v||^2 / |S|) (||v v^T|| <= ||v||^2), where now
// |S| >= sqrt(s0^2 - 2 s0 r - r^2) >= 0.6614 s0, so L <= c1 + c2 s0 (1.25 + 1.5625 / 0.6614)
// < c1 + 3.625 c2 s0. Then the solution from V exists and is analytic on |tau| <= rho < r / F
// with ||u(tau) - V|| <= F |tau| <= r, and Cauchy's estimate bounds its Taylor coefficients:
// ||c_m|| <= r / rho^m for m >= 1. For real 0 <= sigma = q rho the velocity tail beyond degree
// n is at most r q^(n+1) / (1 - q), the position tail (coefficients c_m / (m + 1)) at most
// sigma r q^(n+1) / ((n + 2)(1 - q)). Three discs are tried: r = 0.4 s0 with F1 (the widest,
// best at low speed where F ~ |g|), r = s0 / 4 with min(F1, F2), and, near terminal velocity
// where ||f(V)|| is small, the r that maximizes h = q rho with F2: d/dr of r^(n/(n+1)) /
// (||f|| + L r) vanishes at r = 16 ||f(V)|| / L; there the tail scales with r while rho stays
// near 1 / L, so q may reach q_max.
DragTaylorPlan PlanDragTaylorStep(const DragModel& model, const Vec3& v, double accel_bound,
                                  double tolerance) {
  DragTaylorPlan best;
  const double s_mid = v.norm();  // within 2.6 u relative of |v|
  const double s_lo = RoundedDown(s_mid * (1.0 - 4.0 * kUnitRoundoff));
  const double s_hi = RoundedUp(s_mid * (1.0 + 4.0 * kUnitRoundoff));
  if (!(s_lo > 0.0) || !(tolerance > 0.0)) return best;
  const double g_norm = RoundedUp(model.g.norm());
  const double lipschitz = RoundedUp(model.c1 + 3.625 * model.c2 * s_hi);
  const double r_widest = RoundedDown(0.4 * s_lo);
  const double r_wide = RoundedDown(0.25 * s_lo);
  const double r_narrow = std::min(r_wide, RoundedDown(16.0 * accel_bound / lipschitz));
  for (const double r : {r_widest, r_wide, r_narrow}) {
    if (!(r > 0.0)) continue;
    const double speed = s_hi + r;
    double f_bound = RoundedUp(g_norm + model.c1 * speed + model.c2 * speed * speed);
    if (r <= r_wide) f_bound = std::min(f_bound, RoundedUp(accel_bound + lipschitz * r));
    const double rho = RoundedDown(r / f_bound);
    const double length = StepShare(r, tolerance) * rho;
    if (length > best.length) best = DragTaylorPlan{r, rho, length};
  }
  return best;
}

// Taylor coefficients of the exact solution by automatic differentiation (Moore, "Interval
// Analysis", 1966, ch. 11; Griewank & Walther, "Evaluating Derivatives", §13.2):
//   q = v . v:   q_m = sum_j v_j . v_(m-j)
//   s = sqrt(q): s_0 = |V|,  s_m = (q_m - sum_{j=1}^{m-1} s_j s_(m-j)) / (2 s_0)
//   w = s v:     w_m = sum_j s_j v_(m-j)
//   v' = f(v):   v_(m+1) = ([m = 0] g - c1 v_m - c2 w_m) / (m + 1)
// Every sum is a BallSum (rounding_bounds.hpp) written out lane by lane, so each coefficient
// comes with a certified radius. A coefficient is packed as (v_x, v_y, v_z, s) in one Array4d
// (two SSE2 operations per step; each lane rounds as a scalar would, so the bounds are those
// of scalar code). The sum for s_m uses the symmetry j <-> m - j (a doubled term is exact) and
// the sign (1, 1, 1, -1): 2 v_0 . v_m + sum_{j=1}^{m-1} (v_j . v_(m-j) - s_j s_(m-j)) with the
// lane s_m still 0 when the j = 0 term is added; its four lanes are added at the end (4 k
// terms in all).
DragTaylorSeries DragTaylorSeriesAt(const DragModel& model, const Vec3& v,
                                    const DragTaylorPlan& plan) {
  using Lanes = Eigen::Array4d;
  DragTaylorSeries series;
  series.plan = plan;
  std::array<Lanes, kN + 1> c, cr, cm;  // mid, radius, |mid| + radius
  BallSum q0;
  for (int i = 0; i < 3; ++i) q0.AddExact(v[i], v[i], 0.0);
  const Ball s0 = SquareRoot(q0.Result());
  SPARSEDYN_ASSERT(s0.mid > s0.rad, "drag Taylor step from a velocity of about zero");
  c[0] = Lanes(v.x(), v.y(), v.z(), s0.mid);
  cr[0] = Lanes(0.0, 0.0, 0.0, s0.rad);
  cm[0] = c[0].abs() + cr[0];
  const Ball two_s0{2.0 * s0.mid, 2.0 * s0.rad};
  const Lanes sign(1.0, 1.0, 1.0, -1.0);
  const Lanes g(model.g.x(), model.g.y(), model.g.z(), 0.0);
  for (int m = 0; m < kN; ++m) {
    if (m > 0) {
      Lanes n_mid = Lanes::Zero(), n_abs = Lanes::Zero(), n_rad = Lanes::Zero();
      int terms = 0;
      for (int j = 0; 2 * j <= m; ++j) {
        const double weight = 2 * j == m ? 1.0 : 2.0;  // exact
        const Lanes a = (weight * c[j]) * sign, a_rad = weight * cr[j];
        const Lanes product = a * c[m - j];
        n_mid += product;
        n_abs += product.abs();
        n_rad += a.abs() * cr[m - j] + a_rad * cm[m - j];
        terms += 4;
      }
      const BallSum n{n_mid.sum(), n_abs.sum(), n_rad.sum(), terms};
      const Ball s_m = DividedBy(n.Result(), two_s0);
      c[m][3] = s_m.mid;
      cr[m][3] = s_m.rad;
      cm[m][3] = std::abs(s_m.mid) + s_m.rad;
    }
    // w_m = sum_j s_j v_(m-j) in lanes 0..2 (lane 3 is not used).
    Lanes w_mid = Lanes::Zero(), w_abs = Lanes::Zero(), w_rad = Lanes::Zero();
    for (int j = 0; j <= m; ++j) {
      const double a = c[j][3], a_abs = std::abs(a), a_rad = cr[j][3];
      const Lanes product = a * c[m - j];
      w_mid += product;
      w_abs += product.abs();
      w_rad += a_abs * cr[m - j] + a_rad * cm[m - j];
    }
    const Lanes w_radius = (w_rad + (1.02 * Gamma(m + 1)) * w_abs) * (1.0 + 0x1p-40) +
                           std::numeric_limits<double>::min();
    // v_(m+1): the BallSum of [m = 0] g, -c1 v_m and -c2 w_m (three terms), divided by m + 1.
    const Lanes g_term = m == 0 ? g : Lanes::Zero();
    const Lanes rhs_mid = g_term - model.c1 * c[m] - model.c2 * w_mid;
    const Lanes rhs_abs = g_term.abs() + (model.c1 * c[m]).abs() + (model.c2 * w_mid).abs();
    const Lanes rhs_rad = model.c1 * cr[m] + model.c2 * w_radius;
    const Lanes rhs_radius = (rhs_rad + (1.02 * Gamma(3)) * rhs_abs) * (1.0 + 0x1p-40) +
                             std::numeric_limits<double>::min();
    const double k = m + 1.0;
    c[m + 1] = rhs_mid / k;
    cr[m + 1] = (rhs_radius / k + kUnitRoundoff * c[m + 1].abs()) * (1.0 + 0x1p-40) +
                std::numeric_limits<double>::min();
    c[m + 1][3] = 0.0;  // s_(m+1), set at the next m
    cr[m + 1][3] = 0.0;
    cm[m + 1] = c[m + 1].abs() + cr[m + 1];
  }
  for (int m = 0; m <= kN; ++m) {
    series.mid[m] = Vec3(c[m][0], c[m][1], c[m][2]);
    series.rad[m] = Vec3(cr[m][0], cr[m][1], cr[m][2]);
  }
  // What the evaluation needs: position coefficients c_m / (m + 1) (radius rad / (m + 1) plus
  // the rounding of the quotient) and the norms of all of them.
  for (int m = 0; m <= kN; ++m) {
    series.position_mid[m] = series.mid[m] / (m + 1.0);
    series.mid_norm[m] = series.mid[m].norm();
    series.rad_norm[m] = RoundedUp(series.rad[m].norm());
    series.position_mid_norm[m] = series.position_mid[m].norm();
    series.position_rad_norm[m] =
        RoundedUp(series.rad_norm[m] / (m + 1.0) + kUnitRoundoff * series.position_mid_norm[m]);
  }
  return series;
}

DragState EvaluateDragTaylor(const DragTaylorSeries& series, const Vec3& position, double sigma) {
  SPARSEDYN_ASSERT(sigma >= 0.0 && sigma <= series.plan.length,
                   "drag Taylor step evaluated outside its length");
  // Horner's rule for u(sigma) = sum_m c_m sigma^m and for Y(sigma) = sum_m c_m/(m+1) sigma^m
  // (x = X + sigma Y); alongside, sum_m |c_m| sigma^m and sum_m rad_m sigma^m (norms), for the
  // bounds gamma_2n sum |c_m| sigma^m of Horner's rule (Higham, eq. 5.3) plus the propagated
  // radii, and the same for Y.
  Vec3 vel = series.mid[kN];
  Vec3 y = series.position_mid[kN];
  double vel_abs = series.mid_norm[kN];
  double vel_rad = series.rad_norm[kN];
  double y_abs = series.position_mid_norm[kN];
  double y_rad = series.position_rad_norm[kN];
  for (int m = kN - 1; m >= 0; --m) {
    vel = vel * sigma + series.mid[m];
    y = y * sigma + series.position_mid[m];
    vel_abs = vel_abs * sigma + series.mid_norm[m];
    vel_rad = vel_rad * sigma + series.rad_norm[m];
    y_abs = y_abs * sigma + series.position_mid_norm[m];
    y_rad = y_rad * sigma + series.position_rad_norm[m];
  }
  // The tails by the Cauchy estimate (PlanDragTaylorStep), q = sigma / rho rounded up.
  const DragTaylorPlan& plan = series.plan;
  const double q = RoundedUp(sigma / plan.rho);
  SPARSEDYN_ASSERT(q < 1.0, "drag Taylor step beyond its Cauchy radius");
  double q_power = q;
  for (int m = 0; m < kN; ++m) q_power *= q;
  const double tail = plan.r * q_power / (1.0 - q);

  DragState state;
  state.position = position + sigma * y;
  state.velocity = vel;
  // Horner over n + 1 terms is 2n roundings; sigma Y one more, and the norms of the vectors
  // add one relative rounding each, all inside RoundedUp's margin.
  state.velocity_error = RoundedUp(vel_rad + Gamma(2 * kN) * vel_abs + tail);
  state.position_error = RoundedUp(sigma * (y_rad + Gamma(2 * kN + 2) * y_abs + tail / (kN + 2.0)) +
                                   1.01 * kUnitRoundoff * (position.norm() + sigma * y_abs));
  return state;
}

}  // namespace sparsedyn
