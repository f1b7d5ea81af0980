// SPDX-License-Identifier: MIT
// Construction costs of ConvexPolyhedron: Qhull + validation from points, validation alone from
// a face list, and the random generator, by face count.
#include <benchmark/benchmark.h>

#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/geometry/generators.hpp"

namespace sparsedyn {
namespace {

void BM_RandomConvexPolyhedron(benchmark::State& state) {
  const int faces = static_cast<int>(state.range(0));
  std::uint64_t seed = 1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(RandomConvexPolyhedron(faces, seed++));
  }
  state.counters["faces"] = faces;
}
BENCHMARK(BM_RandomConvexPolyhedron)->Arg(24)->Arg(600)->Arg(5000);

void BM_FromPoints(benchmark::State& state) {
  const ConvexPolyhedron shape = *RandomConvexPolyhedron(static_cast<int>(state.range(0)), 7);
  const std::vector<Eigen::Vector3d> points(shape.vertices().begin(), shape.vertices().end());
  for (auto _ : state) benchmark::DoNotOptimize(ConvexPolyhedron::FromPoints(points));
}
BENCHMARK(BM_FromPoints)->Arg(24)->Arg(600)->Arg(5000);

void BM_FromMesh(benchmark::State& state) {
  const PolygonMesh mesh = RandomConvexPolyhedron(static_cast<int>(state.range(0)), 7)->ToMesh();
  for (auto _ : state) benchmark::DoNotOptimize(ConvexPolyhedron::FromMesh(mesh));
}
BENCHMARK(BM_FromMesh)->Arg(24)->Arg(600)->Arg(5000);

}  // namespace
}  // namespace sparsedyn

BENCHMARK_MAIN();
