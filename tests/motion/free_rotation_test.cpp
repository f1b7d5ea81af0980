// SPDX-License-Identifier: MIT
// The torque-free rotation's closed forms (src/motion/free_rotation.hpp), each against an
// oracle of its own: the invariants E and L recomputed from the world-frame output, a
// long-double Runge-Kutta integration of Euler's equations and the quaternion kinematics
// (checked by halving its step), the textbook regular precession, RigidPath, Boost's Jacobi
// functions, and finite differences of the output against Euler's equations.
#include "motion/free_rotation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "motion/rigid_path.hpp"

namespace sparsedyn {
namespace {

using Quat = Eigen::Quaterniond;

// The angle (rad) of the rotation between two orientations (either quaternion sign).
double AngleBetween(const Quat& a, const Quat& b) {
  const Quat d = a.conjugate() * b;
  return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

// Euler's equations I ω' = (I ω) × ω with q' = ½ q (0, ω) in the body frame, by classical
// Runge-Kutta in long double with a fixed step.
class EulerIntegrator {
 public:
  EulerIntegrator(const Vec3& moments, const Quat& q, const Vec3& w_B) {
    for (int i = 0; i < 3; ++i) {
      moments_[i] = moments[i];
      state_[i] = w_B[i];
    }
    state_[3] = q.w();
    state_[4] = q.x();
    state_[5] = q.y();
    state_[6] = q.z();
  }
  using State = std::array<long double, 7>;

  void Step(long double h) { state_ = StepFrom(state_, h); }
  State StepFrom(const State& s, long double h) const {
    const State k1 = Derivative(s);
    const State k2 = Derivative(Add(s, k1, h / 2));
    const State k3 = Derivative(Add(s, k2, h / 2));
    const State k4 = Derivative(Add(s, k3, h));
    State out;
    for (int i = 0; i < 7; ++i) out[i] = s[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    return out;
  }
  const State& state() const { return state_; }
  void set_state(const State& s) { state_ = s; }
  static Vec3 Omega(const State& s) {
    return Vec3(static_cast<double>(s[0]), static_cast<double>(s[1]), static_cast<double>(s[2]));
  }
  static Quat Orientation(const State& s) {
    return Quat(static_cast<double>(s[3]), static_cast<double>(s[4]), static_cast<double>(s[5]),
                static_cast<double>(s[6]))
        .normalized();
  }

 private:
  static State Add(const State& s, const State& d, long double h) {
    State out;
    for (int i = 0; i < 7; ++i) out[i] = s[i] + h * d[i];
    return out;
  }
  State Derivative(const State& s) const {
    const long double w0 = s[0], w1 = s[1], w2 = s[2];
    const long double l0 = moments_[0] * w0, l1 = moments_[1] * w1, l2 = moments_[2] * w2;
    State d;
    d[0] = (l1 * w2 - l2 * w1) / moments_[0];
    d[1] = (l2 * w0 - l0 * w2) / moments_[1];
    d[2] = (l0 * w1 - l1 * w0) / moments_[2];
    const long double qw = s[3], qx = s[4], qy = s[5], qz = s[6];
    d[3] = -0.5L * (qx * w0 + qy * w1 + qz * w2);
    d[4] = 0.5L * (qw * w0 + qy * w2 - qz * w1);
    d[5] = 0.5L * (qw * w1 + qz * w0 - qx * w2);
    d[6] = 0.5L * (qw * w2 + qx * w1 - qy * w0);
    return d;
  }
  std::array<long double, 3> moments_{};
  State state_{};
};

Quat RandomOrientation(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  return Quat(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
}

// Moments in [0.5, 3] and a body-frame ω of norm `speed`, in random order and orientation.
struct Case {
  Vec3 moments;
  Quat q0;
  Vec3 w_B;
  Vec3 w_W() const { return q0 * w_B; }
  FreeRotation Make(double t0 = 0.0) const { return FreeRotation(t0, moments, q0, w_W()); }
};

Case RandomCase(std::mt19937_64& rng, double speed) {
  std::uniform_real_distribution<double> uniform(0.5, 3.0);
  std::normal_distribution<double> normal;
  Case c{Vec3(uniform(rng), uniform(rng), uniform(rng)), RandomOrientation(rng),
         Vec3(normal(rng), normal(rng), normal(rng))};
  c.w_B *= speed / c.w_B.norm();
  return c;
}

// The same moments with ω_c changed so that 1 - k^2 is near `complement` (a near-separatrix
// state): |L|^2 - 2 E I_mid = I_c (I_c - I_b) ω_c^2 - I_a (I_b - I_a) ω_a^2 for the extremes.
Case NearSeparatrix(Case c, double complement) {
  std::array<int, 3> o{0, 1, 2};
  std::sort(o.begin(), o.end(), [&](int i, int j) { return c.moments[i] < c.moments[j]; });
  const double ia = c.moments[o[0]], ib = c.moments[o[1]], ic = c.moments[o[2]];
  const double va = c.w_B[o[0]];
  const double base = ia * (ib - ia) * va * va;
  const double wc2 = base * (1.0 + complement) / (ic * (ic - ib));
  c.w_B[o[2]] = std::copysign(std::sqrt(wc2), c.w_B[o[2]]);
  return c;
}

struct Drift {
  double energy = 0.0, momentum = 0.0;
};

// E and L at t from the world-frame output alone: ω_B = qᵀ ω_W, L_W = q I qᵀ ω_W.
Drift InvariantDrift(const FreeRotation& f, const Vec3& moments, double t) {
  const Quat q = f.OrientationAt(t);
  const Vec3 w_W = f.OmegaWorldAt(t);
  const Vec3 w_B = q.conjugate() * w_W;
  const double energy = 0.5 * w_B.dot(moments.cwiseProduct(w_B));
  const Vec3 L_W = q * moments.cwiseProduct(w_B).eval();
  return {std::abs(energy - f.Energy()) / f.Energy(),
          (L_W - f.AngularMomentumWorld()).norm() / f.AngularMomentumWorld().norm()};
}

// Tolerances, each with its reason.
// Conservation over 10^3 turns: the closed form's round-off does not accumulate in E or L.
constexpr double kConservation = 1e-12;
// Closed form vs RK4 (h = 1e-3 s, |ω| = 1 rad/s, 100 s): RK4's own error is ~1e-11 here.
constexpr double kAgainstIntegrator = 1e-9;

TEST(FreeRotation, ConservesEnergyAndMomentumOverAThousandTurns) {
  std::mt19937_64 rng(20261203);
  std::printf("seed 20261203\n");
  Drift worst;
  for (int trial = 0; trial < 24; ++trial) {
    Case c = RandomCase(rng, 1.0);
    if (trial % 3 == 1) c = NearSeparatrix(c, 1e-8);
    if (trial % 3 == 2) c = NearSeparatrix(c, -1e-12);
    const FreeRotation f = c.Make(1e6);  // a large absolute t0: only t - t0 matters
    const double turns_time = 1000.0 * 2.0 * std::numbers::pi / c.w_B.norm();
    for (int s = 0; s <= 2000; ++s) {
      const Drift d = InvariantDrift(f, c.moments, 1e6 + turns_time * s / 2000.0);
      worst.energy = std::max(worst.energy, d.energy);
      worst.momentum = std::max(worst.momentum, d.momentum);
    }
  }
  std::printf("largest relative drift over 1000 turns: energy %.3g, |L| vector %.3g\n",
              worst.energy, worst.momentum);
  EXPECT_LT(worst.energy, kConservation);
  EXPECT_LT(worst.momentum, kConservation);
}

// The largest orientation and ω errors against RK4 at every second up to `duration`.
std::pair<double, double> CompareWithIntegrator(const Case& c, double duration, double h,
                                                const FreeRotation& f) {
  EulerIntegrator rk(c.moments, c.q0, c.q0.conjugate() * c.w_W());
  double angle = 0.0, omega = 0.0;
  const int per_second = static_cast<int>(std::lround(1.0 / h));
  for (int second = 1; second <= static_cast<int>(duration); ++second) {
    for (int i = 0; i < per_second; ++i) rk.Step(static_cast<long double>(h));
    const double t = second;
    angle =
        std::max(angle, AngleBetween(f.OrientationAt(t), EulerIntegrator::Orientation(rk.state())));
    omega = std::max(omega, (f.OmegaBodyAt(t) - EulerIntegrator::Omega(rk.state())).norm());
  }
  return {angle, omega};
}

TEST(FreeRotation, AgreesWithRungeKuttaOverAHundredSeconds) {
  std::mt19937_64 rng(20261204);
  double worst_angle = 0.0, worst_omega = 0.0, worst_step_check = 0.0;
  for (int trial = 0; trial < 6; ++trial) {
    const Case c = RandomCase(rng, 1.0);
    const FreeRotation f = c.Make();
    SCOPED_TRACE(testing::Message() << "trial " << trial << " kind " << static_cast<int>(f.kind())
                                    << " k^2 " << f.ModulusSquared());
    const auto [angle, omega] = CompareWithIntegrator(c, 100.0, 1e-3, f);
    // The oracle's own error: halving its step changes it by 15/16 of its error.
    if (trial < 2) {
      const auto [angle2, omega2] = CompareWithIntegrator(c, 100.0, 2e-3, f);
      worst_step_check = std::max(worst_step_check, std::max(angle2, omega2));
    }
    worst_angle = std::max(worst_angle, angle);
    worst_omega = std::max(worst_omega, omega);
    EXPECT_LT(angle, kAgainstIntegrator);
    EXPECT_LT(omega, kAgainstIntegrator);
  }
  std::printf(
      "vs RK4 (h = 1e-3) over 100 s: orientation %.3g rad, ω %.3g rad/s; with h = 2e-3 "
      "the error is %.3g (RK4's own error ~1/16 of that at h = 1e-3)\n",
      worst_angle, worst_omega, worst_step_check);
}

TEST(FreeRotation, AgreesWithRungeKuttaOnBothBranchesAndNearTheSeparatrix) {
  // Moments in an odd order (z, x, y = smallest, middle, largest), ω near each branch's axis,
  // and 1 - k^2 ~ 1e-6 on either side of the separatrix, which flip every ~50 s.
  const Vec3 I(2.0, 3.0, 1.0);
  const Quat q0 = Quat(0.2, -0.4, 0.1, 0.9).normalized();
  double worst = 0.0;
  for (const Vec3& w_B : {Vec3(0.2, 0.9, -0.3), Vec3(-0.3, 0.2, 0.9), Vec3(0.4, -0.5, 0.6)}) {
    for (const double complement : {0.0, 1e-6, -1e-6}) {
      Case c{I, q0, w_B};
      if (complement != 0.0) c = NearSeparatrix(c, complement);
      const FreeRotation f = c.Make();
      SCOPED_TRACE(testing::Message() << "w_B " << c.w_B.transpose() << " 1 - k^2 "
                                      << f.ComplementSquared() << " about axis " << f.Axes()[2]);
      const auto [angle, omega] = CompareWithIntegrator(c, 100.0, 1e-3, f);
      EXPECT_LT(angle, kAgainstIntegrator);
      EXPECT_LT(omega, kAgainstIntegrator);
      worst = std::max({worst, angle, omega});
    }
  }
  std::printf("both branches and 1 - k^2 ~ 1e-6 vs RK4 over 100 s: %.3g\n", worst);
}

// Zero crossings of the middle-axis ω component, found by bisection of `component(t)`.
template <typename F>
std::vector<double> Crossings(F component, double duration, double step) {
  std::vector<double> roots;
  double t_prev = 0.0, prev = component(0.0);
  for (double t = step; t <= duration; t += step) {
    const double now = component(t);
    if ((prev < 0.0) != (now < 0.0)) {
      double lo = t_prev, hi = t;
      for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        ((component(mid) < 0.0) == (prev < 0.0) ? lo : hi) = mid;
      }
      roots.push_back(0.5 * (lo + hi));
    }
    t_prev = t;
    prev = now;
  }
  return roots;
}

TEST(FreeRotation, IntermediateAxisFlipPeriodIsTwoKOverLambda) {
  // A body turning close to its middle axis (y) flips over and back (Dzhanibekov).
  const Case c{Vec3(1.0, 2.0, 3.0), Quat(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized())),
               Vec3(0.02, 1.0, 0.03)};
  const FreeRotation f = c.Make();
  ASSERT_EQ(f.kind(), FreeRotation::Kind::kElliptic);
  const double period = f.FlipPeriod();

  // The closed form's own sign changes of ω_y.
  const auto closed = Crossings([&](double t) { return f.OmegaBodyAt(t)[1]; }, 6.0 * period, 0.05);
  // The integrator's: RK4 steps of h, then bisection on the length of one last step.
  const double h = 1e-3;
  EulerIntegrator rk(c.moments, c.q0, c.w_B);
  std::vector<double> measured;
  for (int i = 1; i * h <= 6.0 * period; ++i) {
    const auto before = rk.state();
    rk.Step(h);
    if ((before[1] < 0) != (rk.state()[1] < 0)) {
      long double lo = 0, hi = h;
      for (int j = 0; j < 60; ++j) {
        const long double mid = 0.5L * (lo + hi);
        ((rk.StepFrom(before, mid)[1] < 0) == (before[1] < 0) ? lo : hi) = mid;
      }
      measured.push_back((i - 1) * h + static_cast<double>(lo));
    }
  }
  ASSERT_GE(closed.size(), 4u);
  ASSERT_EQ(closed.size(), measured.size());
  double worst_closed = 0.0, worst_measured = 0.0;
  for (std::size_t i = 1; i < closed.size(); ++i) {
    worst_closed = std::max(worst_closed, std::abs(closed[i] - closed[i - 1] - period));
    worst_measured = std::max(worst_measured, std::abs(measured[i] - measured[i - 1] - period));
  }
  // 2K/λ by Boost's complete integral of the first kind, from k = sqrt(k^2).
  const double boost_period = 2.0 * boost::math::ellint_1(std::sqrt(f.ModulusSquared())) / f.Rate();
  std::printf(
      "flip period 2K/λ = %.15g s (Boost ellint_1: %.3g off); closed-form crossings "
      "%.3g off, RK4 crossings %.3g off\n",
      period, std::abs(boost_period - period), worst_closed, worst_measured);
  EXPECT_NEAR(boost_period, period, 1e-12 * period);
  EXPECT_LT(worst_closed, 1e-12 * period);
  EXPECT_LT(worst_measured, 1e-9 * period);
}

TEST(FreeRotation, AxisymmetricBodyPrecessesAtTheTextbookRate) {
  // Symmetry axis x (I3 = 3), the other two 2: Ω = (I3 - I1) / I1 ω3 about e_x.
  const Case c{Vec3(3.0, 2.0, 2.0), Quat(Eigen::AngleAxisd(1.1, Vec3(0.2, -1, 0.4).normalized())),
               Vec3(0.8, 0.5, -0.3)};
  const FreeRotation f = c.Make(5.0);
  ASSERT_EQ(f.kind(), FreeRotation::Kind::kAxisymmetric);
  const double Omega = (3.0 - 2.0) / 2.0 * 0.8;
  double worst = 0.0;
  for (double dt = 0.0; dt <= 100.0; dt += 0.25) {
    const double co = std::cos(Omega * dt), si = std::sin(Omega * dt);
    const Vec3 textbook(0.8, co * 0.5 - si * -0.3, si * 0.5 + co * -0.3);
    worst = std::max(worst, (f.OmegaBodyAt(5.0 + dt) - textbook).norm());
  }
  const auto [angle, omega] = CompareWithIntegrator(c, 100.0, 1e-3, c.Make(0.0));
  std::printf("axisymmetric: ω vs textbook %.3g, vs RK4: orientation %.3g, ω %.3g\n", worst, angle,
              omega);
  EXPECT_LT(worst, 1e-14);
  EXPECT_LT(angle, kAgainstIntegrator);
  EXPECT_LT(omega, kAgainstIntegrator);
}

TEST(FreeRotation, SphericalTopIsRigidPathBitForBit) {
  const Quat q0(Eigen::AngleAxisd(0.7, Vec3(1, 1, 0).normalized()));
  const Vec3 w(0.3, -1.2, 0.5);
  const FreeRotation f(2.0, Vec3::Constant(1.7), q0, w);
  ASSERT_EQ(f.kind(), FreeRotation::Kind::kConstant);
  RigidPath path;
  path.centre.t0 = 2.0;
  path.q0 = f.q0();
  path.omega = w;
  for (double t = 2.0; t < 300.0; t += 0.37) {
    const Quat a = f.OrientationAt(t), b = path.OrientationAt(t);
    ASSERT_EQ(a.coeffs(), b.coeffs()) << "t = " << t;
    ASSERT_EQ(f.OmegaWorldAt(t), w);
  }
  // At rest, and turning about a principal axis, the motion is constant too.
  const FreeRotation rest(0.0, Vec3(1, 2, 3), q0, Vec3::Zero());
  EXPECT_EQ(rest.OrientationAt(10.0).coeffs(), rest.q0().coeffs());
  EXPECT_EQ(rest.MaxOmegaNorm(), 0.0);
  const FreeRotation about_y(0.0, Vec3(1, 2, 3), Quat::Identity(), Vec3(0, 2, 0));
  EXPECT_EQ(about_y.kind(), FreeRotation::Kind::kConstant);
  EXPECT_EQ(about_y.OmegaBodyAt(7.0), Vec3(0, 2, 0));
}

TEST(FreeRotation, MaxOmegaNormBoundsEverySample) {
  std::mt19937_64 rng(20261205);
  for (int trial = 0; trial < 30; ++trial) {
    Case c = RandomCase(rng, 0.5 + trial);
    if (trial % 2) c = NearSeparatrix(c, trial % 4 == 1 ? 1e-3 : -1e-3);
    const FreeRotation f = c.Make();
    const double i_min = c.moments.minCoeff();
    EXPECT_LE(f.MaxOmegaNorm(), std::sqrt(2 * f.Energy() / i_min) * (1 + 1e-15));
    EXPECT_LE(f.MaxOmegaNorm(), f.AngularMomentumWorld().norm() / i_min * (1 + 1e-15));
    double largest = 0.0;
    for (int s = 0; s < 4000; ++s) {
      largest = std::max(largest,
                         f.OmegaWorldAt(0.01 * s * 2 * std::numbers::pi / f.MaxOmegaNorm()).norm());
    }
    EXPECT_LE(largest, f.MaxOmegaNorm());
    EXPECT_GT(largest, 0.99 * f.MaxOmegaNorm());  // sharp: reached within sampling
  }
}

TEST(FreeRotation, JacobiAmplitudeAgreesWithBoost) {
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  double worst = 0.0;
  for (int trial = 0; trial < 2000; ++trial) {
    const double k = 0.999 * uniform(rng);
    const double kc = std::sqrt((1 - k) * (1 + k));
    const double quarter = boost::math::ellint_1(k);
    const double u = (2 * uniform(rng) - 1) * quarter;
    double cn, dn;
    const double sn = boost::math::jacobi_elliptic(k, u, &cn, &dn);
    const double phi = JacobiAmplitude(u, k, kc);
    worst = std::max({worst, std::abs(std::sin(phi) - sn), std::abs(std::cos(phi) - cn)});
  }
  std::printf("amplitude vs Boost jacobi_elliptic (k <= 0.999): %.3g\n", worst);
  EXPECT_LT(worst, 1e-14);
}

// Finite differences of the closed form against Euler's equations and q' = ½ ω_W q, by
// Richardson extrapolation of central differences (truncation O(h^4)).
std::pair<double, double> OdeResidual(const FreeRotation& f, const Vec3& I, double t) {
  const double h = 1e-3;
  auto diff = [&](auto g) {
    const Vec3 d1 = (g(t + h) - g(t - h)) / (2 * h);
    const Vec3 d2 = (g(t + 2 * h) - g(t - 2 * h)) / (4 * h);
    return Vec3((4.0 * d1 - d2) / 3.0);
  };
  const Vec3 w = f.OmegaBodyAt(t);
  const Vec3 euler = (I.cwiseProduct(w).cross(w)).cwiseQuotient(I);
  const Vec3 dw = diff([&](double s) { return f.OmegaBodyAt(s); });
  // The orientation relative to the one at t, so that the quaternion's sign does not matter.
  const Quat q = f.OrientationAt(t);
  const Vec3 rotation_rate = diff([&](double s) {
    const Quat d = f.OrientationAt(s) * q.conjugate();
    return Vec3((d.w() < 0 ? -2.0 : 2.0) * d.vec());
  });
  return {(dw - euler).norm(), (rotation_rate - f.OmegaWorldAt(t)).norm()};
}

TEST(FreeRotation, NearSeparatrixSolvesEulerToRoundOff) {
  // I = (1, 2.5, 3) and ω_x = ω_z make |L|^2 = 2 E I_mid exactly; then ω_z^2 is raised by a
  // relative 1 - k^2 ≈ (I_c - I_a) d / ((I_c - I_b) pc) to come off the separatrix.
  const Vec3 I(1.0, 2.5, 3.0);
  for (const double target : {1e-6, 1e-10, 1e-14, 0.0}) {
    Vec3 w_B(0.5, 0.25, 0.5);
    // d = 3·0.5 ω_z^2 - 1·1.5 ω_x^2; pc = 2.5·1.5 ω_y^2 + 3·2 ω_z^2, 1 - k^2 = 2 d / (0.5 pc)
    if (target > 0) {
      const double pc = 3.75 * 0.0625 + 6.0 * 0.25;
      w_B.z() = std::sqrt((1.5 * 0.25 + target * 0.25 * pc) / 1.5);
    }
    const FreeRotation f(0.0, I, Quat(0, 1, 0, 0), Quat(0, 1, 0, 0) * w_B);
    SCOPED_TRACE(testing::Message()
                 << "1 - k^2 target " << target << " actual " << f.ComplementSquared());
    EXPECT_EQ(f.kind(),
              target == 0 ? FreeRotation::Kind::kSeparatrix : FreeRotation::Kind::kElliptic);
    double residual_w = 0.0, residual_q = 0.0;
    Drift drift;
    const double duration = 200.0;  // several flips for 1 - k^2 = 1e-6, the approach else
    for (double t = 0.05; t < duration; t += 0.0731) {
      const auto [rw, rq] = OdeResidual(f, I, t);
      residual_w = std::max(residual_w, rw);
      residual_q = std::max(residual_q, rq);
      const Drift d = InvariantDrift(f, I, t);
      drift.energy = std::max(drift.energy, d.energy);
      drift.momentum = std::max(drift.momentum, d.momentum);
    }
    std::printf(
        "1 - k^2 = %.3g (%s): Euler residual %.3g, kinematics residual %.3g, drift "
        "E %.3g L %.3g, flip period %.6g s\n",
        f.ComplementSquared(), target == 0 ? "separatrix" : "elliptic", residual_w, residual_q,
        drift.energy, drift.momentum, f.FlipPeriod());
    EXPECT_LT(residual_w, 1e-9);
    EXPECT_LT(residual_q, 1e-9);
    EXPECT_LT(drift.energy, kConservation);
    EXPECT_LT(drift.momentum, kConservation);
  }
}

TEST(FreeRotation, NearSeparatrixTendsToTheSeparatrix) {
  // Before the flip (u <= 10) sn(u | k) - tanh u = O((1 - k^2) cosh^2 u): the elliptic form at
  // 1 - k^2 = 1e-14 (and 1e-16) must agree with the sech/tanh limit, the start the same.
  const Vec3 I(1.0, 2.5, 3.0);
  const Vec3 w_B(0.5, 0.25, 0.5);
  const FreeRotation limit(0.0, I, Quat::Identity(), w_B);
  ASSERT_EQ(limit.kind(), FreeRotation::Kind::kSeparatrix);
  for (const double target : {1e-14, 1e-16}) {
    const double pc = 3.75 * 0.0625 + 6.0 * 0.25;
    const Vec3 w_near(0.5, 0.25, std::sqrt((1.5 * 0.25 + target * 0.25 * pc) / 1.5));
    const FreeRotation near(0.0, I, Quat::Identity(), w_near);
    double worst_w = 0.0, worst_q = 0.0;
    const double horizon = 10.0 / near.Rate();
    for (double t = 0.0; t <= horizon; t += horizon / 500) {
      worst_w = std::max(worst_w, (near.OmegaBodyAt(t) - limit.OmegaBodyAt(t)).norm());
      worst_q = std::max(worst_q, AngleBetween(near.OrientationAt(t), limit.OrientationAt(t)));
    }
    std::printf("1 - k^2 = %.3g vs the separatrix over u <= 10: ω %.3g, orientation %.3g\n",
                near.ComplementSquared(), worst_w, worst_q);
    EXPECT_LT(worst_w, 1e-9);
    EXPECT_LT(worst_q, 1e-9);
  }
}

TEST(FreeRotation, NearSeparatrixMatchesTheExpansionInTheComplement) {
  // DLMF 22.10.7-9: sn, cn, dn = tanh, sech, sech + (k'^2 / 4)(sinh u cosh u ∓ u)(...) +
  // O(k'^4 e^{4u}): an oracle to round-off for u up to where k'^4 e^{4u} ~ 1e-16.
  const Vec3 I(1.0, 2.5, 3.0);
  for (const double target : {1e-10, 1e-14}) {
    const double pc = 3.75 * 0.0625 + 6.0 * 0.25;
    const Vec3 w_B(0.5, 0.25, std::sqrt((1.5 * 0.25 + target * 0.25 * pc) / 1.5));
    const FreeRotation f(0.0, I, Quat::Identity(), w_B);
    ASSERT_EQ(f.kind(), FreeRotation::Kind::kElliptic);
    ASSERT_EQ(f.Axes(), (std::array<int, 3>{0, 1, 2}));
    const double mc = f.ComplementSquared();
    const double u_max = (std::log(1e-16) - 2.0 * std::log(mc)) / 4.0;
    const Vec3 amplitudes = f.Amplitudes();
    double worst = 0.0;
    for (double t = 0.0; f.ArgumentAt(t) <= u_max; t += 0.01) {
      const double u = f.ArgumentAt(t);
      const double sech = 1.0 / std::cosh(u), tanh = std::tanh(u);
      const double shch = std::sinh(u) * std::cosh(u);
      const Vec3 expansion(sech - mc / 4 * (shch - u) * tanh * sech,
                           tanh + mc / 4 * (shch - u) * sech * sech,
                           sech + mc / 4 * (shch + u) * tanh * sech);
      worst = std::max(worst, (f.OmegaBodyAt(t).cwiseQuotient(amplitudes) - expansion).norm());
    }
    std::printf("1 - k^2 = %.3g: sn, cn, dn vs the expansion in k'^2 for u <= %.3g: %.3g\n", mc,
                u_max, worst);
    EXPECT_LT(worst, 1e-14);
  }
}

TEST(FreeRotation, NearlyEqualMomentsAreContinuousAcrossTheThreshold) {
  // Three ways two moments come together: the two smallest, the two largest (the body turns
  // about the smallest, k -> 0), and the two largest with the body about the largest, where
  // the rate λ vanishes like sqrt(ΔI / I) (ω_x tiny so that |L|^2 > 2 E I_mid).
  const double tau = FreeRotation::kNearlyEqualMoments;
  const Quat q0(Eigen::AngleAxisd(0.4, Vec3(0.3, 1, -0.2).normalized()));
  double worst_jump = 0.0, worst_rk = 0.0;
  for (const int pair : {0, 1, 2}) {
    const Vec3 w_B = pair == 2 ? Vec3(1e-6, -0.5, 0.7) : Vec3(0.6, -0.5, 0.7);
    auto moments = [&](double delta) {
      return pair == 0 ? Vec3(1.0, 1.0 + delta * 2.0, 2.0) : Vec3(1.0, 2.0 - delta * 2.0, 2.0);
    };
    const Case above_case{moments(tau * (1 + 1e-3)), q0, w_B};
    const FreeRotation below(0.0, moments(tau * (1 - 1e-3)), q0, q0 * w_B);
    const FreeRotation above = above_case.Make();
    const FreeRotation tiny(0.0, moments(1e-12), q0, q0 * w_B);
    SCOPED_TRACE(testing::Message() << "pair " << pair << " λ " << above.Rate());
    EXPECT_EQ(below.kind(), FreeRotation::Kind::kAxisymmetric);
    EXPECT_EQ(tiny.kind(), FreeRotation::Kind::kAxisymmetric);
    EXPECT_EQ(above.kind(), FreeRotation::Kind::kElliptic);
    for (double t = 0.0; t <= 10.0; t += 0.01) {
      const double jump = std::max(AngleBetween(below.OrientationAt(t), above.OrientationAt(t)),
                                   (below.OmegaWorldAt(t) - above.OmegaWorldAt(t)).norm());
      worst_jump = std::max(worst_jump, jump);
      ASSERT_TRUE(tiny.OrientationAt(t).coeffs().allFinite());
      ASSERT_TRUE(tiny.OmegaWorldAt(t).allFinite());
    }
    // The elliptic form just above the threshold against RK4.
    const auto [angle, omega] = CompareWithIntegrator(above_case, 10.0, 1e-3, above);
    worst_rk = std::max({worst_rk, angle, omega});
  }
  std::printf(
      "jump across kNearlyEqualMoments = %.3g over 10 s at |ω| ~ 1: %.3g; the elliptic "
      "form just above it vs RK4: %.3g\n",
      tau, worst_jump, worst_rk);
  // The fall-back's own error is ~ΔI/I |ω|^2 t = 2e-10 · 10 here.
  EXPECT_LT(worst_jump, 1e-8);
  EXPECT_LT(worst_rk, kAgainstIntegrator);
}

TEST(FreeRotation, RebasingAtAnyTimeGivesTheSameMotion) {
  std::mt19937_64 rng(20261207);
  double worst = 0.0;
  for (int trial = 0; trial < 20; ++trial) {
    Case c = RandomCase(rng, 1.0);
    if (trial % 4 == 1) c.moments[1] = c.moments[0];  // axisymmetric
    if (trial % 4 == 2) c = NearSeparatrix(c, 1e-4);
    const FreeRotation f = c.Make(3.0);
    for (const double t1 : {3.5, 17.0, 60.0}) {
      const FreeRotation g(t1, c.moments, f.OrientationAt(t1), f.OmegaWorldAt(t1));
      EXPECT_EQ(g.kind(), f.kind());
      for (double t = t1; t <= t1 + 20.0; t += 0.5) {
        const double error = std::max(AngleBetween(f.OrientationAt(t), g.OrientationAt(t)),
                                      (f.OmegaWorldAt(t) - g.OmegaWorldAt(t)).norm());
        worst = std::max(worst, error);
      }
    }
  }
  std::printf("rebased vs direct over 20 s: %.3g\n", worst);
  EXPECT_LT(worst, 1e-12);
}

TEST(FreeRotation, RefusesBadInput) {
  const Quat q = Quat::Identity();
  const Vec3 w(0.1, 0.2, 0.3);
  EXPECT_TRUE(FreeRotation::Create(0.0, Vec3(1, 2, 3), q, w).ok());
  const Result<FreeRotation> zero = FreeRotation::Create(0.0, Vec3(1, 0, 3), q, w);
  ASSERT_FALSE(zero.ok());
  EXPECT_NE(zero.error().message.find("body axis y"), std::string::npos) << zero.error().message;
  EXPECT_FALSE(FreeRotation::Create(0.0, Vec3(-1, 2, 3), q, w).ok());
  EXPECT_FALSE(FreeRotation::Create(0.0, Vec3(1, 2, NAN), q, w).ok());
  EXPECT_FALSE(FreeRotation::Create(0.0, Vec3(1, 2, INFINITY), q, w).ok());
  const Result<FreeRotation> scaled = FreeRotation::Create(0.0, Vec3(1, 2, 3), Quat(2, 0, 0, 0), w);
  ASSERT_FALSE(scaled.ok());
  EXPECT_NE(scaled.error().message.find("unit quaternion"), std::string::npos);
  EXPECT_FALSE(FreeRotation::Create(0.0, Vec3(1, 2, 3), Quat(NAN, 0, 0, 0), w).ok());
  EXPECT_FALSE(FreeRotation::Create(0.0, Vec3(1, 2, 3), q, Vec3(0, NAN, 0)).ok());
  EXPECT_DEATH(FreeRotation(0.0, Vec3(1, 0, 3), q, w), "moments");
  EXPECT_DEATH(FreeRotation(0.0, Vec3(1, 2, 3), Quat(0.5, 0, 0, 0), w), "unit quaternion");
}

}  // namespace
}  // namespace sparsedyn
