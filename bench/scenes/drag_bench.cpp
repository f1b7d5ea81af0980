// SPDX-License-Identifier: MIT
// Drag on every body (issue #36 part 5 and its target: at most 2x the events of the same scene
// without drag): the gas preset (periodic box, packing 0.05) run twice in one process over the
// same simulated time, without drag and with drag on every body, and the ratios of their events
// and CPU times reported next to each run's own figures (the peer is the same scene in the same
// run, so the machine's load cancels).
#include <benchmark/benchmark.h>

#include <cmath>
#include <ctime>

#include "bench/support/enskog_rate.hpp"
#include "scenes/gas.hpp"

namespace sparsedyn {
namespace {

using bench::CollisionRate;

struct Run {
  double events = 0, collisions = 0, checks = 0, steps = 0, cpu_seconds = 0;
  double energy_kept = 0;  // final / initial kinetic energy
};

// The gas of n bodies over `collisions_per_particle` (at the Enskog rate without drag), with
// `drag` on every body.
Run RunGas(std::uint32_t n, double collisions_per_particle, const Drag& drag,
           Broadphase broadphase) {
  scenes::GasOptions options;
  options.n = n;
  WorldSettings settings;
  settings.drag = drag;
  settings.broadphase = broadphase;
  World world = *scenes::MakeGas(options, settings);
  const double energy = world.KineticEnergy();
  const std::clock_t start = std::clock();
  Run run;
  if (!world.AdvanceTo(collisions_per_particle / CollisionRate(options.packing))) return run;
  run.cpu_seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  const Statistics& stats = world.Stats();
  run.events = static_cast<double>(stats.events);
  run.collisions = static_cast<double>(stats.collisions);
  run.checks = static_cast<double>(stats.drag_checks);
  run.steps = static_cast<double>(stats.drag_steps);
  run.energy_kept = world.KineticEnergy() / energy;
  return run;
}

// range(0) = N, range(1) = drag kind: 1 linear only (c1 = 0.05/s), 2 quadratic only
// (c2 = 0.05/m), 3 both; range(2): 0 AllPairs, 1 Grid.
void BM_GasWithDrag(benchmark::State& state) {
  const auto n = static_cast<std::uint32_t>(state.range(0));
  const int kind = static_cast<int>(state.range(1));
  const Drag drag{kind & 1 ? 0.05 : 0.0, kind & 2 ? 0.05 : 0.0};
  const Broadphase broadphase = state.range(2) == 1 ? Broadphase::kGrid : Broadphase::kAllPairs;
  constexpr double kCollisionsPerParticle = 5.0;
  Run plain, dragged;
  for (auto _ : state) {
    plain = RunGas(n, kCollisionsPerParticle, Drag{}, broadphase);
    dragged = RunGas(n, kCollisionsPerParticle, drag, broadphase);
  }
  if (plain.events == 0 || dragged.events == 0) {
    state.SkipWithError("a run stalled");
    return;
  }
  state.counters["events_plain"] = plain.events;
  state.counters["events_drag"] = dragged.events;
  state.counters["events_ratio"] = dragged.events / plain.events;  // target <= 2
  state.counters["collisions_ratio"] = dragged.collisions / plain.collisions;
  state.counters["checks/body"] = dragged.checks / n;
  state.counters["steps/collision"] = dragged.steps / dragged.collisions;
  state.counters["cpu_s_plain"] = plain.cpu_seconds;
  state.counters["cpu_s_drag"] = dragged.cpu_seconds;
  state.counters["time_ratio"] = dragged.cpu_seconds / plain.cpu_seconds;
  state.counters["energy_kept"] = dragged.energy_kept;
}

BENCHMARK(BM_GasWithDrag)
    ->ArgsProduct({{1000, 10000}, {1, 2, 3}, {1}})
    ->Args({1000, 3, 0})
    ->ArgNames({"n", "linear1_quadratic2_both3", "allpairs0_grid1"})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace sparsedyn

BENCHMARK_MAIN();
