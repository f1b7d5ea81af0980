// SPDX-License-Identifier: MIT
#pragma once

namespace sparsedyn {

/// Asks for the cache line that holds `address`, ahead of its use: a hint, which never faults,
/// for any address. Not __builtin_prefetch: GCC 12 at -O3 has dropped loops of that builtin
/// from the binary without a word (the look-ahead's fetch of 27 cells' first elements was never
/// in it; Grid::FetchAround's nine fetches vanished after an edit of its loop, 9% slower at
/// N = 10^5). A volatile asm statement is always kept.
inline void Prefetch(const void* address) {
#if defined(__x86_64__) || defined(__i386__)
  asm volatile("prefetcht0 %0" : : "m"(*static_cast<const char*>(address)));
#else
  __builtin_prefetch(address);
#endif
}

}  // namespace sparsedyn
