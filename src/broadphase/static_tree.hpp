// SPDX-License-Identifier: MIT
// The static bodies' own broad phase (issue #36): a bounding-volume hierarchy over their
// world boxes. Static bodies never move, so they are not elements of the sparse phase (no
// queue entry, not in the uniform Grid, whose cells grow to the largest element): each moving
// element asks the tree which static it can reach first, and when it leaves one it reached.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "broadphase/box_crossing.hpp"
#include "sparse/mover.hpp"
#include "sparsedyn/assert.hpp"
#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/geometry/pose.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// The world box of `polyhedron` at `pose` (its vertices' extremes), moved outwards by a bound
/// on the rounding of the transform, so that it holds the exact shape.
Aabb BoxOfPolyhedron(const ConvexPolyhedron& polyhedron, const Pose& pose);
/// The box of a sphere, likewise.
Aabb BoxOfSphere(const Vec3& centre, double radius);

/// A bounding-volume hierarchy over the boxes of static bodies, each named by the caller's
/// index (e.g. its body slot). Built top-down by the binned surface-area heuristic (Wald 2007,
/// "On fast construction of SAH-based bounding volume hierarchies"), with a box that covers
/// more than half of a node's area (a floor under pebbles) in a leaf of its own at that node.
///
/// Why rebuilds and not an incremental tree: statics change only between runs of the event
/// loop, while every prediction of every moving element queries the tree, so query speed
/// wins and a tree built from all boxes at once is the best one. Insert puts a box on a pending
/// list that every query also scans, Remove marks a built box dead; when the pending list
/// outgrows an eighth of the tree, or the dead a quarter, the tree is rebuilt (O(N log N)).
/// The sizes grow geometrically between rebuilds, so adding N statics one by one costs
/// O(N log N) in all. Build() rebuilds now: call it before a run so that no query scans.
class StaticTree {
 public:
  /// The first static a moving element reaches: dt after the mover's time, and its index;
  /// kInfinity and kNoIndex when none within the limit.
  struct Entry {
    double dt = kInfinity;
    std::uint32_t index = kNoIndex;
  };
  /// What a query did: node boxes whose entry was computed, and statics tested.
  struct Work {
    int nodes = 0;
    int statics = 0;
  };

  /// Adds the static `index` (not present) with its world box.
  void Insert(std::uint32_t index, const Aabb& box);
  /// Removes the static `index` (present).
  void Remove(std::uint32_t index);
  bool Contains(std::uint32_t index) const {
    return index < slot_.size() && slot_[index] != kNoIndex;
  }
  /// The box of the static `index` (present).
  const Aabb& box(std::uint32_t index) const;
  std::size_t size() const { return live_; }
  /// Rebuilds the hierarchy over every static now (nothing pending, nothing dead).
  void Build();
  /// The hierarchy's depth (1: a single leaf; 0: empty).
  int depth() const { return depth_; }

  /// The earliest dt in [0, dt_limit] (dt_limit may be infinity) at which the sphere of
  /// `mover` (centre p + v dt + a dt^2/2, radius r0 + r1 dt + r2 dt^2/2) first touches a
  /// static's box, i.e. its centre is within the box inflated by the radius (a conservative
  /// stand-in for the box with rounded edges), and that static; statics with skip(index)
  /// true (those the element is already engaged with) are left out. Never later than the
  /// exact time (BoxCrossing::Entry); 0 when the element touches a box now. Subtrees are pruned
  /// by the path's swept box over [0, the best time so far] and by their own entry times, and
  /// visited nearest entry first. Ties go to the static found first (deterministic).
  template <class Skip>
  Entry FirstEntry(const Mover& mover, double dt_limit, const Skip& skip,
                   Work* work = nullptr) const;

  /// For an element whose inflated-box test with the static `index` holds now: the first dt
  /// after which it does not, never earlier than the exact time (an engagement ended early
  /// would be taken up again at once). kInfinity if it never ends.
  double Exit(const Mover& mover, std::uint32_t index) const {
    return BoxCrossing(mover).Exit(box(index));
  }

  /// Calls fn(index) for every static whose box overlaps `query` (closed boxes).
  template <class Fn>
  void ForEachOverlapping(const Aabb& query, const Fn& fn) const;

  /// Bytes held by the tree's arrays.
  std::size_t MemoryBytes() const;

 private:
  // Internal node (count 0): children n + 1 and `first`. Leaf: prims_[first, first + count).
  struct Node {
    Aabb box;
    std::uint32_t first = 0;
    std::uint32_t count = 0;
  };
  struct Prim {
    Aabb box;
    std::uint32_t index = kNoIndex;  // kNoIndex: removed since the build
  };
  static constexpr std::uint32_t kPending = 0x80000000u;  // slot_ bit: in pending_
  static constexpr int kMaxDepth = 100;                   // deeper: a leaf of what is left
  static constexpr std::size_t kStack = 128;

  std::uint32_t BuildNode(std::size_t begin, std::size_t end, int depth);
  std::uint32_t BuildLeaf(std::size_t begin, std::size_t end, const Aabb& box);
  // Where SAH splits [begin, end) (its prims reordered), or begin when it finds no split.
  std::size_t SahSplit(std::size_t begin, std::size_t end, const Aabb& box);
  void RebuildIfWorn();

  std::vector<Node> nodes_;
  std::vector<Prim> prims_;          // in tree order
  std::vector<Prim> pending_;        // inserted since the last build
  std::vector<std::uint32_t> slot_;  // by index: position in prims_, or kPending | in pending_
  std::size_t live_ = 0, dead_ = 0;
  int depth_ = 0;
};

template <class Skip>
StaticTree::Entry StaticTree::FirstEntry(const Mover& mover, double dt_limit, const Skip& skip,
                                         Work* work) const {
  const BoxCrossing crossing(mover);
  Entry best;
  Work count;
  auto offer = [&](const Prim& prim, const Aabb& swept) {
    if (prim.index == kNoIndex || !prim.box.Overlaps(swept) || skip(prim.index)) return false;
    ++count.statics;
    const double dt = crossing.Entry(prim.box, std::min(dt_limit, best.dt));
    if (!(dt < best.dt)) return false;
    best = {dt, prim.index};
    return true;
  };
  Aabb swept = crossing.Swept(dt_limit);
  for (const Prim& prim : pending_) {
    if (offer(prim, swept)) swept = crossing.Swept(best.dt);
  }
  // Depth first, nearer entry first; a subtree whose entry is not before the best is pruned.
  struct Item {
    std::uint32_t node;
    double dt;
  };
  std::array<Item, kStack> stack;
  std::size_t top = 0;
  auto enter = [&](std::uint32_t n) {  // a node's entry, counted
    const Aabb& b = nodes_[n].box;
    if (!b.Overlaps(swept)) return kInfinity;
    ++count.nodes;
    return crossing.Entry(b, std::min(dt_limit, best.dt));
  };
  if (!nodes_.empty()) {
    const double root = enter(0);
    if (root < best.dt) stack[top++] = {0, root};
  }
  while (top > 0) {
    const Item item = stack[--top];
    if (!(item.dt < best.dt)) continue;
    const Node& node = nodes_[item.node];
    if (node.count > 0) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        if (offer(prims_[i], swept)) swept = crossing.Swept(best.dt);
      }
      continue;
    }
    const std::uint32_t left = item.node + 1, right = node.first;
    const double dt_left = enter(left), dt_right = enter(right);
    const bool left_first = dt_left <= dt_right;
    const Item near{left_first ? left : right, left_first ? dt_left : dt_right};
    const Item far{left_first ? right : left, left_first ? dt_right : dt_left};
    SPARSEDYN_ASSERT(top + 2 <= kStack, "StaticTree: traversal stack overflow");
    if (far.dt < best.dt) stack[top++] = far;
    if (near.dt < best.dt) stack[top++] = near;
  }
  if (work != nullptr) *work = count;
  return best;
}

template <class Fn>
void StaticTree::ForEachOverlapping(const Aabb& query, const Fn& fn) const {
  for (const Prim& prim : pending_) {
    if (prim.box.Overlaps(query)) fn(prim.index);
  }
  if (nodes_.empty()) return;
  std::array<std::uint32_t, kStack> stack;
  std::size_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!node.box.Overlaps(query)) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        if (prims_[i].index != kNoIndex && prims_[i].box.Overlaps(query)) fn(prims_[i].index);
      }
      continue;
    }
    SPARSEDYN_ASSERT(top + 2 <= kStack, "StaticTree: traversal stack overflow");
    stack[top++] = node.first;
    stack[top++] = static_cast<std::uint32_t>(&node - nodes_.data()) + 1;
  }
}

}  // namespace sparsedyn
