// SPDX-License-Identifier: MIT
#include "geometry/point_box_tree.hpp"

#include <algorithm>
#include <numeric>

namespace sparsedyn {

namespace {
constexpr std::uint32_t kLeafPoints = 8;
// ForEachAbove's stack holds one sibling a level: 64 is room for this depth (a median split
// halves the points, so 2^40 of them before it binds).
constexpr int kMaxDepth = 40;
}  // namespace

PointBoxTree::PointBoxTree(std::span<const Vec3> points) : points_(points) {
  if (points.empty()) return;
  order_.resize(points.size());
  std::iota(order_.begin(), order_.end(), 0u);
  nodes_.reserve(2 * points.size() / kLeafPoints + 1);
  nodes_.emplace_back();
  Build(0, 0, static_cast<std::uint32_t>(points.size()), 0);
}

void PointBoxTree::Build(std::uint32_t self, std::uint32_t begin, std::uint32_t end, int depth) {
  Vec3 lo = points_[order_[begin]], hi = lo;
  for (std::uint32_t k = begin + 1; k < end; ++k) {
    lo = lo.cwiseMin(points_[order_[k]]);
    hi = hi.cwiseMax(points_[order_[k]]);
  }
  nodes_[self].lo = lo;
  nodes_[self].hi = hi;
  nodes_[self].begin = begin;
  nodes_[self].end = end;
  if (end - begin <= kLeafPoints || depth >= kMaxDepth) return;
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  const std::uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                   [&](std::uint32_t a, std::uint32_t b) {
                     return points_[a][axis] < points_[b][axis];
                   });
  // Siblings are adjacent: the children are left and left + 1.
  const auto left = static_cast<std::uint32_t>(nodes_.size());
  nodes_[self].left = left;
  nodes_.emplace_back();
  nodes_.emplace_back();
  Build(left, begin, middle, depth + 1);
  Build(left + 1, middle, end, depth + 1);
}

}  // namespace sparsedyn
