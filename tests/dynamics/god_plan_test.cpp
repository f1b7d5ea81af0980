// SPDX-License-Identifier: MIT
// God objects' plans (src/dynamics/god_move.hpp, god_plan.hpp): the closed-form least
// acceleration of one-switch moves against a brute-force search over the switch, the earliest
// feasible duration against a brute-force scan of durations, the bang-bang minimum time of a
// rest-to-rest move, and random tracks: |a| <= A, continuity, targets reached on time when
// they can be and as early as they can be otherwise.
#include "dynamics/god_plan.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "dynamics/god_move.hpp"

namespace sparsedyn {
namespace {

std::mt19937_64& Rng() {
  static std::mt19937_64 rng(20261210);
  return rng;
}

double LogUniform(double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(Rng()));
}

Vec3 RandomVector(double scale) {
  std::normal_distribution<double> normal(0.0, scale);
  return Vec3(normal(Rng()), normal(Rng()), normal(Rng()));
}

// Brute force, sharing nothing with god_move.cpp: for a switch at tau1 = alpha tau, solve
// a1 tau1 + a2 tau2 = V - v and a1 (tau1^2 / 2 + tau1 tau2) + a2 tau2^2 / 2 = D - v tau
// (velocity and position at the end) per component in long double; the largest |a| of the two.
long double LargestAcceleration(const GodMoveEnds& ends, double tau, long double alpha) {
  const long double t1 = alpha * tau, t2 = (1 - alpha) * tau;
  const long double m11 = t1, m12 = t2, m21 = t1 * t1 / 2 + t1 * t2, m22 = t2 * t2 / 2;
  const long double det = m11 * m22 - m12 * m21;
  long double n1 = 0, n2 = 0;
  for (int i = 0; i < 3; ++i) {
    const long double r1 = static_cast<long double>(ends.end_velocity[i]) - ends.start_velocity[i];
    const long double r2 =
        ends.displacement[i] - static_cast<long double>(ends.start_velocity[i]) * tau;
    const long double a1 = (r1 * m22 - m12 * r2) / det, a2 = (m11 * r2 - m21 * r1) / det;
    n1 += a1 * a1;
    n2 += a2 * a2;
  }
  return std::sqrt(std::max(n1, n2));
}

// The least largest |a| over the switch: a scan of 400 switches, then golden sections around
// the best three cells.
long double BruteForceLeastAcceleration(const GodMoveEnds& ends, double tau) {
  const int n = 400;
  int best = 1;
  long double best_value = LargestAcceleration(ends, tau, 1.0L / n);
  for (int k = 2; k < n; ++k) {
    const long double value = LargestAcceleration(ends, tau, static_cast<long double>(k) / n);
    if (value < best_value) {
      best_value = value;
      best = k;
    }
  }
  long double lo = static_cast<long double>(best - 1) / n;
  long double hi = static_cast<long double>(best + 1) / n;
  const long double phi = (std::sqrt(5.0L) - 1) / 2;
  for (int i = 0; i < 100; ++i) {
    const long double x1 = hi - phi * (hi - lo), x2 = lo + phi * (hi - lo);
    if (LargestAcceleration(ends, tau, x1) < LargestAcceleration(ends, tau, x2)) {
      hi = x2;
    } else {
      lo = x1;
    }
  }
  return std::min(best_value, LargestAcceleration(ends, tau, (lo + hi) / 2));
}

GodMoveEnds RandomEnds() {
  GodMoveEnds e{RandomVector(LogUniform(0.1, 10.0)), RandomVector(LogUniform(0.01, 3.0)),
                RandomVector(LogUniform(0.01, 3.0))};
  const double kind = std::uniform_real_distribution<double>(0, 1)(Rng());
  if (kind < 0.15) e.start_velocity = e.end_velocity = Vec3::Zero();  // rest to rest
  if (kind > 0.85) e.end_velocity = e.start_velocity;                 // pass through
  return e;
}

// Where the move's pieces take the object from the origin with the start velocity.
std::pair<Vec3, Vec3> EndOfMove(const GodMove& m, const Vec3& v) {
  const double t1 = m.switch_fraction * m.duration, t2 = m.duration - t1;
  const Vec3 w = v + m.first * t1;
  const Vec3 x = v * t1 + 0.5 * m.first * t1 * t1;
  if (m.switch_fraction == 1.0) return {x, w};
  return {x + w * t2 + 0.5 * m.second * t2 * t2, w + m.second * t2};
}

TEST(GodMove, LeastAccelerationIsTheBruteForceMinimumOverTheSwitch) {
  double worst = 0.0;
  for (int trial = 0; trial < 400; ++trial) {
    const GodMoveEnds ends = RandomEnds();
    const double tau = LogUniform(0.1, 10.0);
    const double closed = GodMoveAcceleration(ends, tau);
    const long double brute = BruteForceLeastAcceleration(ends, tau);
    // The brute force can only find a larger maximum, and finds it to its precision.
    EXPECT_GE(brute, closed * (1.0 - 1e-13)) << trial;
    EXPECT_LE(brute, closed * (1.0 + 1e-9)) << trial;
    worst = std::max(worst, static_cast<double>(std::abs(brute - closed) / closed));
  }
  std::printf("closed form vs brute force: largest relative difference %.3g\n", worst);
}

TEST(GodMove, MovesMeetTheirEndsWithTheLeastAcceleration) {
  for (int trial = 0; trial < 2000; ++trial) {
    const GodMoveEnds ends = RandomEnds();
    const double tau = LogUniform(0.01, 100.0);
    const GodMove move = MakeGodMove(ends, tau);
    const double m = GodMoveAcceleration(ends, tau);
    const auto [x, v] = EndOfMove(move, ends.start_velocity);
    const double scale = ends.displacement.norm() + ends.start_velocity.norm() * tau + 1e-3;
    EXPECT_LE((x - ends.displacement).norm(), 1e-12 * scale) << trial;
    EXPECT_LE((v - ends.end_velocity).norm(), 1e-12 * (scale / tau)) << trial;
    EXPECT_LE(move.first.norm(), m * (1.0 + 1e-12)) << trial;
    if (move.switch_fraction < 1.0) {
      EXPECT_LE(move.second.norm(), m * (1.0 + 1e-12)) << trial;
    }
  }
}

TEST(GodMove, RestToRestTakesTheBangBangMinimumTime) {
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 d = RandomVector(LogUniform(1e-3, 1e3));
    const double a = LogUniform(1e-2, 1e3);
    const GodMoveEnds ends{d, Vec3::Zero(), Vec3::Zero()};
    const double minimum = 2.0 * std::sqrt(d.norm() / a);
    // Asked for less (or for "now"), it takes exactly the minimum: A for half, -A for half.
    const double asked = trial % 2 == 0 ? 0.0 : 0.3 * minimum;
    const double tau = EarliestGodMoveDuration(ends, a, asked);
    EXPECT_NEAR(tau, minimum, 1e-12 * minimum);
    const GodMove move = MakeGodMove(ends, tau);
    EXPECT_NEAR(move.switch_fraction, 0.5, 1e-12);
    EXPECT_NEAR(move.first.norm(), a, 1e-12 * a);
    EXPECT_NEAR(move.second.norm(), a, 1e-12 * a);
    EXPECT_NEAR(move.first.dot(d) / d.norm(), a, 1e-12 * a);  // towards the target first
    // Asked for more, it takes what was asked, gentler.
    EXPECT_EQ(EarliestGodMoveDuration(ends, a, 1.5 * minimum), 1.5 * minimum);
  }
}

// The earliest feasible duration against a scan of 300 durations from the one asked for:
// none before it is feasible by the brute force (its least largest |a| exceeds A), and it is.
TEST(GodMove, EarliestDurationIsTheFirstFeasibleOfABruteForceScan) {
  int lagged = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const GodMoveEnds ends = RandomEnds();
    const double a = LogUniform(0.1, 10.0);
    const double asked = LogUniform(0.01, 3.0);
    const double tau = EarliestGodMoveDuration(ends, a, asked);
    SCOPED_TRACE(::testing::Message() << "trial " << trial << " tau " << tau);
    ASSERT_GE(tau, asked);
    EXPECT_LE(GodMoveAcceleration(ends, tau), a * (1.0 + 1e-13));
    EXPECT_LE(BruteForceLeastAcceleration(ends, tau), a * (1.0 + 1e-9));
    if (tau == asked) continue;
    ++lagged;
    const int n = 300;
    for (int k = 0; k < n; ++k) {
      const double t = asked + (tau * (1.0 - 1e-6) - asked) * k / (n - 1);
      ASSERT_GT(BruteForceLeastAcceleration(ends, t), a) << "feasible earlier at " << t;
    }
  }
  std::printf("%d of 150 moves lagged\n", lagged);
  EXPECT_GT(lagged, 30);
}

// Coasting at 1 m/s passes 3 mm from the target 2 m ahead at 2 s, at the velocity asked for.
// With a weak hand (A = 0.01) only a narrow window around 2 s is feasible, then nothing
// until about 400 s (slowing down and coming back takes that long). Asked for 1 s, the move
// must take the window, not the long run.
TEST(GodMove, FindsAFeasibleWindowBeforeTheLongRun) {
  const GodMoveEnds ends{Vec3(2, 0.003, 0), Vec3(1, 0, 0), Vec3(1, 0, 0)};  // a bit aside
  const double tau = EarliestGodMoveDuration(ends, 0.01, 1.0);
  EXPECT_GT(tau, 1.99);
  EXPECT_LT(tau, 2.0);
  EXPECT_LE(BruteForceLeastAcceleration(ends, tau), 0.01 * (1.0 + 1e-9));
  for (double t = 1.0; t < tau * (1.0 - 1e-6); t += 0.001) {
    ASSERT_GT(BruteForceLeastAcceleration(ends, t), 0.01) << t;
  }
  EXPECT_GT(BruteForceLeastAcceleration(ends, 3.0), 0.01);  // the gap after the window
  EXPECT_GT(EarliestGodMoveDuration(ends, 0.01, 3.0), 300.0);
}

TEST(GodPlan, RandomTracksKeepTheBoundAndReachTheirTargets) {
  int on_time = 0, late = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const double a = LogUniform(1.0, 100.0);
    const double t0 = LogUniform(0.1, 100.0);
    std::vector<GodTarget> track;
    double t = t0;
    for (int i = 0; i < 1 + trial % 6; ++i) {
      t += LogUniform(0.2, 5.0);
      GodTarget target{t, RandomVector(2.0), std::nullopt};
      if (i % 3 == 1) target.velocity = RandomVector(1.0);
      track.push_back(target);
    }
    const Vec3 p = RandomVector(2.0), v = RandomVector(1.0);
    const GodPlan plan(t0, p, v, track, a);
    SCOPED_TRACE(::testing::Message() << "trial " << trial);
    const auto& pieces = plan.pieces();
    ASSERT_FALSE(pieces.empty());
    EXPECT_EQ(pieces.front().t0, t0);
    EXPECT_EQ(pieces.front().p0, p);
    EXPECT_EQ(pieces.front().v0, v);
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      EXPECT_LE(pieces[k].a.norm(), a * (1.0 + 1e-12));
      EXPECT_LT(pieces[k].t0, pieces[k].t1);
      if (k + 1 == pieces.size()) break;
      const GodPiece& next = pieces[k + 1];
      EXPECT_EQ(pieces[k].t1, next.t0);
      EXPECT_LE((pieces[k].PositionAt(next.t0) - next.p0).norm(), 1e-12 * (1 + next.p0.norm()));
      EXPECT_LE((pieces[k].VelocityAt(next.t0) - next.v0).norm(), 1e-12 * (1 + next.v0.norm()));
      EXPECT_EQ(plan.NextSwitchAfter(pieces[k].t0), pieces[k].t1);
      EXPECT_EQ(&plan.PieceAt(0.5 * (pieces[k].t0 + pieces[k].t1)), &pieces[k]);
    }
    EXPECT_EQ(plan.NextSwitchAfter(plan.EndTime()), kInfinity);
    // Each target: on time when it could be, otherwise late; its position (and velocity)
    // at its arrival.
    ASSERT_EQ(plan.arrival_times().size(), track.size());
    for (std::size_t i = 0; i < track.size(); ++i) {
      const double arrival = plan.arrival_times()[i];
      EXPECT_GE(arrival, track[i].time);
      (arrival == track[i].time ? on_time : late) += 1;
      const GodState s = plan.StateAt(arrival);
      EXPECT_LE((s.position - track[i].position).norm(), 1e-9 * (1 + track[i].position.norm()));
      if (track[i].velocity) {
        EXPECT_LE((s.velocity - *track[i].velocity).norm(), 1e-9 * (1 + track[i].velocity->norm()));
      }
    }
    // After the last target: still, or coasting at the velocity asked for.
    const GodState end = plan.StateAt(plan.EndTime() + 10.0);
    const Vec3 last_v = track.back().velocity ? *track.back().velocity : Vec3::Zero();
    EXPECT_LE((end.velocity - last_v).norm(), 1e-9 * (1 + last_v.norm()));
    EXPECT_EQ(end.acceleration, Vec3::Zero());
  }
  std::printf("targets on time %d, late %d\n", on_time, late);
  EXPECT_GT(on_time, 100);
  EXPECT_GT(late, 100);
}

// A lagging target is reached at the earliest feasible time from where the plan stood.
TEST(GodPlan, LateTargetIsReachedAsSoonAsItCanBe) {
  const std::vector<GodTarget> track = {{1.0, Vec3(10, 0, 0), std::nullopt}};
  const GodPlan plan(0.0, Vec3::Zero(), Vec3::Zero(), track, 2.0);
  EXPECT_NEAR(plan.arrival_times()[0], 2.0 * std::sqrt(10.0 / 2.0), 1e-12);
  EXPECT_EQ(plan.pieces().size(), 3u);  // accelerate, decelerate, hold
  EXPECT_EQ(plan.StateAt(100.0).position, plan.StateAt(plan.EndTime()).position);
}

// Waypoints without velocities along a line at a steady pace: the sweep gives each the
// pace's velocity, so the object glides through them without accelerating.
TEST(GodPlan, SteadyTrackIsSweptAtConstantVelocity) {
  const Vec3 pace(1.5, -0.5, 0.25);
  std::vector<GodTarget> track;
  for (int i = 1; i <= 5; ++i) track.push_back({2.0 * i, pace * (2.0 * i), std::nullopt});
  track.push_back({12.0, pace * 12.0, pace});
  const GodPlan plan(0.0, Vec3::Zero(), pace, track, 1.0);
  for (const GodPiece& piece : plan.pieces()) EXPECT_LE(piece.a.norm(), 1e-14);
  for (double t = 0.0; t < 20.0; t += 0.37) {
    EXPECT_LE((plan.StateAt(t).position - pace * t).norm(), 1e-12);
  }
}

TEST(GodPlan, ValidationNamesTheField) {
  const std::vector<GodTarget> ok = {{1.0, Vec3(1, 0, 0), std::nullopt},
                                     {2.0, Vec3(2, 0, 0), Vec3(0, 1, 0)}};
  EXPECT_TRUE(ValidateGodTrack(ok, 1.0).ok());
  EXPECT_EQ(ValidateGodTrack(ok, 0.0).error().message,
            "max_acceleration must be finite and > 0, got 0");
  EXPECT_FALSE(ValidateGodTrack(ok, NAN).ok());
  std::vector<GodTarget> back = ok;
  back[1].time = 1.0;
  EXPECT_EQ(ValidateGodTrack(back, 1.0).error().message,
            "track[1].time must be after track[0].time (1 <= 1)");
  std::vector<GodTarget> nan = ok;
  nan[1].velocity = Vec3(0, NAN, 0);
  EXPECT_EQ(ValidateGodTrack(nan, 1.0).error().message, "track[1].velocity must be finite");
  EXPECT_DEATH(GodPlan(0.0, Vec3::Zero(), Vec3::Zero(), back, 1.0), "ValidateGodTrack");
}

}  // namespace
}  // namespace sparsedyn
