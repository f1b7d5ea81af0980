// SPDX-License-Identifier: MIT
// Quadratic drag's certified integrator (src/motion/drag_stepper.hpp, drag_taylor.hpp) through
// DragMotion: against the 1D closed forms (straight down, thrown up through v = 0, horizontal
// without gravity, and both drags along gravity), against a long-double Runge-Kutta reference
// in 3D, and its determinism and cost.
#include "motion/drag_motion.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include "motion/drag_oracles.hpp"
#include "motion/drag_stepper.hpp"

namespace sparsedyn {
namespace {

using testing::Distance;

double LogUniform(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(rng));
}

Vec3 RandomVector(std::mt19937_64& rng, double scale) {
  std::normal_distribution<double> normal(0.0, scale);
  return Vec3(normal(rng), normal(rng), normal(rng));
}

// Compares one DragMotion time with a long-double reference position and velocity; returns the
// larger of the two error-to-bound ratios (<= 1 passes).
double CheckAgainst(const DragMotion& motion, double t, const std::array<long double, 3>& x,
                    const std::array<long double, 3>& v, double reference_error = 0.0) {
  const DragState s = motion.StateAt(t);
  const double ex = Distance(x, s.position);
  const double ev = Distance(v, s.velocity);
  EXPECT_LE(ex, s.position_error + reference_error) << "t = " << t;
  EXPECT_LE(ev, s.velocity_error + reference_error) << "t = " << t;
  return std::max(ex / s.position_error, ev / s.velocity_error);
}

TEST(QuadraticDrag, FallingStraightDownMatchesTheTanhClosedForm) {
  double worst = 0.0;
  for (const double c2 : {1e-3, 0.1, 9.81, 300.0}) {
    for (const double w0 : {0.0, -0.5 * std::sqrt(9.81 / c2)}) {
      const Vec3 p0(1.0, -2.0, 3.0);
      const DragMotion motion(0.0, p0, Vec3(0, 0, w0), Vec3(0, 0, -9.81), Drag{.quadratic = c2});
      const double scale = 1.0 / std::sqrt(9.81 * c2);  // the time constant vt / g
      for (double t = 0.0; t <= 6.0 * scale; t += 0.037 * scale) {
        const auto zw = testing::VerticalQuadraticDrag(9.81, c2, w0, t);
        worst = std::max(worst,
                         CheckAgainst(motion, t, {1.0L, -2.0L, 3.0L + zw[0]}, {0.0L, 0.0L, zw[1]}));
      }
    }
  }
  std::printf("straight down: largest error / bound %.3g\n", worst);
}

TEST(QuadraticDrag, ThrownUpPassesThroughZeroSpeedOnTheClosedForm) {
  double worst = 0.0;
  for (const double c2 : {0.01, 0.5, 20.0}) {
    const double vt = std::sqrt(9.81 / c2);
    for (const double w0 : {0.1 * vt, vt, 30.0 * vt}) {
      const DragMotion motion(2.0, Vec3::Zero(), Vec3(0, 0, w0), Vec3(0, 0, -9.81),
                              Drag{.quadratic = c2});
      const double apex = std::atan(w0 / vt) * vt / 9.81;
      // The motion is evaluated at the double t = 2 + dt, the reference at exactly t - 2.
      for (double dt = 0.0; dt <= 3.0 * apex + 2.0 * vt / 9.81; dt += apex / 41.0) {
        const double t = 2.0 + dt;
        const auto zw = testing::VerticalQuadraticDrag(9.81, c2, w0, t - 2.0L);
        worst = std::max(worst, CheckAgainst(motion, t, {0.0L, 0.0L, zw[0]}, {0.0L, 0.0L, zw[1]}));
      }
      // At the apex (to a double) the speed is about zero: the slow steps carry it across.
      const double t_apex = 2.0 + apex;
      const auto at_apex = testing::VerticalQuadraticDrag(9.81, c2, w0, t_apex - 2.0L);
      CheckAgainst(motion, t_apex, {0.0L, 0.0L, at_apex[0]}, {0.0L, 0.0L, at_apex[1]});
    }
  }
  std::printf("thrown up: largest error / bound %.3g\n", worst);
}

// Without gravity the direction is fixed and the speed obeys s' = -c1 s - c2 s^2 (Bernoulli):
// s = c1 s0 e^(-c1 t) / (c1 + c2 s0 (1 - e^(-c1 t))), distance ln(1 + c2 s0 (1 - e^(-c1 t)) / c1)
// / c2; for c1 = 0, s0 / (1 + c2 s0 t) and ln(1 + c2 s0 t) / c2.
TEST(QuadraticDrag, HorizontalWithoutGravityMatchesTheBernoulliClosedForm) {
  double worst = 0.0;
  const Vec3 dir = Vec3(3, -4, 12) / 13.0;
  for (const double c1 : {0.0, 0.02, 1.0, 40.0}) {
    for (const double c2 : {1e-3, 0.3, 50.0}) {
      const double s0 = 7.0;
      const DragMotion motion(0.0, Vec3::Zero(), s0 * dir, Vec3::Zero(),
                              Drag{.linear = c1, .quadratic = c2});
      const double scale = 1.0 / (c1 + c2 * s0);
      for (double t = 0.0; t <= 200.0 * scale; t += 0.71 * scale) {
        long double s, d;
        if (c1 == 0.0) {
          s = s0 / (1.0L + static_cast<long double>(c2) * s0 * t);
          d = std::log1p(static_cast<long double>(c2) * s0 * t) / c2;
        } else {
          const long double decay = std::exp(-static_cast<long double>(c1) * t);
          const long double gained = -std::expm1(-static_cast<long double>(c1) * t) / c1;
          s = s0 * decay / (1.0L + static_cast<long double>(c2) * s0 * gained);
          d = std::log1p(static_cast<long double>(c2) * s0 * gained) / c2;
        }
        std::array<long double, 3> x, v;
        for (int i = 0; i < 3; ++i) {
          x[i] = d * static_cast<long double>(dir[i]);
          v[i] = s * static_cast<long double>(dir[i]);
        }
        worst = std::max(worst, CheckAgainst(motion, t, x, v));
      }
    }
  }
  std::printf("horizontal: largest error / bound %.3g\n", worst);
}

// Falling along g from v0 >= 0 (down) with both drags: w' = gz - c1 w - c2 w^2 = -c2 (w - w+)
// (w - w-), so (w - w+) / (w - w-) = C e^(-lambda t) with lambda = sqrt(c1^2 + 4 c2 gz),
// w = (w+ - w- C E) / (1 - C E), and the distance w+ t + ln((1 - C E) / (1 - C)) / c2.
// Returns {z, w} with z and w measured up (both negative).
std::array<long double, 2> RiccatiFall(double c1, double c2, double w0, long double t) {
  const long double gz = 9.81L;
  const long double root = std::sqrt(static_cast<long double>(c1) * c1 + 4 * c2 * gz);
  const long double w_plus = (root - c1) / (2 * c2), w_minus = (-root - c1) / (2 * c2);
  const long double big_c = (w0 - w_plus) / (w0 - w_minus);
  const long double e = std::exp(-root * t);
  const long double w = (w_plus - w_minus * big_c * e) / (1 - big_c * e);
  return {-(w_plus * t + std::log((1 - big_c * e) / (1 - big_c)) / c2), -w};
}

TEST(QuadraticDrag, FallingWithBothDragsMatchesTheRiccatiClosedForm) {
  double worst = 0.0;
  for (const double c1 : {0.1, 2.0, 30.0}) {
    for (const double c2 : {0.01, 1.0, 80.0}) {
      for (const double w0 : {0.0, 3.0, 40.0}) {
        const double root = std::sqrt(c1 * c1 + 4 * c2 * 9.81);
        const DragMotion motion(0.0, Vec3::Zero(), Vec3(0, 0, -w0), Vec3(0, 0, -9.81),
                                Drag{.linear = c1, .quadratic = c2});
        // The terminal speed, 2 gz / (c1 + sqrt(c1^2 + 4 c2 gz)), in long double.
        const long double w_plus =
            2 * 9.81L / (c1 + std::sqrt(static_cast<long double>(c1) * c1 + 4 * c2 * 9.81L));
        EXPECT_NEAR(motion.TerminalVelocity().z(), -static_cast<double>(w_plus),
                    1e-15 * static_cast<double>(w_plus));
        for (double t = 0.0; t <= 30.0 / root; t += 0.17 / root) {
          const auto zw = RiccatiFall(c1, c2, w0, t);
          worst = std::max(worst, CheckAgainst(motion, t, {0, 0, zw[0]}, {0, 0, zw[1]}));
        }
      }
    }
  }
  std::printf("both drags along g: largest error / bound %.3g\n", worst);
}

// Long after the start the stepper is on its settled step (at terminal velocity): still on
// the closed form, within bounds that stop growing but for round-off.
TEST(QuadraticDrag, SettledStepFollowsTheRiccatiClosedForm) {
  double worst = 0.0;
  for (const double c1 : {0.0, 0.5}) {
    for (const double c2 : {0.05, 3.0}) {
      const DragModel model{Vec3(0, 0, -9.81), c1, c2};
      const DragFlow flow = DragFlow::Make(model, Vec3(0, 0, -1.0));
      DragStepper stepper(flow, Vec3::Zero(), Vec3(0, 0, -1.0));
      const DragMotion motion(0.0, Vec3::Zero(), Vec3(0, 0, -1.0), model.g, Drag{c1, c2});
      const double root = std::sqrt(c1 * c1 + 4 * c2 * 9.81);
      for (double t = 60.0 / root; t < 1e4; t *= 1.7) {
        stepper.AdvanceTo(t);
        const auto zw = RiccatiFall(c1, c2, 1.0, t);
        worst = std::max(worst, CheckAgainst(motion, t, {0, 0, zw[0]}, {0, 0, zw[1]}));
      }
      EXPECT_FALSE(std::isfinite(stepper.End()));  // settled
    }
  }
  std::printf("settled: largest error / bound %.3g\n", worst);
}

// The 3D case has no closed form: a long-double RK4 at two step sizes (their difference, times
// 16/15, bounds its own error by Richardson) is the reference.
TEST(QuadraticDrag, AgreesWithALongDoubleReferenceIn3D) {
  std::mt19937_64 rng(20261204);
  double worst = 0.0;
  for (int trial = 0; trial < 60; ++trial) {
    const Vec3 p0 = RandomVector(rng, 5.0);
    const Vec3 v0 = RandomVector(rng, LogUniform(rng, 0.1, 30.0));
    const Vec3 g = RandomVector(rng, 10.0);
    const double c1 = trial % 3 == 0 ? 0.0 : LogUniform(rng, 1e-3, 3.0);
    const double c2 = LogUniform(rng, 1e-3, 3.0);
    const DragMotion motion(0.0, p0, v0, g, Drag{.linear = c1, .quadratic = c2});
    const double vt = motion.TerminalVelocity().norm();
    const double duration = LogUniform(rng, 0.1, 3.0) * vt / g.norm();
    SCOPED_TRACE(::testing::Message() << "trial " << trial << " c1 " << c1 << " c2 " << c2);
    const long steps = 20000;
    const testing::LongState fine =
        testing::ReferenceDragRk4(p0, v0, g, c1, c2, duration, 2 * steps);
    const testing::LongState coarse = testing::ReferenceDragRk4(p0, v0, g, c1, c2, duration, steps);
    double reference_error = 0.0;
    for (int i = 0; i < 3; ++i) {
      reference_error += static_cast<double>(std::abs(fine.x[i] - coarse.x[i]) +
                                             std::abs(fine.v[i] - coarse.v[i]));
    }
    reference_error = 16.0 / 15.0 * reference_error + 1e-18 * (p0.norm() + 100.0);
    worst = std::max(worst, CheckAgainst(motion, duration, fine.x, fine.v, reference_error));
  }
  std::printf("3D: largest error / bound %.3g\n", worst);
}

TEST(QuadraticDrag, EvaluationsAreDeterministicAndIndependentOfEachOther) {
  const DragMotion motion(1.5, Vec3(1, 2, 3), Vec3(10, -4, 7), Vec3(0.2, 0, -9.81),
                          Drag{.linear = 0.05, .quadratic = 0.3});
  const DragState a = motion.StateAt(2.7);
  (void)motion.StateAt(9.0);  // nothing is cached
  const DragState b = motion.StateAt(2.7);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.velocity, b.velocity);
  EXPECT_EQ(a.acceleration, b.acceleration);
  EXPECT_EQ(a.position_error, b.position_error);
  EXPECT_EQ(motion.PositionAt(2.7), a.position);
  EXPECT_EQ(motion.VelocityAt(2.7), a.velocity);
  EXPECT_EQ(motion.AccelerationAt(2.7), a.acceleration);
  EXPECT_EQ(motion.PositionErrorAt(2.7), a.position_error);
  // The start is the start, exactly.
  EXPECT_EQ(motion.PositionAt(1.5), Vec3(1, 2, 3));
  EXPECT_EQ(motion.VelocityAt(1.5), Vec3(10, -4, 7));
}

TEST(QuadraticDrag, ErrorBoundNeverDecreasesAlongTheSegment) {
  const DragMotion motion(0.0, Vec3(1, 2, 3), Vec3(-3, 8, 20), Vec3(0, 0, -9.81),
                          Drag{.quadratic = 0.2});
  double last = 0.0;
  for (double t = 0.0; t < 8.0; t += 0.013) {
    const double e = motion.PositionErrorAt(t);
    EXPECT_GE(e, last) << t;
    last = e;
  }
}

// Settled dust: once within the tolerance of terminal velocity the stepper takes its final
// step, and any later time costs one evaluation.
TEST(QuadraticDrag, SettlesOnAFinalStepAtTerminalVelocity) {
  const Vec3 g(0, 0, -9.81);
  const DragModel model{g, 0.1, 9.81};  // vt close to 1 m/s
  const DragFlow flow = DragFlow::Make(model, Vec3(2, 0, 1));
  DragStepper stepper(flow, Vec3::Zero(), Vec3(2, 0, 1));
  stepper.AdvanceTo(1e6);
  EXPECT_FALSE(std::isfinite(stepper.End()));
  std::printf("steps until settled: %d (at %.3g s)\n", stepper.steps(), stepper.Begin());
  EXPECT_LT(stepper.steps(), 2000);
  const DragState s = stepper.Evaluate(1e6);
  EXPECT_LE((s.velocity - flow.terminal_velocity).norm(), 1e-14);
  EXPECT_LE(s.position_error, 1e-6);  // u |x| with |x| ~ 1e6 m
}

// The cost of an evaluation: one walk over the steps of the segment.
TEST(QuadraticDrag, CostPerEvaluation) {
  std::mt19937_64 rng(20261205);
  long steps = 0;
  int count = 0;
  const auto start = std::chrono::steady_clock::now();
  double sink = 0.0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 v0 = RandomVector(rng, 3.0);
    const Vec3 g(0, 0, -9.81);
    const DragModel model{g, 0.1, 0.5};
    const DragFlow flow = DragFlow::Make(model, v0);
    DragStepper stepper(flow, Vec3::Zero(), v0);
    const double horizon = 0.05;  // a typical check interval for this body
    stepper.AdvanceTo(horizon);
    sink += stepper.Evaluate(horizon).position.norm();
    steps += stepper.steps() + 1;
    ++count;
  }
  const double ns =
      std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
  std::printf("0.05 s walk: %.1f steps, %.0f ns per evaluation, %.0f ns per step (%g)\n",
              static_cast<double>(steps) / count, ns / count, ns / static_cast<double>(steps),
              sink);
}

}  // namespace
}  // namespace sparsedyn
