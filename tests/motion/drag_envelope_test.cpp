// SPDX-License-Identifier: MIT
// DragMotion's view for the sparse phase: the quadratic path and envelope of SegmentFor /
// SegmentAt hold the true motion over the horizon; HorizonFor is the longest that fits and
// grows as a body settles; the preconditions are asserted.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include "motion/drag_envelope_check.hpp"
#include "motion/drag_motion.hpp"

namespace sparsedyn {
namespace {

using testing::DragBody;

TEST(DragEnvelope, RandomBodiesStayInsideTheirEnvelopes) {
  std::mt19937_64 rng(20261206);
  double worst = 0.0;
  for (int trial = 0; trial < 3000; ++trial) {
    const DragBody b = testing::RandomDragBody(rng);
    SCOPED_TRACE(b.Describe());
    const double ratio = testing::WorstEnvelopeRatio(b, 24, 1e3, 3);
    ASSERT_LE(ratio, 1.0);
    worst = std::max(worst, ratio);
  }
  // The envelope is used, not only bounded: the worst sample comes near its edge (with weak
  // linear drag the jerk is almost constant, and J tau^3 / 6 almost exact at the horizon).
  std::printf("largest distance from the path / envelope: %.6f\n", worst);
  EXPECT_GT(worst, 0.05);
}

// The exact motion (not only the reported one) inside the envelope of quadratic drag, by the
// long-double Runge-Kutta reference.
TEST(DragEnvelope, ExactQuadraticMotionStaysInside) {
  std::mt19937_64 rng(20261207);
  for (int trial = 0; trial < 40; ++trial) {
    DragBody b = testing::RandomDragBody(rng);
    b.drag.quadratic = std::max(b.drag.quadratic, 0.01);
    b.t = b.t0;
    SCOPED_TRACE(b.Describe());
    const DragMotion motion(b.t0, b.p0, b.v0, b.g, b.drag);
    const TaylorSegment seg = motion.SegmentFor(b.t, b.max_error);
    const double span = std::min(seg.horizon, 10.0);
    for (const double f : {0.25, 0.5, 1.0}) {
      const double tau = f * span;
      const testing::LongState ref =
          testing::ReferenceDragRk4(b.p0, b.v0, b.g, b.drag.linear, b.drag.quadratic, tau, 20000);
      const double off = testing::Distance(ref.x, seg.path.PositionAt(b.t + tau));
      EXPECT_LE(off, seg.envelope.At(tau) * (1.0 + 1e-9) + 1e-12 * (1.0 + b.p0.norm()));
    }
  }
}

TEST(DragEnvelope, HorizonIsTheLongestThatFits) {
  std::mt19937_64 rng(20261208);
  for (int trial = 0; trial < 500; ++trial) {
    const DragBody b = testing::RandomDragBody(rng);
    SCOPED_TRACE(b.Describe());
    const DragMotion motion(b.t0, b.p0, b.v0, b.g, b.drag);
    const double h = motion.HorizonFor(b.t, b.max_error);
    ASSERT_GT(h, 0.0);
    if (!std::isfinite(h) || h > 1e6) continue;
    EXPECT_EQ(h, motion.SegmentFor(b.t, b.max_error).horizon);
    EXPECT_LE(motion.SegmentAt(b.t, h).envelope.At(h), b.max_error * (1.0 + 1e-12));
    const double longer = 1.001 * h;
    EXPECT_GT(motion.SegmentAt(b.t, longer).envelope.At(longer), b.max_error);
    // A cap is a cap.
    EXPECT_EQ(motion.HorizonFor(b.t, b.max_error, 0.5 * h), 0.5 * h);
  }
}

// Dust from rest, segment after segment as the World runs it (a new DragMotion at each
// check, from the state there): the checks thin out as the dust reaches terminal velocity.
TEST(DragEnvelope, HorizonGrowsAsTheBodySettles) {
  for (const Drag drag :
       {Drag{.linear = 2.0}, Drag{.quadratic = 9.81}, Drag{.linear = 0.5, .quadratic = 3.0}}) {
    const Vec3 g(0, 0, -9.81);
    const double max_error = 1e-3 * 0.01;  // a thousandth of a 1 cm radius
    double t = 0.0;
    Vec3 p = Vec3::Zero(), v = Vec3::Zero();
    std::vector<double> horizons;
    const auto start = std::chrono::steady_clock::now();
    while (t < 20.0) {
      const DragMotion motion(t, p, v, g, drag);
      const TaylorSegment seg = motion.SegmentFor(t, max_error);
      horizons.push_back(seg.horizon);
      if (!std::isfinite(seg.horizon)) break;
      t += seg.horizon;
      const DragState s = motion.StateAt(t);
      p = s.position;
      v = s.velocity;
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "drag {%g, %g}: %zu checks in 20 s; horizons %.3g s first, %.3g s at the end"
        " (%.2f ms in all)\n",
        drag.linear, drag.quadratic, horizons.size(), horizons.front(), horizons.back(), ms);
    // After the first second (several time constants) each horizon is longer than the last.
    EXPECT_GT(horizons.back(), 100.0 * horizons.front());
    EXPECT_LT(horizons.size(), 400u);
    const DragMotion last(t, p, v, g, drag);
    EXPECT_LE((last.VelocityAt(t) - last.TerminalVelocity()).norm(), 1e-9);
  }
}

TEST(DragEnvelope, WithoutDragThePathIsExactAndTheHorizonLong) {
  const DragMotion motion(3.0, Vec3(1, 2, 3), Vec3(4, 5, 6), Vec3(0, 0, -9.81), Drag{});
  const TaylorSegment seg = motion.SegmentFor(3.0, 1e-6);
  EXPECT_EQ(seg.path.a, Vec3(0, 0, -9.81));
  EXPECT_GT(seg.horizon, 1e3);  // only round-off grows
  EXPECT_LE(seg.envelope.e2, 1e-12);
}

TEST(DragEnvelope, AtRestWithoutGravityNeedsNoCheck) {
  for (const Drag drag : {Drag{}, Drag{.linear = 1.0}, Drag{.quadratic = 1.0}}) {
    const DragMotion motion(0.0, Vec3(1, 2, 3), Vec3::Zero(), Vec3::Zero(), drag);
    EXPECT_EQ(motion.HorizonFor(5.0, 1e-6), kInfinity);
    EXPECT_EQ(motion.PositionAt(1e9), Vec3(1, 2, 3));
  }
}

TEST(DragMotionDeathTest, BadParametersAreAsserted) {
  const Vec3 g(0, 0, -9.81);
  EXPECT_DEATH(DragMotion(0.0, Vec3::Zero(), Vec3::Zero(), g, Drag{.linear = -1.0}), "drag");
  EXPECT_DEATH(DragMotion(0.0, Vec3::Zero(), Vec3::Zero(), g, Drag{.quadratic = NAN}), "drag");
  EXPECT_DEATH(DragMotion(0.0, Vec3(NAN, 0, 0), Vec3::Zero(), g, Drag{}), "finite");
  const DragMotion motion(1.0, Vec3::Zero(), Vec3::Zero(), g, Drag{.quadratic = 1.0});
  EXPECT_DEATH(motion.StateAt(0.5), "t >= t0");
  EXPECT_DEATH(motion.HorizonFor(1.0, 0.0), "max_error");
  EXPECT_DEATH(motion.SegmentAt(1.0, -1.0), "horizon");
}

}  // namespace
}  // namespace sparsedyn
