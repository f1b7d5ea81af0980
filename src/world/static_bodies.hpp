// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "broadphase/static_tree.hpp"
#include "sparsedyn/geometry/pose.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// The static bodies (issue #36 part 3): fixed in place, of infinite mass, with no path and no
/// events of their own. They are not elements of the sparse phase (the Grid's cells would grow
/// to the largest of them): their boxes are in a StaticTree of their own, which each moving
/// element's prediction asks for the first static it can reach. Where a static stands among
/// element indices (an engagement's partner, a slot's body) it is named by its key: its index
/// with kKeyBit set.
class StaticBodies {
 public:
  static constexpr std::uint32_t kKeyBit = 0x80000000u;
  static bool IsKey(std::uint32_t key) { return (key & kKeyBit) != 0; }
  static std::uint32_t KeyOf(std::uint32_t s) { return s | kKeyBit; }
  static std::uint32_t IndexOf(std::uint32_t key) { return key & ~kKeyBit; }

  struct Static {
    std::uint32_t shape = kNoIndex;  // into the World's ShapeTable; kNoIndex: a sphere
    double radius = 0.0;             // a sphere's radius, a polyhedron's bounding radius
    Pose pose;                       // body to world (a sphere's rotation is the identity)
    double restitution = 1.0;
    double friction = 0.0;
    std::uint32_t slot = kNoIndex;   // its public slot (BodyIds)
    bool alive = false;
  };

  bool Empty() const { return live_ == 0; }
  std::uint32_t Count() const { return live_; }
  /// The index the next Add gives.
  std::uint32_t NextIndex() const { return static_cast<std::uint32_t>(statics_.size()); }
  /// Adds a static with its world box; returns its index.
  std::uint32_t Add(const Static& s, const Aabb& box) {
    const auto index = static_cast<std::uint32_t>(statics_.size());
    statics_.push_back(s);
    statics_.back().alive = true;
    tree_.Insert(index, box);
    ++live_;
    return index;
  }
  void Remove(std::uint32_t s) {
    statics_[s].alive = false;
    tree_.Remove(s);
    --live_;
  }
  const Static& operator[](std::uint32_t s) const { return statics_[s]; }
  bool Alive(std::uint32_t s) const { return s < statics_.size() && statics_[s].alive; }
  StaticTree& tree() { return tree_; }
  const StaticTree& tree() const { return tree_; }
  std::size_t MemoryBytes() const {
    return statics_.capacity() * sizeof(Static) + tree_.MemoryBytes();
  }

 private:
  std::vector<Static> statics_;
  StaticTree tree_;
  std::uint32_t live_ = 0;
};

}  // namespace sparsedyn
