// SPDX-License-Identifier: MIT
// The cases of the §7.3 feature-tracking benchmark (thesis App. J.2) and our own closest-feature
// benchmarks over them, shared by bench/micro/closest_features_bench.cpp (ours alone) and
// bench/peers/closest_features_peers_bench.cpp (ours next to FCL and Bullet in one process).
#pragma once

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scenes/rotating_pair.hpp"
#include "sparsedyn/narrow/closest_features.hpp"

namespace sparsedyn::bench {

/// Face counts and spin angles of the experiment (thesis §7.3: 1°, 5° and 25° per step).
inline const std::vector<int> kFaceCounts = {8, 16, 32, 64, 128, 256, 512, 1000};
inline const std::vector<double> kDegreesPerStep = {1.0, 5.0, 25.0};
/// Cold starts are timed on the poses of this angle (they do not depend on it).
inline constexpr double kColdStartDegrees = 5.0;

/// One case: the pose sequence and the polyhedra with the walk's tables.
struct ClosestFeaturesCase {
  scenes::RotatingPair pair;
  std::unique_ptr<TrackedPolyhedron> a;
  std::unique_ptr<TrackedPolyhedron> b;
};

/// Builds the case or exits with the error (a benchmark program has nobody to return it to).
inline std::unique_ptr<ClosestFeaturesCase> MakeClosestFeaturesCase(int faces, double degrees) {
  Result<scenes::RotatingPair> pair =
      scenes::MakeRotatingPair({.faces = faces, .degrees_per_step = degrees});
  if (!pair) {
    std::fprintf(stderr, "%s\n", pair.error().message.c_str());
    std::exit(1);
  }
  auto c = std::make_unique<ClosestFeaturesCase>();
  c->pair = std::move(*pair);
  c->a = std::make_unique<TrackedPolyhedron>(c->pair.a);
  c->b = std::make_unique<TrackedPolyhedron>(c->pair.b);
  return c;
}

/// The benchmark name of an engine on a case, e.g. "fcl_libccd/deg:5/faces:64". (Built by
/// appending: "literal" + std::string&& trips GCC 12's false -Wrestrict, GCC bug 105329.)
inline std::string CaseName(std::string engine, const ClosestFeaturesCase& c) {
  engine += "/deg:";
  engine += std::to_string(static_cast<int>(c.pair.options.degrees_per_step));
  engine += "/faces:";
  engine += std::to_string(c.pair.options.faces);
  return engine;
}

/// Counters every benchmark of a case reports, so that scripts can group rows.
inline void SetCaseCounters(benchmark::State& state, const ClosestFeaturesCase& c) {
  state.counters["faces"] = c.pair.options.faces;
  state.counters["deg"] = c.pair.options.degrees_per_step;
}

/// Our warm-started tracking: one ClosestFeatureTracker::Update per iteration along the loop of
/// poses, after one untimed lap so that every timed update is warm.
inline void BM_OursWarm(benchmark::State& state, const ClosestFeaturesCase* c) {
  const scenes::RotatingPair& pair = c->pair;
  ClosestFeatureTracker tracker(*c->a, *c->b);
  for (const Pose& X_WA : pair.X_WA) tracker.Update(X_WA, pair.X_WB);
  const std::uint64_t calls0 = tracker.calls(), steps0 = tracker.steps();
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(tracker.Update(pair.X_WA[k], pair.X_WB).distance);
    if (++k == pair.X_WA.size()) k = 0;
  }
  SetCaseCounters(state, *c);
  state.counters["steps/update"] =
      static_cast<double>(tracker.steps() - steps0) / static_cast<double>(tracker.calls() - calls0);
  state.counters["cap_failures"] = static_cast<double>(tracker.iteration_cap_failures());
}

/// Cold starts: FindClosestFeatures with no previous pair, from the J.1.2 direction table or
/// (use_direction_table false) from vertex 0 of each polyhedron.
inline void BM_OursCold(benchmark::State& state, const ClosestFeaturesCase* c,
                        bool use_direction_table) {
  const scenes::RotatingPair& pair = c->pair;
  ClosestFeaturesOptions options;
  options.use_direction_table = use_direction_table;
  std::size_t k = 0;
  std::uint64_t steps = 0, calls = 0;
  for (auto _ : state) {
    const ClosestFeatures result =
        FindClosestFeatures(*c->a, pair.X_WA[k], *c->b, pair.X_WB, std::nullopt, options);
    benchmark::DoNotOptimize(result.distance);
    steps += static_cast<std::uint64_t>(result.steps);
    ++calls;
    if (++k == pair.X_WA.size()) k = 0;
  }
  SetCaseCounters(state, *c);
  state.counters["steps/update"] = static_cast<double>(steps) / static_cast<double>(calls);
}

/// Our signed distance at every pose of the loop (warm-started), for the agreement checks.
inline std::vector<double> OursDistances(const ClosestFeaturesCase& c) {
  ClosestFeatureTracker tracker(*c.a, *c.b);
  std::vector<double> distances;
  distances.reserve(c.pair.X_WA.size());
  for (const Pose& X_WA : c.pair.X_WA)
    distances.push_back(tracker.Update(X_WA, c.pair.X_WB).distance);
  return distances;
}

}  // namespace sparsedyn::bench
