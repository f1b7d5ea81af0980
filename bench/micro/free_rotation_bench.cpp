// SPDX-License-Identifier: MIT
// ns per orientation (and ω) evaluation of a free rotation (src/motion/free_rotation.hpp) by
// kind, against RigidPath::OrientationAt, the constant-ω turn of today's segments, on 1024
// random bodies (moments in [0.5, 3], |ω| = 1 rad/s) at times spread over 0..100 s.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>
#include <vector>

#include "motion/free_rotation.hpp"
#include "motion/rigid_path.hpp"

namespace sparsedyn {
namespace {

constexpr std::size_t kBodies = 1024;

struct Bodies {
  std::vector<FreeRotation> rotations;
  std::vector<RigidPath> paths;
  std::vector<double> times;
};

// kind 0: three distinct moments (elliptic); 1: two equal (axisymmetric); 2: spherical.
Bodies MakeBodies(int kind) {
  std::mt19937_64 rng(20261203 + static_cast<std::uint64_t>(kind));
  std::uniform_real_distribution<double> moment(0.5, 3.0), time(0.0, 100.0);
  std::normal_distribution<double> normal;
  Bodies bodies;
  for (std::size_t i = 0; i < kBodies; ++i) {
    Vec3 moments(moment(rng), moment(rng), moment(rng));
    if (kind == 1) moments.y() = moments.x();
    if (kind == 2) moments.setConstant(moments.x());
    const Eigen::Quaterniond q0 =
        Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
    const Vec3 w = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    bodies.rotations.emplace_back(0.0, moments, q0, w);
    RigidPath path;
    path.q0 = q0;
    path.omega = w;
    bodies.paths.push_back(path);
    bodies.times.push_back(time(rng));
  }
  return bodies;
}

void BM_RigidPathOrientationAt(benchmark::State& state) {
  const Bodies bodies = MakeBodies(0);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bodies.paths[i].OrientationAt(bodies.times[i]));
    i = (i + 1) & (kBodies - 1);
  }
}
BENCHMARK(BM_RigidPathOrientationAt);

void BM_FreeRotationOrientationAt(benchmark::State& state) {
  const Bodies bodies = MakeBodies(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bodies.rotations[i].OrientationAt(bodies.times[i]));
    i = (i + 1) & (kBodies - 1);
  }
}
BENCHMARK(BM_FreeRotationOrientationAt)->ArgName("kind")->Arg(0)->Arg(1)->Arg(2);

void BM_FreeRotationOmegaWorldAt(benchmark::State& state) {
  const Bodies bodies = MakeBodies(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bodies.rotations[i].OmegaWorldAt(bodies.times[i]));
    i = (i + 1) & (kBodies - 1);
  }
}
BENCHMARK(BM_FreeRotationOmegaWorldAt)->ArgName("kind")->Arg(0)->Arg(1)->Arg(2);

void BM_FreeRotationOmegaBodyAt(benchmark::State& state) {
  const Bodies bodies = MakeBodies(0);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bodies.rotations[i].OmegaBodyAt(bodies.times[i]));
    i = (i + 1) & (kBodies - 1);
  }
}
BENCHMARK(BM_FreeRotationOmegaBodyAt);

void BM_FreeRotationConstruct(benchmark::State& state) {
  const Bodies bodies = MakeBodies(0);
  std::size_t i = 0;
  for (auto _ : state) {
    const FreeRotation& f = bodies.rotations[i];
    benchmark::DoNotOptimize(FreeRotation(0.0, f.moments(), f.q0(), f.OmegaWorldAt(0.0)));
    i = (i + 1) & (kBodies - 1);
  }
}
BENCHMARK(BM_FreeRotationConstruct);

}  // namespace
}  // namespace sparsedyn

BENCHMARK_MAIN();
