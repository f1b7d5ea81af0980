// SPDX-License-Identifier: MIT
// The huge-page allocator: large blocks start on a 2 MB boundary, small ones come from the usual
// allocator, and a BigVector behaves as a std::vector through growth, copies and moves.
#include "base/huge_pages.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <new>
#include <numeric>
#include <utility>

namespace sparsedyn {
namespace {

bool OnHugePageBoundary(const void* p) {
  return reinterpret_cast<std::uintptr_t>(p) % kHugePage == 0;
}

TEST(HugePages, LargeBlocksStartOnAHugePageBoundary) {
  HugePageAllocator<double> allocator;
  const std::size_t n = 3 * kHugePage / sizeof(double) + 5;  // not a whole number of pages
  double* p = allocator.allocate(n);
  EXPECT_TRUE(OnHugePageBoundary(p));
  p[0] = 1.0;
  p[n - 1] = 2.0;  // the whole block is usable
  EXPECT_EQ(p[0] + p[n - 1], 3.0);
  allocator.deallocate(p, n);
}

TEST(HugePages, SmallBlocksComeFromTheUsualAllocator) {
  HugePageAllocator<std::uint32_t> allocator;
  // Several small blocks at once: the usual allocator packs them, so not all can be on a 2 MB
  // boundary, as the huge-page path would put each.
  std::uint32_t* blocks[4];
  int on_boundary = 0;
  for (auto& block : blocks) {
    block = allocator.allocate(1000);
    block[999] = 7;
    on_boundary += OnHugePageBoundary(block) ? 1 : 0;
  }
  EXPECT_LT(on_boundary, 2);
  for (auto* block : blocks) allocator.deallocate(block, 1000);
}

TEST(HugePages, BigVectorGrowsCopiesAndMovesAsAVector) {
  BigVector<std::uint32_t> v;
  const std::uint32_t n = 3u << 20;  // 12 MB: crosses from small to huge blocks while growing
  for (std::uint32_t i = 0; i < n; ++i) v.push_back(i);
  EXPECT_TRUE(OnHugePageBoundary(v.data()));
  BigVector<std::uint32_t> copy = v;
  EXPECT_TRUE(OnHugePageBoundary(copy.data()));
  EXPECT_EQ(std::accumulate(copy.begin(), copy.end(), std::uint64_t{0}),
            std::uint64_t{n} * (n - 1) / 2);
  const std::uint32_t* data = copy.data();
  BigVector<std::uint32_t> moved = std::move(copy);
  EXPECT_EQ(moved.data(), data);  // a move takes the block over (the allocators are equal)
  moved.resize(10);
  moved.shrink_to_fit();
  EXPECT_EQ(moved.back(), 9u);
}

TEST(HugePages, SizesBeyondTheAddressSpaceAreRefused) {
  HugePageAllocator<double> allocator;
  EXPECT_THROW(static_cast<void>(allocator.allocate(std::size_t(-1) / 4)),
               std::bad_array_new_length);
}

}  // namespace
}  // namespace sparsedyn
