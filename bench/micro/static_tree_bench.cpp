// SPDX-License-Identifier: MIT
// The static bodies' broad phase (issue #36): StaticTree::FirstEntry against a linear scan of
// every static (the same leaf test, behind the same swept-box filter), for N statics of very
// different sizes (boxes log-uniform in 1 cm .. 100 m per axis, and a 1000 m floor slab under
// them) in a region that grows with N (constant density), and movers on straight lines or
// parabolas, with an event horizon of 1 s or none. Counter: queries per second.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "broadphase/static_tree.hpp"

namespace sparsedyn::bench {
namespace {

struct Scene {
  std::vector<Aabb> boxes;
  std::vector<Mover> movers;
  StaticTree tree;
};

Scene MakeScene(int n) {
  std::mt19937_64 rng(20261227);
  auto uniform = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, uniform()); };
  const double region = 20.0 * std::cbrt(static_cast<double>(n));
  auto point = [&](double scale) {
    return Vec3(scale * (2 * uniform() - 1), scale * (2 * uniform() - 1),
                scale * (2 * uniform() - 1));
  };
  Scene s;
  s.boxes.push_back({{-500, -region - 1, -500}, {500, -region, 500}});
  while (static_cast<int>(s.boxes.size()) < n) {
    const Vec3 c = point(region);
    const Vec3 half(log_uniform(1e-2, 1e2), log_uniform(1e-2, 1e2), log_uniform(1e-2, 1e2));
    s.boxes.push_back({c - half, c + half});
  }
  for (int i = 0; i < 1024; ++i) {
    Mover m;
    m.p = point(region);
    m.v = point(3.0);
    m.r0 = 0.01 * (1 + uniform());  // 1-2 cm pebbles
    if (i % 2) m.a = {0, -9.81, 0};
    s.movers.push_back(m);
  }
  for (std::uint32_t i = 0; i < s.boxes.size(); ++i) s.tree.Insert(i, s.boxes[i]);
  s.tree.Build();
  return s;
}

const Scene& SceneOf(int n) {
  static std::vector<std::pair<int, Scene>> scenes;
  for (const auto& [size, scene] : scenes) {
    if (size == n) return scene;
  }
  return scenes.emplace_back(n, MakeScene(n)).second;
}

double Limit(const benchmark::State& state) { return state.range(1) ? 1.0 : kInfinity; }

void BM_StaticTreeFirstEntry(benchmark::State& state) {
  const Scene& s = SceneOf(static_cast<int>(state.range(0)));
  const double limit = Limit(state);
  std::size_t i = 0;
  for (auto _ : state) {
    const StaticTree::Entry e =
        s.tree.FirstEntry(s.movers[i++ & 1023], limit, [](std::uint32_t) { return false; });
    benchmark::DoNotOptimize(e);
  }
  state.counters["queries/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// Every static's entry, the earliest: the same BoxCrossing test behind the swept-box filter.
void BM_LinearScanFirstEntry(benchmark::State& state) {
  const Scene& s = SceneOf(static_cast<int>(state.range(0)));
  const double limit = Limit(state);
  std::size_t i = 0;
  for (auto _ : state) {
    const BoxCrossing crossing(s.movers[i++ & 1023]);
    StaticTree::Entry best;
    Aabb swept = crossing.Swept(limit);
    for (std::uint32_t k = 0; k < s.boxes.size(); ++k) {
      if (!s.boxes[k].Overlaps(swept)) continue;
      const double dt = crossing.Entry(s.boxes[k], std::min(limit, best.dt));
      if (dt < best.dt) {
        best = {dt, k};
        swept = crossing.Swept(dt);
      }
    }
    benchmark::DoNotOptimize(best);
  }
  state.counters["queries/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void Sizes(benchmark::internal::Benchmark* b) {
  for (const int n : {100, 1000, 10000, 100000}) {
    for (const int limited : {1, 0}) b->Args({n, limited});
  }
  b->ArgNames({"statics", "horizon_1s"});
}

BENCHMARK(BM_StaticTreeFirstEntry)->Apply(Sizes);
BENCHMARK(BM_LinearScanFirstEntry)->Apply(Sizes);

}  // namespace
}  // namespace sparsedyn::bench

BENCHMARK_MAIN();
