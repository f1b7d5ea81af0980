// SPDX-License-Identifier: MIT
// The hard-sphere gas (issue #2's benchmark): collisions/s and events/s on one core for
// N = 10^3 .. 10^6 at packing 0.05, 0.10, 0.30, AllPairs vs Grid; bytes per body; stale
// fraction. Each run builds the gas, lets it settle for 2 collisions per particle (not timed),
// then times a stretch of about 20 collisions per particle (fewer at large N).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>

#include "scenes/gas.hpp"

namespace sparsedyn {
namespace {

// Enskog collision rate per particle (sigma = 1, kT = m = 1), to size the simulated stretch.
double CollisionRate(double packing) {
  const double n = 6 * packing / M_PI;
  const double g = (1 - packing / 2) / std::pow(1 - packing, 3);
  return 4 * n * g * std::sqrt(M_PI);
}

void BM_Gas(benchmark::State& state) {
  const auto n = static_cast<std::uint32_t>(state.range(0));
  const double packing = static_cast<double>(state.range(1)) / 100.0;
  const auto broadphase = static_cast<Broadphase>(state.range(2));
  const double per_particle = n >= 1000000 ? 4.0 : (n >= 100000 ? 10.0 : 20.0);
  scenes::GasOptions options;
  options.n = n;
  options.packing = packing;
  WorldSettings settings;
  settings.broadphase = broadphase;
  double collisions = 0, events = 0, stale = 0, seconds = 0, bytes = 0;
  for (auto _ : state) {
    state.PauseTiming();
    World world = *scenes::MakeGas(options, settings);
    const double rate = CollisionRate(packing);
    if (!world.AdvanceTo(2.0 / rate)) state.SkipWithError("stalled");
    const Statistics before = world.Stats();
    state.ResumeTiming();
    const auto start = std::chrono::steady_clock::now();
    if (!world.AdvanceTo((2.0 + per_particle) / rate)) state.SkipWithError("stalled");
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.PauseTiming();
    const Statistics& after = world.Stats();
    collisions += static_cast<double>(after.collisions - before.collisions);
    events += static_cast<double>(after.events - before.events);
    stale += static_cast<double>(after.stale_target_absent + after.stale_actor_absent -
                                 before.stale_target_absent - before.stale_actor_absent);
    bytes = static_cast<double>(world.MemoryBytes()) / n;
    state.ResumeTiming();
  }
  state.counters["collisions/s"] = collisions / seconds;
  state.counters["events/s"] = events / seconds;
  state.counters["events/collision"] = events / collisions;
  state.counters["stale/event"] = stale / events;
  state.counters["bytes/body"] = bytes;
}

void GasArguments(benchmark::internal::Benchmark* b) {
  for (const int packing : {5, 10, 30}) {
    for (const int n : {1000, 10000, 100000, 1000000}) {
      b->Args({n, packing, static_cast<int>(Broadphase::kGrid)});
    }
    for (const int n : {1000, 10000}) b->Args({n, packing, static_cast<int>(Broadphase::kAllPairs)});
  }
}

BENCHMARK(BM_Gas)->Apply(GasArguments)->ArgNames({"n", "packing%", "allpairs0_grid1"})
    ->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace sparsedyn

BENCHMARK_MAIN();
