// SPDX-License-Identifier: MIT
#pragma once
// The counters behind sparsedyn::CapHits() (include/sparsedyn/statistics.hpp): each capped
// iterate-to-convergence loop bumps its counter on the path where the cap was reached, which
// is the rare one, so the common path pays nothing.
#include <atomic>
#include <cstdint>

namespace sparsedyn::caps {

inline std::atomic<std::uint64_t> root_narrowing{0};
inline std::atomic<std::uint64_t> meeting_certification{0};
inline std::atomic<std::uint64_t> impulse_rounds{0};
inline std::atomic<std::uint64_t> level_crossing{0};
inline std::atomic<std::uint64_t> bisection{0};

inline void Count(std::atomic<std::uint64_t>& counter) {
  counter.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace sparsedyn::caps
