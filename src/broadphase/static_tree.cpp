// SPDX-License-Identifier: MIT
#include "broadphase/static_tree.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sparsedyn {
namespace {

// Leaves hold up to this many statics when SAH finds no better split; nodes of this many or
// fewer are always leaves.
constexpr std::size_t kMaxLeaf = 4;
constexpr std::size_t kSmallLeaf = 2;
// SAH bins per split (Wald 2007 uses 16 to 32).
constexpr int kBins = 16;
// A box covering more than this fraction of its node's half area gets a leaf of its own.
constexpr double kDominant = 0.5;

Vec3 Centre(const Aabb& b) { return 0.5 * (b.lo + b.hi); }

}  // namespace

Aabb BoxOfPolyhedron(const ConvexPolyhedron& polyhedron, const Pose& pose) {
  Aabb box;
  double extent = 0.0;
  for (const Vec3& v : polyhedron.vertices()) {
    const Vec3 p = pose.ToWorld(v);
    box.lo = box.lo.cwiseMin(p);
    box.hi = box.hi.cwiseMax(p);
    extent = std::max(extent, v.cwiseAbs().maxCoeff());
  }
  // A rotated vertex is within a few ulps of |v| of the exact one (the quaternion's rotation
  // matrix and the product), the translation adds one rounding: 64 ulps of both is ample.
  const double pad = 64.0 * std::numeric_limits<double>::epsilon() *
                     (extent + pose.translation.cwiseAbs().maxCoeff());
  box.lo.array() -= pad;
  box.hi.array() += pad;
  return box;
}

Aabb BoxOfSphere(const Vec3& centre, double radius) {
  const double pad =
      4.0 * std::numeric_limits<double>::epsilon() * (centre.cwiseAbs().maxCoeff() + radius);
  return {centre.array() - (radius + pad), centre.array() + (radius + pad)};
}

void StaticTree::Insert(std::uint32_t index, const Aabb& box) {
  SPARSEDYN_ASSERT(index < kPending && !Contains(index), "StaticTree::Insert: index in use");
  if (index >= slot_.size()) slot_.resize(index + 1, kNoIndex);
  slot_[index] = kPending | static_cast<std::uint32_t>(pending_.size());
  pending_.push_back({box, index});
  ++live_;
  RebuildIfWorn();
}

void StaticTree::Remove(std::uint32_t index) {
  SPARSEDYN_ASSERT(Contains(index), "StaticTree::Remove: no such static");
  const std::uint32_t slot = slot_[index];
  slot_[index] = kNoIndex;
  --live_;
  if ((slot & kPending) != 0) {
    // Swap the last pending box into the hole.
    const std::uint32_t at = slot & ~kPending;
    pending_[at] = pending_.back();
    pending_.pop_back();
    if (at < pending_.size()) slot_[pending_[at].index] = kPending | at;
    return;
  }
  prims_[slot].index = kNoIndex;  // its box stays in the nodes' boxes: still conservative
  ++dead_;
  RebuildIfWorn();
}

const Aabb& StaticTree::box(std::uint32_t index) const {
  SPARSEDYN_ASSERT(Contains(index), "StaticTree::box: no such static");
  const std::uint32_t slot = slot_[index];
  return (slot & kPending) != 0 ? pending_[slot & ~kPending].box : prims_[slot].box;
}

void StaticTree::RebuildIfWorn() {
  const std::size_t built = prims_.size() - dead_;
  if (pending_.size() > 16 + built / 8 || dead_ > 16 + built / 4) Build();
}

void StaticTree::Build() {
  std::vector<Prim> all;
  all.reserve(live_);
  for (const Prim& p : prims_) {
    if (p.index != kNoIndex) all.push_back(p);
  }
  all.insert(all.end(), pending_.begin(), pending_.end());
  prims_ = std::move(all);
  pending_.clear();
  dead_ = 0;
  nodes_.clear();
  depth_ = 0;
  if (!prims_.empty()) {
    nodes_.reserve(2 * prims_.size());
    BuildNode(0, prims_.size(), 1);
  }
  for (std::size_t i = 0; i < prims_.size(); ++i)
    slot_[prims_[i].index] = static_cast<std::uint32_t>(i);
}

std::uint32_t StaticTree::BuildLeaf(std::size_t begin, std::size_t end, const Aabb& box) {
  nodes_.push_back(
      {box, static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end - begin)});
  return static_cast<std::uint32_t>(nodes_.size() - 1);
}

std::uint32_t StaticTree::BuildNode(std::size_t begin, std::size_t end, int depth) {
  depth_ = std::max(depth_, depth);
  Aabb box;
  for (std::size_t i = begin; i < end; ++i) box.Grow(prims_[i].box);
  if (end - begin <= kSmallLeaf || depth >= kMaxDepth) return BuildLeaf(begin, end, box);

  // A dominant box (a floor under pebbles) in a leaf of its own: otherwise it would widen
  // every node on its way down and every query near any pebble would visit them.
  std::size_t largest = begin;
  for (std::size_t i = begin + 1; i < end; ++i) {
    if (prims_[i].box.HalfArea() > prims_[largest].box.HalfArea()) largest = i;
  }
  std::size_t mid = begin;
  if (prims_[largest].box.HalfArea() > kDominant * box.HalfArea()) {
    std::swap(prims_[begin], prims_[largest]);
    mid = begin + 1;
  } else {
    mid = SahSplit(begin, end, box);
    if (mid == begin && end - begin <= kMaxLeaf) return BuildLeaf(begin, end, box);
    if (mid == begin) {
      // No useful split (equal centres, or SAH prefers one leaf of too many): the median
      // along the widest axis keeps the depth logarithmic.
      const Vec3 extent = box.hi - box.lo;
      int axis = 0;
      extent.maxCoeff(&axis);
      mid = begin + (end - begin) / 2;
      std::nth_element(prims_.begin() + static_cast<std::ptrdiff_t>(begin),
                       prims_.begin() + static_cast<std::ptrdiff_t>(mid),
                       prims_.begin() + static_cast<std::ptrdiff_t>(end),
                       [axis](const Prim& x, const Prim& y) {
                         return Centre(x.box)[axis] < Centre(y.box)[axis];
                       });
    }
  }
  const std::size_t node = nodes_.size();
  nodes_.push_back({box, 0, 0});
  BuildNode(begin, mid, depth + 1);  // the left child is node + 1
  const std::uint32_t right = BuildNode(mid, end, depth + 1);
  nodes_[node].first = right;
  return static_cast<std::uint32_t>(node);
}

std::size_t StaticTree::SahSplit(std::size_t begin, std::size_t end, const Aabb& box) {
  // Bin the centres along the axis of their widest spread.
  Aabb centres;
  for (std::size_t i = begin; i < end; ++i) {
    const Vec3 c = Centre(prims_[i].box);
    centres.Grow({c, c});
  }
  const Vec3 spread = centres.hi - centres.lo;
  int axis = 0;
  spread.maxCoeff(&axis);
  if (!(spread[axis] > 0.0)) return begin;
  const double lo = centres.lo[axis], scale = kBins / spread[axis];
  auto bin_of = [&](const Prim& p) {
    return std::clamp(static_cast<int>((Centre(p.box)[axis] - lo) * scale), 0, kBins - 1);
  };
  std::array<Aabb, kBins> bins;
  std::array<std::size_t, kBins> counts{};
  for (std::size_t i = begin; i < end; ++i) {
    const auto b = static_cast<std::size_t>(bin_of(prims_[i]));
    bins[b].Grow(prims_[i].box);
    ++counts[b];
  }
  // Cost of splitting after bin k: area x count of each side (traversal cost ~ one box).
  std::array<double, kBins> left_cost{};
  Aabb grown;
  std::size_t n = 0;
  for (std::size_t k = 0; k + 1 < kBins; ++k) {
    grown.Grow(bins[k]);
    n += counts[k];
    left_cost[k] = grown.HalfArea() * static_cast<double>(n);
  }
  double best_cost = box.HalfArea() * static_cast<double>(end - begin);  // one leaf
  int best = -1;
  grown = Aabb{};
  n = 0;
  for (int k = kBins - 1; k > 0; --k) {
    grown.Grow(bins[static_cast<std::size_t>(k)]);
    n += counts[static_cast<std::size_t>(k)];
    const double cost =
        left_cost[static_cast<std::size_t>(k - 1)] + grown.HalfArea() * static_cast<double>(n);
    if (n < end - begin && n > 0 && cost < best_cost) {
      best_cost = cost;
      best = k - 1;
    }
  }
  if (best < 0) return begin;
  const auto first = prims_.begin() + static_cast<std::ptrdiff_t>(begin);
  const auto split = std::partition(first, prims_.begin() + static_cast<std::ptrdiff_t>(end),
                                    [&](const Prim& p) { return bin_of(p) <= best; });
  return begin + static_cast<std::size_t>(split - first);
}

std::size_t StaticTree::MemoryBytes() const {
  return nodes_.capacity() * sizeof(Node) +
         (prims_.capacity() + pending_.capacity()) * sizeof(Prim) +
         slot_.capacity() * sizeof(std::uint32_t);
}

}  // namespace sparsedyn
