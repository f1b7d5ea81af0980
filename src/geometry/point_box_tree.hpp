// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// Points in nested axis-aligned boxes (median splits on the longest side): which points lie
/// above a plane, without looking at the points of a box that lies wholly below it. Checking
/// every face plane of a convex mesh against every vertex was O(V F): 70 s for a random
/// polyhedron of 10^5 faces; a plane of a convex body cuts only the boxes near its face.
class PointBoxTree {
 public:
  explicit PointBoxTree(std::span<const Vec3> points);

  /// Calls visit(v, normal . points[v] - offset) for every point v whose box reaches above
  /// `threshold()` at the time the box is reached (so a visitor that raises the threshold
  /// prunes the rest); every point above the threshold is visited.
  template <typename Threshold, typename Visit>
  void ForEachAbove(const Vec3& normal, double offset, Threshold threshold, Visit visit) const {
    if (nodes_.empty()) return;
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      // The box's highest corner along the normal.
      const Vec3 corner = (normal.array() > 0).select(node.hi, node.lo);
      if (normal.dot(corner) - offset < threshold()) continue;
      if (node.left == 0) {
        for (std::uint32_t k = node.begin; k < node.end; ++k) {
          const std::uint32_t v = order_[k];
          visit(v, normal.dot(points_[v]) - offset);
        }
        continue;
      }
      stack[top++] = node.left + 1;
      stack[top++] = node.left;
    }
  }

 private:
  struct Node {
    Vec3 lo, hi;
    std::uint32_t begin = 0, end = 0;
    std::uint32_t left = 0;  // its children are left and left + 1; 0 for a leaf
  };
  void Build(std::uint32_t self, std::uint32_t begin, std::uint32_t end, int depth);

  std::span<const Vec3> points_;
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace sparsedyn
