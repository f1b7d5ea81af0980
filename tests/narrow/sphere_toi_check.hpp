// SPDX-License-Identifier: MIT
// The oracle cross-check of PredictSphereContact shared by the fast and slow tests: the
// polyhedron-pair motion cases of toi_cases.hpp with B replaced by a sphere (its centre on B's
// path), predicted (resuming after checkpoints, as the World does) and compared with the first
// time the sampled gap (the long double brute-force distance less the radius) reaches the
// tolerance. Optionally seen from the polyhedron's or the sphere's frame, which holds that one
// still (a static polyhedron, a static sphere) and leaves the relative motion unchanged.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <memory>

#include "narrow/sphere_contact.hpp"
#include "point_oracle.hpp"
#include "toi_check.hpp"

namespace sparsedyn::testing {

/// A sphere (radius, centre on motion.path_b.centre) and a polyhedron (motion.a on
/// motion.path_a); motion.b is null.
struct SphereCase {
  MotionCase motion;
  double radius = 0.0;
  std::string Describe() const {
    return motion.Describe() + ", sphere radius " + std::to_string(radius) + " on path B";
  }
};

/// Which body the case is seen from: none, the polyhedron's frame (it stands still) or the
/// sphere's. A frame translating with one body's centre path: both paths lose its velocity
/// and acceleration, so the relative motion, hence every contact time, is the same.
enum class Still : std::uint8_t { kNeither, kPolyhedron, kSphere };

inline SphereCase SphereFromPair(MotionCase pair, double radius_fraction, Still still) {
  SphereCase c{pair, radius_fraction * MotionCase::Radius(*pair.b)};
  c.motion.b = nullptr;
  c.motion.path_b.omega = Vec3::Zero();
  if (still != Still::kNeither) {
    const Path held = still == Still::kPolyhedron ? c.motion.path_a.centre : c.motion.path_b.centre;
    for (Path* p : {&c.motion.path_a.centre, &c.motion.path_b.centre}) {
      p->v0 -= held.v0;
      p->a -= held.a;
    }
  }
  return c;
}

inline SphereContactPrediction PredictSphereResuming(const SphereCase& c,
                                                     const ContactPredictionOptions& options,
                                                     int& iterations, int& checkpoints) {
  SphereContactPrediction p;
  double t = c.motion.t_begin;
  std::optional<FeatureId> warm;
  iterations = checkpoints = 0;
  for (int call = 0; call < 10000; ++call) {
    p = PredictSphereContact(*c.motion.a->tracked, c.motion.path_a, c.motion.path_b.centre,
                             c.radius, t, c.motion.t_end, warm, options);
    iterations += p.iterations;
    if (p.kind != ContactPrediction::Kind::kCheckpoint) break;
    ++checkpoints;
    t = p.time;
    warm = p.closest.feature;
  }
  return p;
}

/// `spin` = 0: the polyhedron translates (exact); otherwise it rotates (never late).
inline ToiFigures RunSphereCheck(std::uint64_t seed, int count, double spin, bool accelerate,
                                 Still still, double tolerance = kToiTolerance) {
  MotionCaseGenerator generator(seed);
  std::map<const Shape*, std::unique_ptr<PointOracle>> oracles;
  ToiFigures f;
  f.tolerance = tolerance;
  ContactPredictionOptions options;
  options.tolerance = tolerance;
  const bool exact = spin == 0.0;
  const double level = exact ? tolerance : options.advancement_target * tolerance;
  for (int trial = 0; trial < count; ++trial) {
    const double fraction = 0.1 + 0.9 * generator.Uniform();
    const SphereCase c = SphereFromPair(generator.Pair(spin, accelerate), fraction, still);
    SCOPED_TRACE("seed " + std::to_string(seed) + " trial " + std::to_string(trial) + ": " +
                 c.Describe());
    auto& oracle = oracles[c.motion.a];
    if (!oracle) oracle = std::make_unique<PointOracle>(*c.motion.a->polyhedron);
    int iterations = 0, checkpoints = 0;
    const auto start = std::chrono::steady_clock::now();
    const SphereContactPrediction p = PredictSphereResuming(c, options, iterations, checkpoints);
    f.prediction_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    f.checkpoints += checkpoints;
    // The gap at the returned time as the World sees it: the walk from the returned feature.
    const double gap_there =
        FindClosestFeatureToPoint(*c.motion.a->tracked, c.motion.path_a.PoseAt(p.time),
                                  c.motion.path_b.centre.PositionAt(p.time), p.closest.feature)
            .distance -
        c.radius;
    EXPECT_EQ(gap_there, p.gap) << "the reported gap is the walk's";
    auto gap = [&](double t) {
      return static_cast<double>(oracle->SignedDistance(c.motion.path_a.PoseAt(t),
                                                        c.motion.path_b.centre.PositionAt(t))) -
             c.radius;
    };
    // Exact predictions step past a gap that only grazes the tolerance within the round-off of
    // the walk's distance (PredictContact's rule: the World acts on a contact only where its
    // walk agrees), so no contact is a miss only if the gap goes below tolerance less that
    // round-off; a shallower graze is counted in f.tangent.
    const double min_step = kOracleMinStep * (c.motion.t_end - c.motion.t_begin);
    if (exact && p.kind != ContactPrediction::Kind::kContact &&
        !FirstTimeBelow(gap, c.motion.Lipschitz(), tolerance - kContactRoundOff, c.motion.t_begin,
                        c.motion.t_end, min_step)
             .time &&
        FirstTimeBelow(gap, c.motion.Lipschitz(), tolerance, c.motion.t_begin, c.motion.t_end,
                       min_step)
            .time) {
      ++f.cases;
      ++f.tangent;
      continue;
    }
    CheckAgainstOracle(c.motion, p.kind, p.time, gap_there, iterations, exact, level, gap, f);
  }
  return f;
}

}  // namespace sparsedyn::testing
