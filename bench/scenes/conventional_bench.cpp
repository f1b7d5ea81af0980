// SPDX-License-Identifier: MIT
// The conventional method against the event-driven World on data/scenes/polyhedra_100.json
// (docs/conventional.md "Measured"): the same bodies, the same simulated time.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "sparsedyn/conventional.hpp"
#include "sparsedyn/io/scene_file.hpp"
#include "sparsedyn/world.hpp"

namespace {

using sparsedyn::SceneDescription;

// Short enough for the World to run the scene (it stalls at t = 0.957 as of this writing).
constexpr double kUntil = 0.9;

const SceneDescription& Scene() {
  static const SceneDescription scene =
      sparsedyn::ReadScene(std::string(SPARSEDYN_SOURCE_DIR) + "/data/scenes/polyhedra_100.json")
          .value();
  return scene;
}

// range(0) = -log10(dt): 2, 3, 4.
void BM_Conventional(benchmark::State& state) {
  const SceneDescription& scene = Scene();
  const sparsedyn::ConventionalSettings settings{
      .dt = std::pow(10.0, -static_cast<double>(state.range(0))), .digits = 4};
  double collisions = 0;
  double steps = 0;
  for (auto _ : state) {
    state.PauseTiming();
    sparsedyn::ConventionalWorld world(scene.settings, settings);
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
      (void)world.AddBody(sparsedyn::SceneBodyDef(scene, i)).value();
    }
    state.ResumeTiming();
    if (const sparsedyn::Status ok = world.AdvanceTo(kUntil); !ok) {
      state.SkipWithError(ok.error().message.c_str());
      return;
    }
    collisions = static_cast<double>(world.Stats().collisions + world.Stats().wall_collisions);
    steps = static_cast<double>(world.Stats().steps);
  }
  state.counters["collisions"] = collisions;
  state.counters["steps/s"] =
      benchmark::Counter(steps, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Conventional)->DenseRange(2, 4)->Unit(benchmark::kMillisecond);

void BM_EventWorld(benchmark::State& state) {
  const SceneDescription& scene = Scene();
  double collisions = 0;
  for (auto _ : state) {
    state.PauseTiming();
    sparsedyn::World world = sparsedyn::BuildWorld(scene).value();
    state.ResumeTiming();
    if (const sparsedyn::Status ok = world.AdvanceTo(kUntil); !ok) {
      state.SkipWithError(ok.error().message.c_str());
      return;
    }
    collisions = static_cast<double>(world.Stats().collisions + world.Stats().wall_collisions);
  }
  state.counters["collisions"] = collisions;
}
BENCHMARK(BM_EventWorld)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
