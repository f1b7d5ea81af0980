// SPDX-License-Identifier: MIT
// The oracle cross-check of contact prediction shared by the fast and slow tests: every random
// case is predicted (resuming after checkpoints, as the World does) and compared with the
// first time the sampled distance (cold-started walk, or brute force over vertices for walls)
// drops to the tolerance.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>

#include "narrow/time_of_contact.hpp"
#include "toi_cases.hpp"
#include "toi_oracle.hpp"

namespace sparsedyn::testing {

// Contact tolerance of the random cases (their polyhedra have radii 0.1-1.5 m).
inline constexpr double kToiTolerance = 1e-4;
// Translating predictions are exact: allowed time error (s) for cases that last ~1-20 s at
// speeds ~1 m/s (issue's bound: 1e-9 x the scene scale; measured: 2.3e-12 s on aligned boxes,
// 6e-15 s on random pairs).
inline constexpr double kToiTimeError = 1e-10;
// The distance an exact prediction may exceed the tolerance by at its contact time: 1e-12 x the
// scale (time_of_contact.cpp), for scales up to 4 here.
inline constexpr double kContactRoundOff = 4e-12;
// The oracle's smallest sampling step as a fraction of the case's duration.
inline constexpr double kOracleMinStep = 2e-6;

struct ToiFigures {
  double tolerance = kToiTolerance;
  int tangent = 0;  // exact contacts where the distance only touches the tolerance (to 1e-12)
  int cases = 0, contacts = 0, oracle_contacts = 0;
  int missed = 0, late = 0, mismatched = 0, too_far = 0;
  double max_time_error = 0.0;        // translating: |predicted - oracle|
  double max_contact_distance = 0.0;  // largest distance at a returned contact / tolerance
  long iterations = 0;
  int max_iterations = 0, checkpoints = 0, advancement_steps = 0;
  long oracle_samples = 0;
  double prediction_seconds = 0.0;  // CPU time in the predictions (printed, never asserted)

  // Cases that break a guarantee: missed, late, too far at contact, and (exact predictions
  // only) a time off the oracle's.
  int Errors(bool exact) const { return missed + late + too_far + (exact ? mismatched : 0); }
  double MeanIterations() const { return cases ? static_cast<double>(iterations) / cases : 0.0; }
  void Print(const char* what) const {
    std::printf(
        "[toi] %s: %d cases, %d contacts (oracle %d), missed %d, late %d, mismatched %d, "
        "max time error %.3g s, max distance at contact %.6g tol, iterations mean %.2f max %d, "
        "checkpoints %d, fallback advancement steps %d, tangent %d, oracle samples %ld, %.2f us "
        "per prediction (tolerance %g)\n",
        what, cases, contacts, oracle_contacts, missed, late, mismatched, max_time_error,
        max_contact_distance, MeanIterations(), max_iterations, checkpoints, advancement_steps,
        tangent, oracle_samples, cases ? 1e6 * prediction_seconds / cases : 0.0, tolerance);
  }
};

// Prints the figures (the log line the docs quote) and fails on any broken guarantee.
inline void ExpectNoErrors(const ToiFigures& f, const char* what, bool exact) {
  f.Print(what);
  EXPECT_EQ(f.Errors(exact), 0) << what;
}

// The prediction resumed after each checkpoint, as the World's detail events do.
struct Resumed {
  ContactPrediction last;
  int iterations = 0, checkpoints = 0, advancement_steps = 0;
};
inline Resumed PredictResuming(const MotionCase& c, const ContactPredictionOptions& options) {
  Resumed r;
  double t = c.t_begin;
  std::optional<FeaturePair> warm;
  for (int call = 0; call < 10000; ++call) {
    r.last =
        PredictContact(*c.a->tracked, c.path_a, *c.b->tracked, c.path_b, t, c.t_end, warm, options);
    r.iterations += r.last.iterations;
    r.advancement_steps += r.last.advancement_steps;
    if (r.last.kind != ContactPrediction::Kind::kCheckpoint) break;
    ++r.checkpoints;
    t = r.last.time;
    warm = r.last.features.features;
  }
  return r;
}

inline double ColdDistance(const MotionCase& c, double t) {
  return FindClosestFeatures(*c.a->tracked, c.path_a.PoseAt(t), *c.b->tracked, c.path_b.PoseAt(t))
      .distance;
}

// The distance at a prediction's time as the World sees it: the walk warm-started from the
// returned features (a cold walk may differ by round-off when several pairs are as close).
inline double WarmDistance(const MotionCase& c, const ContactPrediction& p) {
  return FindClosestFeatures(*c.a->tracked, c.path_a.PoseAt(p.time), *c.b->tracked,
                             c.path_b.PoseAt(p.time), p.features.features)
      .distance;
}

// Compares one prediction with the oracle's first times at `level` (translating: the exact
// time; rotating: the prediction may be earlier, never later, and must hold d <= tolerance).
inline void CheckAgainstOracle(const MotionCase& c, ContactPrediction::Kind kind, double time,
                               double distance_at_time, int iterations, bool exact, double level,
                               const std::function<double(double)>& distance, ToiFigures& f) {
  const SampledFirstTime oracle = FirstTimeBelow(distance, c.Lipschitz(), level, c.t_begin, c.t_end,
                                                 kOracleMinStep * (c.t_end - c.t_begin));
  ++f.cases;
  f.oracle_samples += oracle.samples;
  f.iterations += iterations;
  f.max_iterations = std::max(f.max_iterations, iterations);
  const bool contact = kind == ContactPrediction::Kind::kContact;
  f.contacts += contact;
  f.oracle_contacts += oracle.time.has_value();
  if (contact) {
    f.max_contact_distance = std::max(f.max_contact_distance, distance_at_time / f.tolerance);
    if (distance_at_time > f.tolerance) {  // the World acts only where the walk agrees
      ++f.too_far;
      ADD_FAILURE() << "distance " << distance_at_time << " at the contact time " << time;
    }
  }
  if (oracle.time && !contact) {
    ++f.missed;
    ADD_FAILURE() << "missed: oracle contact at " << *oracle.time;
    return;
  }
  if (!oracle.time) {
    // A distance that only touches the tolerance (to round-off) at one instant is a contact the
    // sampling cannot see.
    if (contact && exact && distance_at_time >= f.tolerance - kContactRoundOff) {
      ++f.tangent;
    } else if (contact && exact) {
      ++f.mismatched;
      ADD_FAILURE() << "contact at " << time << " that the oracle does not see";
    }
    return;
  }
  if (time > *oracle.time + kToiTimeError) {
    ++f.late;
    ADD_FAILURE() << "late: " << time << " after the oracle's " << *oracle.time;
  }
  if (exact) {
    const double error = std::abs(time - *oracle.time);
    f.max_time_error = std::max(f.max_time_error, error);
    if (error > kToiTimeError) {
      ++f.mismatched;
      ADD_FAILURE() << "time " << time << " vs the oracle's " << *oracle.time;
    }
  }
}

// `spin` = 0: translating pairs (exact); otherwise rotating pairs (never late).
// `aligned`: the degenerate AlignedPair cases (translating) instead of random ones.
inline ToiFigures RunPairCheck(std::uint64_t seed, int count, double spin, bool accelerate,
                               bool aligned = false, double tolerance = kToiTolerance) {
  MotionCaseGenerator generator(seed);
  ToiFigures f;
  f.tolerance = tolerance;
  ContactPredictionOptions options;
  options.tolerance = tolerance;
  const bool exact = spin == 0.0;
  const double level = exact ? tolerance : options.advancement_target * tolerance;
  for (int trial = 0; trial < count; ++trial) {
    const MotionCase c = aligned ? generator.AlignedPair() : generator.Pair(spin, accelerate);
    SCOPED_TRACE("seed " + std::to_string(seed) + " trial " + std::to_string(trial) + ": " +
                 c.Describe());
    const auto start = std::chrono::steady_clock::now();
    const Resumed r = PredictResuming(c, options);
    f.prediction_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    f.checkpoints += r.checkpoints;
    f.advancement_steps += r.advancement_steps;
    CheckAgainstOracle(
        c, r.last.kind, r.last.time, WarmDistance(c, r.last), r.iterations, exact, level,
        [&](double t) { return ColdDistance(c, t); }, f);
  }
  return f;
}

// Walls n.x = 0 with random normals; the oracle's distance is brute force over the vertices.
inline ToiFigures RunWallCheck(std::uint64_t seed, int count, double spin, bool accelerate) {
  MotionCaseGenerator generator(seed);
  ToiFigures f;
  const bool exact = spin == 0.0;
  const double level = exact ? kToiTolerance : kAdvancementTarget * kToiTolerance;
  for (int trial = 0; trial < count; ++trial) {
    const Vec3 normal = generator.random().RandomUnit();
    const MotionCase c = generator.Wall(normal, spin, accelerate);
    SCOPED_TRACE("seed " + std::to_string(seed) + " trial " + std::to_string(trial) +
                 ": wall normal (" + std::to_string(normal.x()) + " " + std::to_string(normal.y()) +
                 " " + std::to_string(normal.z()) + "), " + c.Describe());
    auto distance = [&](double t) {
      const Pose X = c.path_a.PoseAt(t);
      double d = std::numeric_limits<double>::infinity();
      for (const Vec3& v : c.a->polyhedron->vertices()) d = std::min(d, normal.dot(X.ToWorld(v)));
      return d;
    };
    WallContactPrediction p;
    int iterations = 0, calls = 0;
    double t = c.t_begin;
    const auto start = std::chrono::steady_clock::now();
    do {
      p = PredictWallContact(*c.a->tracked, c.path_a, normal, 0.0, t, c.t_end, kToiTolerance);
      iterations += p.iterations;
      t = p.time;
      f.checkpoints += p.kind == ContactPrediction::Kind::kCheckpoint;
    } while (p.kind == ContactPrediction::Kind::kCheckpoint && ++calls < 10000);
    f.prediction_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_NEAR(p.gap, distance(p.time), 1e-12) << "the reported gap is the nearest vertex's";
    CheckAgainstOracle(c, p.kind, p.time, distance(p.time), iterations, exact, level, distance, f);
  }
  return f;
}

}  // namespace sparsedyn::testing
