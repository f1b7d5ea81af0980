// SPDX-License-Identifier: MIT
// The hard-sphere gas (issue #2's benchmark): collisions/s and events/s on one core for
// N = 10^3 .. 10^6 (and 10^7 at 0.05) at packing 0.05, 0.10, 0.30, AllPairs vs Grid; bytes per
// body; stale fraction. Each run builds the gas, lets it settle for 2 collisions per particle (0.5
// at 10^7; not timed), then times a stretch of about 20 collisions per particle (fewer at large N).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <optional>
#include <string>

#include "bench/support/enskog_rate.hpp"
#include "bench/support/turns.hpp"
#include "scenes/gas.hpp"
#include "scenes/random.hpp"

namespace sparsedyn {
namespace {

using bench::CollisionRate;

// Collisions per particle in the timed stretch: shorter at large N keeps a run within minutes
// (10^7: ~5 million collisions). SPARSEDYN_GAS_STRETCH overrides it: A/B comparisons on a noisy
// machine want stretches of seconds, whose time averages over the machine's short swings.
double StretchPerParticle(std::uint32_t n) {
  if (const char* text = std::getenv("SPARSEDYN_GAS_STRETCH")) {
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    if (end != text && *end == '\0' && value > 0 && std::isfinite(value)) return value;
    std::fprintf(stderr, "SPARSEDYN_GAS_STRETCH=%s: not a positive number; ignored\n", text);
  }
  return n >= 10000000 ? 1.0 : (n >= 1000000 ? 4.0 : (n >= 100000 ? 10.0 : 20.0));
}

// Runs the gas of `n` bodies at `packing` and reports the counters below.
void RunGas(benchmark::State& state, std::uint32_t n, double packing, Broadphase broadphase,
            double cells_per_body) {
  const double per_particle = StretchPerParticle(n);
  const double settle = n >= 10000000 ? 0.5 : 2.0;
  scenes::GasOptions options;
  options.n = n;
  options.packing = packing;
  WorldSettings settings;
  settings.broadphase = broadphase;
  settings.grid_cells_per_body = cells_per_body;
  double collisions = 0, events = 0, stale = 0, seconds = 0, cpu_seconds = 0, bytes = 0;
  double pair_tests = 0, simulated = 0;
  for (auto _ : state) {
    state.PauseTiming();
    World world = *scenes::MakeGas(options, settings);
    const double rate = CollisionRate(packing);
    if (!world.AdvanceTo(settle / rate)) state.SkipWithError("stalled");
    const Statistics before = world.Stats();
    std::string error;
    const std::optional<bench::Turns> turns = bench::Turns::FromEnvironment(error);
    if (!turns || !turns->Ready()) {
      state.SkipWithError(turns ? "SPARSEDYN_GAS_TURNS: cannot create the READY file" : error.c_str());
      break;
    }
    state.ResumeTiming();
    // The stretch in slices, each on this process's turn (one slice without turns).
    for (int slice = 1; slice <= turns->Slices(); ++slice) {
      if (!turns->Wait()) state.SkipWithError("SPARSEDYN_GAS_TURNS: the IN pipe failed");
      const auto start = std::chrono::steady_clock::now();
      const std::clock_t cpu_start = std::clock();
      const double end = settle + per_particle * slice / turns->Slices();
      if (!world.AdvanceTo(end / rate)) state.SkipWithError("stalled");
      cpu_seconds += static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!turns->Pass()) state.SkipWithError("SPARSEDYN_GAS_TURNS: the OUT pipe failed");
    }
    simulated += per_particle / rate;
    state.PauseTiming();
    const Statistics& after = world.Stats();
    collisions += static_cast<double>(after.collisions - before.collisions);
    events += static_cast<double>(after.events - before.events);
    pair_tests += static_cast<double>(after.pair_tests - before.pair_tests);
    stale += static_cast<double>(after.stale_target_absent + after.stale_actor_absent -
                                 before.stale_target_absent - before.stale_actor_absent);
    bytes = static_cast<double>(world.MemoryBytes()) / n;
    state.ResumeTiming();
  }
  state.counters["collisions/s"] = collisions / seconds;
  // CPU time of this thread's process: robust against other jobs on a shared machine.
  state.counters["collisions/cpu_s"] = collisions / cpu_seconds;
  state.counters["pair_tests/collision"] = pair_tests / collisions;
  // App. I.1-I.2: collisions while every body moves one radius r (mean speed sqrt(8/pi) at
  // kT = m = 1), against the thesis's C = (3 sqrt(2) / 2) D N (dilute limit, no g(sigma)), and
  // the thesis's pair tests per collision for AllPairs, 2 N (1 + stale / 4).
  const double radius_time = options.radius / std::sqrt(8.0 / M_PI);
  state.counters["C_measured/N"] = collisions / simulated * radius_time / n;
  state.counters["C_thesis/N"] = 1.5 * std::sqrt(2.0) * packing;
  state.counters["tests_thesis/collision"] = 2.0 * n * (1.0 + stale / events / 4.0);
  state.counters["events/s"] = events / seconds;
  state.counters["events/collision"] = events / collisions;
  state.counters["stale/event"] = stale / events;
  state.counters["bytes/body"] = bytes;
}

void BM_Gas(benchmark::State& state) {
  RunGas(state, static_cast<std::uint32_t>(state.range(0)),
         static_cast<double>(state.range(1)) / 100.0, static_cast<Broadphase>(state.range(2)),
         WorldSettings{}.grid_cells_per_body);
}

// The cell size choice: fewer cells mean fewer crossings but more pair tests per prediction.
void BM_GasCells(benchmark::State& state) {
  RunGas(state, static_cast<std::uint32_t>(state.range(0)),
         static_cast<double>(state.range(1)) / 100.0, Broadphase::kGrid,
         static_cast<double>(state.range(2)) / 10.0);
}

// Curved paths: the gas (N = 1000, packing 0.05) with a thrust of 0.1 in a random direction
// on every body, so that every pair's meeting is a quartic, on the Grid (kind 0) or AllPairs
// (1, the 27 periodic images of every body); or (2) every body with a growing envelope
// (e1 = 0.01), which takes the World to AllPairs. Timed from the start over 2 collisions per
// particle; pairs_skipped/test is the share of pair tests that the distance bound settled.
void BM_CurvedGas(benchmark::State& state) {
  const auto n = static_cast<std::uint32_t>(state.range(0));
  const int kind = static_cast<int>(state.range(1));
  scenes::GasOptions options;
  options.n = n;
  Result<std::vector<BodyDef>> bodies = scenes::MakeGasBodies(options);
  if (!bodies) {
    state.SkipWithError(bodies.error().message.c_str());
    return;
  }
  scenes::Random random(options.seed);
  for (BodyDef& body : *bodies) {
    if (kind == 2) {
      body.envelope.e1 = 0.01;
    } else {
      // Three normals: a direction uniform on the sphere.
      const Vec3 direction(random.Normal(), random.Normal(), random.Normal());
      body.thrust = 0.1 * direction.normalized();
    }
  }
  WorldSettings settings;
  const double side = scenes::GasBoxSide(options);
  settings.container = Container::PeriodicBox(Vec3::Zero(), Vec3::Constant(side));
  settings.broadphase = kind == 0 ? Broadphase::kGrid : Broadphase::kAllPairs;
  double collisions = 0, cpu_seconds = 0, tests = 0, skipped = 0;
  for (auto _ : state) {
    state.PauseTiming();
    World world(settings);
    for (const BodyDef& body : *bodies) {
      if (!world.AddBody(body)) state.SkipWithError("a body was refused");
    }
    state.ResumeTiming();
    const std::clock_t cpu_start = std::clock();
    if (!world.AdvanceTo(2.0 / CollisionRate(options.packing))) state.SkipWithError("stalled");
    cpu_seconds += static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    collisions += static_cast<double>(world.Stats().collisions);
    tests += static_cast<double>(world.Stats().pair_tests);
    skipped += static_cast<double>(world.Stats().pairs_skipped);
  }
  state.counters["collisions/cpu_s"] = collisions / cpu_seconds;
  state.counters["pair_tests/collision"] = tests / collisions;
  state.counters["pairs_skipped/test"] = skipped / tests;
}

void GasArguments(benchmark::internal::Benchmark* b) {
  for (const int packing : {5, 10, 30}) {
    for (const int n : {1000, 10000, 100000, 1000000}) {
      b->Args({n, packing, static_cast<int>(Broadphase::kGrid)});
    }
    // 10^7 fits in memory (~2 GB at ~200 bytes per body) but takes minutes: packing 0.05 only.
    if (packing == 5) b->Args({10000000, packing, static_cast<int>(Broadphase::kGrid)});
    // AllPairs compares with 27 images of every body in a periodic box: N = 10^3 only.
    b->Args({1000, packing, static_cast<int>(Broadphase::kAllPairs)});
  }
}

BENCHMARK(BM_Gas)
    ->Apply(GasArguments)
    ->ArgNames({"n", "packing%", "allpairs0_grid1"})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_CurvedGas)
    ->ArgsProduct({{1000}, {0, 1, 2}})
    ->ArgNames({"n", "grid0_allpairs1_envelope2"})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GasCells)
    ->ArgsProduct({{10000, 100000}, {5, 30}, {5, 10, 20, 40, 60, 80, 120, 160}})
    ->ArgNames({"n", "packing%", "cells_per_body_x10"})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace sparsedyn

BENCHMARK_MAIN();
