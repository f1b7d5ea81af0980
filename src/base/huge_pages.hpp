// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace sparsedyn {

/// Memory for the large per-element arrays of a simulation (positions, cell lists, the queue),
/// backed by 2 MB pages where the system offers them (Linux transparent huge pages, which
/// Debian enables on request: madvise). A gas visits its elements in no order of memory; with
/// 4 KB pages, an array beyond the reach of the address-translation cache (a few MB) costs a
/// page-table walk on nearly every visit, on top of the cache miss. Measured with glibc's
/// equivalent switch (GLIBC_TUNABLES=glibc.malloc.hugetlb=1) on the gas: +7% collisions per
/// CPU s at N = 10^6, +10-20% at 10^5 (2026-11-25; docs/lab/measurements.md#tenth-measurement).
///
/// Blocks under kHugePage bytes, which could not hold a whole huge page, come from the usual
/// allocator. Larger ones start on a 2 MB boundary; the unused head of the alignment is address
/// space only (never touched, so never backed by memory).
inline constexpr std::size_t kHugePage = std::size_t{2} << 20;

template <typename T>
struct HugePageAllocator {
  using value_type = T;

  HugePageAllocator() = default;
  template <typename U>
  explicit HugePageAllocator(const HugePageAllocator<U>& /*other*/) noexcept {}

  T* allocate(std::size_t n) {
    if (n > std::size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePage) return std::allocator<T>{}.allocate(n);
    void* p = nullptr;
    const std::size_t alignment = alignof(T) > kHugePage ? alignof(T) : kHugePage;
    if (posix_memalign(&p, alignment, bytes) != 0) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
    // Advice only: where the system refuses, the pages stay small and nothing else changes.
    madvise(p, bytes, MADV_HUGEPAGE);
#endif
    return static_cast<T*>(p);
  }

  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < kHugePage) {
      std::allocator<T>{}.deallocate(p, n);
      return;
    }
    std::free(p);
  }

  template <typename U>
  bool operator==(const HugePageAllocator<U>& /*other*/) const noexcept {
    return true;
  }
};

/// A std::vector on HugePageAllocator: for arrays with an entry per element.
template <typename T>
using BigVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace sparsedyn
