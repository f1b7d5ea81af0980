// SPDX-License-Identifier: MIT
// The brute-force cross-check shared by the fast (a few thousand pairs) and slow (2e4 pairs)
// tests: cold start, warm start, plain walk and the long double oracle must agree.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "narrow_oracles.hpp"
#include "pair_generator.hpp"

namespace sparsedyn::testing {

// Error bound of issue #3: 1e-9 x the larger bounding diameter.
inline constexpr double kRelativeErrorBound = 1e-9;

struct OracleFigures {
  int pairs = 0, degenerate = 0, separated = 0, cap_failures = 0;
  double max_relative_error = 0.0;
  long long cold_steps = 0, warm_steps = 0;
  int max_cold_steps = 0;
};

inline OracleFigures RunOracleCheck(std::uint64_t seed, int pair_count) {
  PairGenerator generator(seed);
  OracleFigures figures;
  ClosestFeaturesOptions plain;
  plain.use_angle_tables = false;
  plain.use_direction_table = false;
  for (int trial = 0; trial < pair_count; ++trial) {
    const PlacedPair pair = generator.Next();
    SCOPED_TRACE(::testing::Message()
                 << "seed " << seed << " trial " << trial << ": " << pair.Describe());
    const TrackedPolyhedron& a = *pair.a->tracked;
    const TrackedPolyhedron& b = *pair.b->tracked;
    const double bound = kRelativeErrorBound * pair.Diameter();
    const double reference = static_cast<double>(
        ReferenceSignedDistance(*pair.a->polyhedron, pair.X_WA, *pair.b->polyhedron, pair.X_WB));

    const ClosestFeatures cold = FindClosestFeatures(a, pair.X_WA, b, pair.X_WB);
    ++figures.pairs;
    figures.degenerate += pair.degenerate ? 1 : 0;
    figures.separated += reference > 0.0 ? 1 : 0;
    figures.cap_failures += cold.status == ClosestFeatures::Status::kIterationCap ? 1 : 0;
    figures.cold_steps += cold.steps;
    figures.max_cold_steps = std::max(figures.max_cold_steps, cold.steps);
    const double error = std::abs(cold.distance - reference);
    figures.max_relative_error = std::max(figures.max_relative_error, error / pair.Diameter());
    EXPECT_LE(error, bound) << "walk " << cold.distance << " reference " << reference;
    EXPECT_EQ(cold.status == ClosestFeatures::Status::kSeparated, cold.distance > 0.0);

    // Witnesses: on the surfaces, distance apart along the normal.
    EXPECT_NEAR(SurfaceOffset(*pair.a->polyhedron, pair.X_WA, cold.point_a), 0.0, bound);
    EXPECT_NEAR(SurfaceOffset(*pair.b->polyhedron, pair.X_WB, cold.point_b), 0.0, bound);
    EXPECT_NEAR(cold.normal.norm(), 1.0, 1e-12);
    EXPECT_NEAR(cold.normal.dot(cold.point_b - cold.point_a), cold.distance, bound);

    // The plain walk (no tables, cold start at vertex 0) finds the same distance.
    const ClosestFeatures walked =
        FindClosestFeatures(a, pair.X_WA, b, pair.X_WB, std::nullopt, plain);
    EXPECT_LE(std::abs(walked.distance - cold.distance), bound);
    figures.cap_failures += walked.status == ClosestFeatures::Status::kIterationCap ? 1 : 0;

    // Warm start from a random feature pair: same distance, and an equally close feature pair.
    const auto& pa = *pair.a->polyhedron;
    const auto& pb = *pair.b->polyhedron;
    const FeaturePair start{FeatureId::Face(static_cast<int>(
                                generator.rng()() % static_cast<std::uint64_t>(pa.face_count()))),
                            FeatureId::Edge(static_cast<int>(
                                generator.rng()() % static_cast<std::uint64_t>(pb.edge_count())))};
    const ClosestFeatures warm = FindClosestFeatures(a, pair.X_WA, b, pair.X_WB, start);
    figures.warm_steps += warm.steps;
    figures.cap_failures += warm.status == ClosestFeatures::Status::kIterationCap ? 1 : 0;
    EXPECT_LE(std::abs(warm.distance - cold.distance), bound);
    if (std::abs(cold.distance) > bound) {
      EXPECT_EQ(warm.status, cold.status);
    }
    // Re-entering from the answer takes no step and returns the same pair.
    const ClosestFeatures again = FindClosestFeatures(a, pair.X_WA, b, pair.X_WB, cold.features);
    EXPECT_LE(std::abs(again.distance - cold.distance), bound);
    if (cold.status == ClosestFeatures::Status::kSeparated) {
      EXPECT_EQ(again.steps, 0);
      EXPECT_EQ(again.features, cold.features);
    }
  }
  return figures;
}

inline void PrintFigures(const char* label, const OracleFigures& f) {
  std::printf(
      "%s: %d pairs, %.1f%% degenerate, %.1f%% separated, max error %.3g x diameter, "
      "cold steps mean %.2f max %d, warm (random start) steps mean %.2f, cap failures %d\n",
      label, f.pairs, 100.0 * f.degenerate / f.pairs, 100.0 * f.separated / f.pairs,
      f.max_relative_error, static_cast<double>(f.cold_steps) / f.pairs, f.max_cold_steps,
      static_cast<double>(f.warm_steps) / f.pairs, f.cap_failures);
}

inline void ExpectFiguresInRange(const OracleFigures& f) {
  EXPECT_EQ(f.cap_failures, 0);
  EXPECT_GE(f.degenerate, 0.3 * f.pairs);
  EXPECT_GE(f.separated, 0.4 * f.pairs);
  EXPECT_LE(f.separated, 0.8 * f.pairs);
  EXPECT_LE(f.max_relative_error, kRelativeErrorBound);
}

}  // namespace sparsedyn::testing
