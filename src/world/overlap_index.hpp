// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// A spatial hash of the bodies added before the simulation starts, so that AddBody can refuse
/// an overlapping body in O(1) on average (instead of comparing with all N bodies). Cells are
/// at least one largest diameter wide; a larger body rebuilds the hash with bigger cells.
class OverlapIndex {
 public:
  /// `periodic_length` > 0 per axis wraps cell coordinates (periodic boxes).
  explicit OverlapIndex(const Vec3& origin = Vec3::Zero(),
                        const Vec3& periodic_length = Vec3::Zero())
      : origin_(origin), periodic_length_(periodic_length) {}

  /// Empties the index and releases its memory (it is only needed before the start).
  void Clear() {
    cells_ = {};
    points_ = {};
    radii_ = {};
  }

  /// Adds body `index` (which must equal the number of bodies added so far).
  void Add(const Vec3& p, double radius) {
    points_.push_back(p);
    radii_.push_back(radius);
    if (2 * radius > cell_size_) {
      Rebuild(std::max(2 * radius, 2 * cell_size_));
    } else {
      cells_[Key(CellOf(p))].push_back(static_cast<std::uint32_t>(points_.size() - 1));
    }
  }

  /// Calls fn(j, p_j, r_j) for every indexed body that could overlap a sphere (p, radius).
  template <typename Fn>
  void ForEachNear(const Vec3& p, double radius, Fn&& fn) const {
    if (points_.empty()) return;
    const int reach = static_cast<int>(std::ceil((radius + 0.5 * cell_size_) / cell_size_));
    const std::array<std::int64_t, 3> c = CellOf(p);
    for (int dz = -reach; dz <= reach; ++dz) {
      for (int dy = -reach; dy <= reach; ++dy) {
        for (int dx = -reach; dx <= reach; ++dx) {
          const auto it = cells_.find(Key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if (it == cells_.end()) continue;
          for (const std::uint32_t j : it->second) fn(j, points_[j], radii_[j]);
        }
      }
    }
  }

 private:
  std::array<std::int64_t, 3> CellOf(const Vec3& p) const {
    std::array<std::int64_t, 3> c{};
    for (int k = 0; k < 3; ++k)
      c[k] = static_cast<std::int64_t>(std::floor((p[k] - origin_[k]) / cell_size_));
    return c;
  }

  std::uint64_t Key(std::array<std::int64_t, 3> c) const {
    for (int k = 0; k < 3; ++k) {
      if (periodic_length_[k] > 0) {
        const auto n =
            std::max<std::int64_t>(1, static_cast<std::int64_t>(periodic_length_[k] / cell_size_));
        c[k] = ((c[k] % n) + n) % n;
      }
    }
    // 21 bits per axis, two's complement folded: collisions only cost a few extra distance tests.
    const auto fold = [](std::int64_t v) { return static_cast<std::uint64_t>(v) & 0x1fffffu; };
    return fold(c[0]) | (fold(c[1]) << 21) | (fold(c[2]) << 42);
  }

  void Rebuild(double cell_size) {
    cell_size_ = cell_size;
    cells_.clear();
    for (std::uint32_t j = 0; j < points_.size(); ++j) cells_[Key(CellOf(points_[j]))].push_back(j);
  }

  Vec3 origin_;
  Vec3 periodic_length_;
  double cell_size_ = 0.0;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
  std::vector<Vec3> points_;
  std::vector<double> radii_;
};

}  // namespace sparsedyn
