// SPDX-License-Identifier: MIT
// The event queue structures on two streams, N = 2^10 .. 2^20 entries (one per slot):
// - the hold model (pop the head, re-insert its slot at the head time plus an exponential
//   increment), the classic priority-queue benchmark (Jones 1986; Brown 1988);
// - a sparse-dynamics stream as the World makes it: each event re-schedules its own slot and on
//   average 1.5 other random slots (the partners whose predictions it invalidated), at the
//   event time plus an exponential with mean 1, a collision time independent of N.
// Time per iteration is ns per hold operation, or per event. See
// docs/decisions/0002-event-queue.md.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>
#include <type_traits>
#include <vector>

#include "events/calendar_queue.hpp"
#include "events/heap_queue.hpp"

namespace sparsedyn {
namespace {

using Heap2 = HeapQueue<2>;
using Heap4 = HeapQueue<4>;
using Calendar = CalendarQueue;

// Pre-drawn random numbers, so that the generator's cost stays out of the measurement.
class Draws {
 public:
  explicit Draws(std::uint64_t seed) : exponential_(kCount), bits_(kCount) {
    std::mt19937_64 rng(seed);
    std::exponential_distribution<double> exponential(1.0);
    for (double& x : exponential_) x = exponential(rng);
    for (std::uint64_t& x : bits_) x = rng();
  }
  double Exponential() { return exponential_[next_exponential_++ & kMask]; }
  std::uint64_t Bits() { return bits_[next_bits_++ & kMask]; }

 private:
  static constexpr std::size_t kCount = std::size_t{1} << 16;
  static constexpr std::size_t kMask = kCount - 1;
  std::vector<double> exponential_;
  std::vector<std::uint64_t> bits_;
  std::size_t next_exponential_ = 0;
  std::size_t next_bits_ = 0;
};

template <typename Queue>
void Fill(Queue& queue, std::uint32_t n, Draws& draws) {
  for (std::uint32_t slot = 0; slot < n; ++slot) {
    queue.Set(slot, draws.Exponential(), EventKind::kSphereMeet);
  }
}

template <typename Queue>
void Hold(Queue& queue, Draws& draws) {
  const QueueTop top = queue.Top();
  queue.Pop();
  queue.Set(top.slot, top.time + draws.Exponential(), top.kind);
}

template <typename Queue>
void SparseEvent(Queue& queue, std::uint32_t n, Draws& draws) {
  const QueueTop top = queue.Top();
  queue.Pop();
  queue.Set(top.slot, top.time + draws.Exponential(), EventKind::kSphereMeet);
  // One or two partners (1.5 on average), drawn uniformly among all slots.
  const std::uint64_t bits = draws.Bits();
  const int partners = 1 + static_cast<int>(bits & 1u);
  for (int k = 0; k < partners; ++k) {
    const auto slot = static_cast<std::uint32_t>(((bits >> (1 + 24 * k)) & 0xffffffu) % n);
    queue.Set(slot, top.time + draws.Exponential(), EventKind::kSphereMeet);
  }
}

// Bytes per entry, and for the calendar how often it rebuilt its buckets while measured.
template <typename Queue>
void Report(benchmark::State& state, const Queue& queue, std::uint32_t n, std::uint64_t before) {
  state.SetItemsProcessed(state.iterations());
  state.counters["bytes/entry"] = static_cast<double>(queue.MemoryBytes()) / n;
  if constexpr (std::is_same_v<Queue, Calendar>) {
    state.counters["rebuilds"] = static_cast<double>(queue.RebuildCount() - before);
  }
}

template <typename Queue>
std::uint64_t Rebuilds(const Queue& queue) {
  if constexpr (std::is_same_v<Queue, Calendar>) return queue.RebuildCount();
  return 0;
}

template <typename Queue>
void BM_QueueHold(benchmark::State& state) {
  const auto n = static_cast<std::uint32_t>(state.range(0));
  Draws draws(/*seed=*/20260611);
  Queue queue;
  Fill(queue, n, draws);
  // Warm up to the steady state (the calendar re-adapts its width from the pops).
  for (std::uint32_t i = 0; i < 4 * n; ++i) Hold(queue, draws);
  const std::uint64_t before = Rebuilds(queue);
  for (auto _ : state) Hold(queue, draws);
  Report(state, queue, n, before);
}

template <typename Queue>
void BM_QueueSparseDynamics(benchmark::State& state) {
  const auto n = static_cast<std::uint32_t>(state.range(0));
  Draws draws(/*seed=*/20260612);
  Queue queue;
  Fill(queue, n, draws);
  for (std::uint32_t i = 0; i < 4 * n; ++i) SparseEvent(queue, n, draws);
  const std::uint64_t before = Rebuilds(queue);
  for (auto _ : state) SparseEvent(queue, n, draws);
  Report(state, queue, n, before);
}

BENCHMARK_TEMPLATE(BM_QueueHold, Heap2)->RangeMultiplier(4)->Range(1 << 10, 1 << 20);
BENCHMARK_TEMPLATE(BM_QueueHold, Heap4)->RangeMultiplier(4)->Range(1 << 10, 1 << 20);
BENCHMARK_TEMPLATE(BM_QueueHold, Calendar)->RangeMultiplier(4)->Range(1 << 10, 1 << 20);
BENCHMARK_TEMPLATE(BM_QueueSparseDynamics, Heap2)->RangeMultiplier(4)->Range(1 << 10, 1 << 20);
BENCHMARK_TEMPLATE(BM_QueueSparseDynamics, Heap4)->RangeMultiplier(4)->Range(1 << 10, 1 << 20);
BENCHMARK_TEMPLATE(BM_QueueSparseDynamics, Calendar)->RangeMultiplier(4)->Range(1 << 10, 1 << 20);

}  // namespace
}  // namespace sparsedyn

BENCHMARK_MAIN();
