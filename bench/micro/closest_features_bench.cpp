// SPDX-License-Identifier: MIT
// Our closest-feature tracking alone on the §7.3 cases (thesis App. J.2): warm-started updates
// per spin angle and face count, and cold starts with and without the J.1.2 direction table.
// bench/peers/closest_features_peers_bench.cpp runs the same cases next to FCL and Bullet.
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "bench/support/closest_features_cases.hpp"

namespace sparsedyn::bench {
namespace {

// The cases live until the program ends; benchmarks keep raw pointers to them.
std::vector<std::unique_ptr<ClosestFeaturesCase>>& Cases() {
  static std::vector<std::unique_ptr<ClosestFeaturesCase>> cases;
  return cases;
}

void RegisterAll() {
  for (const int faces : kFaceCounts) {
    for (const double degrees : kDegreesPerStep) {
      const ClosestFeaturesCase* c =
          Cases().emplace_back(MakeClosestFeaturesCase(faces, degrees)).get();
      benchmark::RegisterBenchmark(CaseName("ours_warm", *c).c_str(), BM_OursWarm, c);
      if (degrees != kColdStartDegrees) continue;
      benchmark::RegisterBenchmark(CaseName("ours_cold_table", *c).c_str(), BM_OursCold, c, true);
      benchmark::RegisterBenchmark(CaseName("ours_cold_plain", *c).c_str(), BM_OursCold, c, false);
    }
  }
}

}  // namespace
}  // namespace sparsedyn::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  sparsedyn::bench::RegisterAll();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
