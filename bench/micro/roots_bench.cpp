// SPDX-License-Identifier: MIT
// ns per EarliestRoot call by degree, on meeting-like polynomials (a mix of real roots ahead and
// behind t = 0, complex pairs, and no root at all), over [0, 1e30] as the sparse layer calls it.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "math/roots.hpp"

namespace sparsedyn {
namespace {

// Fixed-seed splitmix64, so every run measures the same polynomials.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  double Uniform(double lo, double hi) {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return lo + (hi - lo) * static_cast<double>(z >> 11) * 0x1p-53;
  }

 private:
  std::uint64_t state_;
};

// Products of real-root factors and complex pairs, degree `degree`, times a random scale.
std::vector<Polynomial> MakePolynomials(int degree, int count) {
  Random random(20260611 + static_cast<std::uint64_t>(degree));
  std::vector<Polynomial> polynomials;
  for (int i = 0; i < count; ++i) {
    Polynomial p{random.Uniform(0.5, 2.0)};
    for (int d = 0; d < degree; d += 2) {
      const double re = random.Uniform(-5, 10);
      if (random.Uniform(0, 1) < 0.5) {
        p = p * Polynomial{re * (re + 1), -(2 * re + 1), 1};  // roots re and re + 1
      } else {
        const double im = random.Uniform(0.1, 3);
        p = p * Polynomial{re * re + im * im, -2 * re, 1};  // complex pair
      }
    }
    polynomials.push_back(p);
  }
  return polynomials;
}

void BM_EarliestRoot(benchmark::State& state) {
  const std::vector<Polynomial> polynomials =
      MakePolynomials(static_cast<int>(state.range(0)), 1024);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(EarliestRoot(polynomials[i], 0.0, 1e30));
    i = (i + 1) & 1023;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EarliestRoot)->Arg(2)->Arg(4)->Arg(6)->Arg(8);

void BM_SolveQuadratic(benchmark::State& state) {
  const std::vector<Polynomial> polynomials = MakePolynomials(2, 1024);
  std::size_t i = 0;
  std::array<double, 2> roots{};
  for (auto _ : state) {
    const Polynomial& p = polynomials[i];
    benchmark::DoNotOptimize(
        SolveQuadratic(p.Coefficient(2), p.Coefficient(1), p.Coefficient(0), roots));
    benchmark::DoNotOptimize(roots);
    i = (i + 1) & 1023;
  }
}
BENCHMARK(BM_SolveQuadratic);

void BM_SolveQuartic(benchmark::State& state) {
  const std::vector<Polynomial> polynomials = MakePolynomials(4, 1024);
  std::size_t i = 0;
  std::array<double, 4> roots{};
  for (auto _ : state) {
    benchmark::DoNotOptimize(SolveQuartic(polynomials[i], roots));
    benchmark::DoNotOptimize(roots);
    i = (i + 1) & 1023;
  }
}
BENCHMARK(BM_SolveQuartic);

}  // namespace
}  // namespace sparsedyn

BENCHMARK_MAIN();
