// SPDX-License-Identifier: MIT
// Issue #36's scene targets, each against its own reference in the same run (the machine is
// noisy: compare the pairs, not the absolute rates):
// - BM_Thesis / BM_ThesisOnSlab: the thesis preset (packing 0.05) with and without a static
//   floor slab 1000 times the bodies' size (half extents 1000 x 1000 x 1 m under bodies of
//   bounding radius 1), its top 2 m above the box floor, reaching far beyond the walls; the
//   bodies that start below its top + 1 m are left out of both. Target: within 10%.
// - BM_Mixed: the same box with every other body a sphere of the same bounding radius (same
//   mass density), against BM_Thesis. Target: at least 0.5x.
// Each run builds its scene, settles for 1 s (not timed), then times 4 simulated seconds; the
// counter is collisions per CPU second (process time, robust against other jobs).
#include <benchmark/benchmark.h>

#include <cmath>
#include <ctime>
#include <string>

#include "scenes/thesis.hpp"
#include "sparsedyn/io/scene_file.hpp"

namespace sparsedyn {
namespace {

enum class Variant { kThesis, kSlab, kMixed };

constexpr double kSlabTop = 2.0;  // m above the box floor

double CpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

Result<SceneDescription> MakeScene(std::uint32_t n, Variant variant) {
  Result<SceneDescription> made = scenes::MakeThesisScene({.n = n, .packing = 0.05});
  if (!made) return made.error();
  SceneDescription scene = std::move(*made);
  // The same bodies in every variant: none within reach of where the slab would be.
  std::erase_if(scene.bodies, [](const SceneBody& body) { return body.position.z() < kSlabTop + 1.0; });
  if (variant == Variant::kMixed) {
    scene.shapes.push_back(SphereShape(1.0));
    const auto sphere = static_cast<std::uint32_t>(scene.shapes.size() - 1);
    for (std::size_t i = 0; i < scene.bodies.size(); i += 2) {
      scene.bodies[i].shape = sphere;
      scene.bodies[i].angular_velocity = Vec3::Zero();
      scene.bodies[i].mass = 4.0 / 3.0 * M_PI;  // density 1, as the polyhedra
      scene.bodies[i].density.reset();
    }
  }
  if (variant == Variant::kSlab) {
    Result<SceneShape> slab =
        ParseShapeSpec(R"({"generator": "box", "half_extents": [1000, 1000, 1]})", ".");
    if (!slab) return slab.error();
    scene.shapes.push_back(std::move(*slab));
    SceneBody floor;
    floor.shape = static_cast<std::uint32_t>(scene.shapes.size() - 1);
    const Vec3 centre = 0.5 * (scene.settings.container.lo + scene.settings.container.hi);
    floor.position = Vec3(centre.x(), centre.y(), scene.settings.container.lo.z() + kSlabTop - 1);
    floor.is_static = true;
    scene.bodies.push_back(floor);
  }
  return scene;
}

void RunScene(benchmark::State& state, Variant variant) {
  const auto n = static_cast<std::uint32_t>(state.range(0));
  double collisions = 0, cpu = 0, statics = 0;
  for (auto _ : state) {
    state.PauseTiming();
    Result<SceneDescription> scene = MakeScene(n, variant);
    if (!scene) {
      state.SkipWithError(scene.error().message.c_str());
      break;
    }
    Result<World> world = BuildWorld(*scene);
    if (!world) {
      state.SkipWithError(world.error().message.c_str());
      break;
    }
    if (!world->AdvanceTo(1.0)) state.SkipWithError("stalled while settling");
    const Statistics before = world->Stats();
    state.ResumeTiming();
    const double start = CpuSeconds();
    if (!world->AdvanceTo(5.0)) state.SkipWithError("stalled");
    cpu += CpuSeconds() - start;
    state.PauseTiming();
    if (!world->Validate()) state.SkipWithError("invalid at the end");
    collisions += static_cast<double>(world->Stats().collisions - before.collisions);
    statics += static_cast<double>(world->Stats().static_collisions - before.static_collisions);
    state.ResumeTiming();
  }
  state.counters["collisions/cpu_s"] = collisions / cpu;
  state.counters["static_collisions"] = statics / static_cast<double>(state.iterations());
  state.counters["collisions"] = collisions / static_cast<double>(state.iterations());
}

void BM_Thesis(benchmark::State& state) { RunScene(state, Variant::kThesis); }
void BM_ThesisOnSlab(benchmark::State& state) { RunScene(state, Variant::kSlab); }
void BM_Mixed(benchmark::State& state) { RunScene(state, Variant::kMixed); }

BENCHMARK(BM_Thesis)->Arg(1000)->Arg(10000)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_ThesisOnSlab)->Arg(1000)->Arg(10000)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_Mixed)->Arg(1000)->Arg(10000)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
}  // namespace sparsedyn

BENCHMARK_MAIN();
