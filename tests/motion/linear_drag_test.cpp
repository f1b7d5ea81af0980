// SPDX-License-Identifier: MIT
// The closed form of linear drag (src/motion/linear_drag.hpp) against the textbook formula in
// 128-bit floats, its limits (no drag: the Path polynomial bit for bit; terminal velocity
// g / c1), and the claims its round-off bound rests on.
#include "motion/linear_drag.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "motion/drag_motion.hpp"
#include "motion/drag_oracles.hpp"
#include "motion/path.hpp"

namespace sparsedyn {
namespace {

using testing::Distance;
using testing::Quad;
using testing::QuadExp;

Vec3 RandomVector(std::mt19937_64& rng, double scale) {
  std::normal_distribution<double> normal(0.0, scale);
  return Vec3(normal(rng), normal(rng), normal(rng));
}

double LogUniform(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(rng));
}

TEST(LinearDragFactors, WithinTheirErrorBoundOfQuadPrecisionValues) {
  std::mt19937_64 rng(20261201);
  double worst = 0.0;
  for (int trial = 0; trial < 200000; ++trial) {
    const double u = trial < 1000 ? trial * 1e-3 : LogUniform(rng, 1e-12, 700.0);
    const LinearDragFactors f = LinearDragFactorsAt(u);
    const Quad q = u;
    const Quad decay = QuadExp(-q);
    const Quad phi1 = u == 0.0 ? Quad(1) : (1 - decay) / q;
    // phi2 by its own series below 0.1 (the closed form cancels there even in 128 bits).
    Quad phi2 = 0;
    if (u < 0.1) {
      Quad term = 0.5;
      for (int k = 0; k < 40; ++k) {
        phi2 += term;
        term *= -q / (k + 3);
      }
    } else {
      phi2 = (decay - 1 + q) / (q * q);
    }
    const double bound = kLinearDragFactorError * kUnitRoundoff;
    const double e1 = std::abs(static_cast<double>((f.phi1 - phi1) / phi1));
    const double e2 = std::abs(static_cast<double>((f.phi2 - phi2) / phi2));
    const double ed = std::abs(static_cast<double>((f.decay - decay) / decay));
    ASSERT_LE(e1, bound) << "u = " << u;
    ASSERT_LE(e2, bound) << "u = " << u;
    ASSERT_LE(ed, bound) << "u = " << u;
    worst = std::max({worst, e1 / bound, e2 / bound, ed / bound});
  }
  std::printf("largest factor error / bound: %.3g\n", worst);
}

// The bound of LinearDragStateAfter takes |u phi'(u) / phi(u)| <= 1 for phi1 and phi2 (the
// sensitivity to the rounding of u = c1 dt). Checked by central differences in long double.
TEST(LinearDragFactors, LogDerivativesLieBetweenMinusOneAndZero) {
  for (double u = 1e-6; u < 1e4; u *= 1.01) {
    const long double h = u * 1e-6L;
    auto phi1 = [](long double x) { return -std::expm1(-x) / x; };
    auto phi2 = [](long double x) { return (std::expm1(-x) + x) / (x * x); };
    if (u > 1e-2) {  // phi2's closed form cancels below
      const long double d2 = u * (std::log(phi2(u + h)) - std::log(phi2(u - h))) / (2 * h);
      EXPECT_GE(d2, -1.0L - 1e-6L) << u;
      EXPECT_LE(d2, 1e-9L) << u;
    }
    const long double d1 = u * (std::log(phi1(u + h)) - std::log(phi1(u - h))) / (2 * h);
    EXPECT_GE(d1, -1.0L - 1e-6L) << u;
    EXPECT_LE(d1, 1e-9L) << u;
  }
}

TEST(LinearDrag, MatchesTheTextbookFormulaWithinItsBound) {
  std::mt19937_64 rng(20261202);
  double worst = 0.0;
  for (int trial = 0; trial < 100000; ++trial) {
    const Vec3 p0 = RandomVector(rng, LogUniform(rng, 1e-3, 1e4));
    const Vec3 v0 = RandomVector(rng, LogUniform(rng, 1e-3, 1e3));
    const Vec3 g = RandomVector(rng, LogUniform(rng, 1e-2, 1e2));
    const double c1 = LogUniform(rng, 1e-6, 1e3);
    const double dt = LogUniform(rng, 1e-12, 1e3) / c1;  // c1 dt in [1e-12, 1e3]
    SCOPED_TRACE(::testing::Message() << "c1 " << c1 << " dt " << dt);
    const DragState s = LinearDragStateAfter(p0, v0, g, c1, dt);
    const testing::QuadState q = testing::TextbookLinearDrag(p0, v0, g, c1, dt);
    const double ex = Distance(q.x, s.position);
    const double ev = Distance(q.v, s.velocity);
    const double ea = Distance(q.a, s.acceleration);
    ASSERT_LE(ex, s.position_error);
    ASSERT_LE(ev, s.velocity_error);
    ASSERT_LE(ea, s.acceleration_error);
    // A zero bound was met exactly above (and counts as no part of it).
    const auto part = [](double error, double bound) { return bound > 0 ? error / bound : 0.0; };
    worst = std::max({worst, part(ex, s.position_error), part(ev, s.velocity_error),
                      part(ea, s.acceleration_error)});
  }
  // The bound is not vacuous: the worst case uses a sizeable part of it.
  std::printf("largest closed-form error / bound: %.3g\n", worst);
  EXPECT_GT(worst, 1e-3);
}

TEST(LinearDrag, WithoutDragIsThePathPolynomialBitForBit) {
  std::mt19937_64 rng(20261203);
  for (int trial = 0; trial < 10000; ++trial) {
    const Path path{RandomVector(rng, 10.0), RandomVector(rng, 3.0), RandomVector(rng, 10.0), 0.0};
    const double dt = LogUniform(rng, 1e-9, 1e3);
    const DragState s = LinearDragStateAfter(path.p0, path.v0, path.a, 0.0, dt);
    EXPECT_EQ(s.position, path.PositionAt(dt));
    EXPECT_EQ(s.velocity, path.VelocityAt(dt));
    EXPECT_EQ(s.acceleration, path.a);
    // The same through DragMotion, at an absolute time.
    const DragMotion motion(5.0, path.p0, path.v0, path.a, Drag{});
    const Path shifted{path.p0, path.v0, path.a, 5.0};
    EXPECT_EQ(motion.PositionAt(5.0 + dt), shifted.PositionAt(5.0 + dt));
    EXPECT_EQ(motion.VelocityAt(5.0 + dt), shifted.VelocityAt(5.0 + dt));
  }
}

TEST(LinearDrag, TinyCoefficientTendsToThePolynomial) {
  const Vec3 p0(1, 2, 3), v0(4, -5, 6), g(0, 0, -9.81);
  const Path path{p0, v0, g, 0.0};
  for (const double c1 : {1e-300, 1e-200, 1e-30, 1e-17}) {
    const DragState s = LinearDragStateAfter(p0, v0, g, c1, 2.0);
    EXPECT_LE((s.position - path.PositionAt(2.0)).norm(), 1e-14) << c1;
    EXPECT_LE((s.velocity - path.VelocityAt(2.0)).norm(), 1e-14) << c1;
  }
}

TEST(LinearDrag, VelocityTendsToTerminalVelocityGOverC1) {
  const Vec3 g(0.3, -0.2, -9.81);
  for (const double c1 : {0.05, 1.0, 30.0}) {
    const DragMotion motion(0.0, Vec3(0, 0, 10), Vec3(5, 1, 2), g, Drag{.linear = c1});
    const Vec3 terminal = g / c1;
    EXPECT_EQ(motion.TerminalVelocity(), terminal);
    const DragState s = motion.StateAt(60.0 / c1);  // e^-60 of the start's deviation left
    EXPECT_LE((s.velocity - terminal).norm(), 1e-14 * terminal.norm()) << c1;
    EXPECT_LE(s.acceleration.norm(), 1e-13 * g.norm()) << c1;
    // The position keeps moving at terminal velocity: x(t) - v_inf t is constant.
    const Vec3 drift0 = s.position - terminal * (60.0 / c1);
    const Vec3 later = motion.PositionAt(90.0 / c1) - terminal * (90.0 / c1);
    EXPECT_LE((later - drift0).norm(), 1e-12 * (1.0 + s.position.norm())) << c1;
  }
}

}  // namespace
}  // namespace sparsedyn
