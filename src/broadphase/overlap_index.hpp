// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// A spatial hash of the bodies added before the simulation starts, so that AddBody can refuse
/// an overlapping body in O(1) on average (instead of comparing with all N bodies). Cells are at
/// least two largest diameters wide, so a query of that size visits 2 cells per axis, not 3; a
/// larger body rebuilds the hash with bigger cells. The table is flat: a head per hash bucket
/// and the bodies threaded through `next_` (no allocation per cell, one probe per cell), with
/// each body's cell key kept so that a bucket shared by two cells yields each body once.
class OverlapIndex {
 public:
  /// `periodic_length` > 0 per axis wraps cell coordinates (periodic boxes); there the cells
  /// tile the length exactly.
  explicit OverlapIndex(const Vec3& origin = Vec3::Zero(),
                        const Vec3& periodic_length = Vec3::Zero())
      : origin_(origin), periodic_length_(periodic_length) {}

  /// Empties the index and releases its memory (it is only needed before the start).
  void Clear() {
    head_ = {};
    next_ = {};
    keys_ = {};
    points_ = {};
    radii_ = {};
    max_radius_ = 0.0;
    min_cell_ = 0.0;
  }

  /// Adds body `index` (which must equal the number of bodies added so far).
  void Add(const Vec3& p, double radius) {
    points_.push_back(p);
    radii_.push_back(radius);
    next_.push_back(kEnd);
    keys_.push_back(0);
    max_radius_ = std::max(max_radius_, radius);
    if (head_.empty() || 4 * radius > min_cell_) {
      Rebuild(std::max({4 * radius, 2 * min_cell_, kSmallestCell}), head_.size());
    } else if (2 * points_.size() > head_.size()) {
      Rebuild(min_cell_, 2 * head_.size());
    } else {
      Link(static_cast<std::uint32_t>(points_.size() - 1));
    }
  }

  /// Calls fn(j, p_j, r_j) once for every indexed body j whose centre may lie within
  /// radius + r_j of p (minimum image in periodic axes), and for some farther ones.
  template <typename Fn>
  void ForEachNear(const Vec3& p, double radius, Fn&& fn) const {
    if (points_.empty()) return;
    // The box around p that holds every centre within reach, widened past round-off in the
    // cell coordinates so that a centre on a cell boundary is found from either side.
    const double reach = radius + max_radius_;
    std::array<std::int64_t, 3> lo{}, count{};
    double cells = 1;
    for (int k = 0; k < 3; ++k) {
      const double x = p[k] - origin_[k];
      const double margin = 1e-6 * cell_[k] + 1e-12 * std::abs(x);
      lo[k] = CellCoordinate((x - reach - margin) / cell_[k]);
      const std::int64_t hi = CellCoordinate((x + reach + margin) / cell_[k]);
      count[k] = hi - lo[k] + 1;
      if (wrap_[k] > 0) count[k] = std::min(count[k], wrap_[k]);  // every cell of the axis once
      cells *= static_cast<double>(count[k]);
    }
    // A query far larger than the cells: visiting every body is cheaper.
    if (cells > static_cast<double>(points_.size())) {
      for (std::uint32_t j = 0; j < points_.size(); ++j) fn(j, points_[j], radii_[j]);
      return;
    }
    for (std::int64_t z = 0; z < count[2]; ++z) {
      for (std::int64_t y = 0; y < count[1]; ++y) {
        for (std::int64_t x = 0; x < count[0]; ++x) {
          const std::uint64_t key = Key({lo[0] + x, lo[1] + y, lo[2] + z});
          for (std::uint32_t j = head_[Bucket(key)]; j != kEnd; j = next_[j]) {
            if (keys_[j] == key) fn(j, points_[j], radii_[j]);
          }
        }
      }
    }
  }

 private:
  static constexpr std::uint32_t kEnd = std::numeric_limits<std::uint32_t>::max();
  // Only for bodies of radius ~0, where no cell size follows from the radius.
  static constexpr double kSmallestCell = 1e-300;

  // floor(u) as an integer, clamped so that far-off coordinates (an open container) cannot
  // overflow; they fold into far cells, which costs distance tests only.
  static std::int64_t CellCoordinate(double u) {
    return static_cast<std::int64_t>(std::clamp(std::floor(u), -4e18, 4e18));
  }

  std::uint64_t Key(std::array<std::int64_t, 3> c) const {
    for (int k = 0; k < 3; ++k) {
      if (wrap_[k] > 0) c[k] = ((c[k] % wrap_[k]) + wrap_[k]) % wrap_[k];
    }
    // 21 bits per axis, two's complement folded: two cells folded together only cost extra
    // distance tests.
    const auto fold = [](std::int64_t v) { return static_cast<std::uint64_t>(v) & 0x1fffffu; };
    return fold(c[0]) | (fold(c[1]) << 21) | (fold(c[2]) << 42);
  }

  std::uint64_t KeyOf(const Vec3& p) const {
    std::array<std::int64_t, 3> c{};
    for (int k = 0; k < 3; ++k) c[k] = CellCoordinate((p[k] - origin_[k]) / cell_[k]);
    return Key(c);
  }

  std::size_t Bucket(std::uint64_t key) const {
    // Fibonacci hashing: the top bits of the product spread neighbouring cells over the table.
    return static_cast<std::size_t>((key * 0x9e3779b97f4a7c15u) >> shift_);
  }

  void Link(std::uint32_t j) {
    keys_[j] = KeyOf(points_[j]);
    std::uint32_t& head = head_[Bucket(keys_[j])];
    next_[j] = head;
    head = j;
  }

  // New cells of at least `min_cell` and a table of at least `buckets` (a power of two).
  void Rebuild(double min_cell, std::size_t buckets) {
    min_cell_ = min_cell;
    for (int k = 0; k < 3; ++k) {
      wrap_[k] = 0;
      cell_[k] = min_cell;
      if (periodic_length_[k] > 0) {
        // At most 2^20 cells, so that wrapped coordinates fit the key's 21 bits unfolded.
        wrap_[k] = static_cast<std::int64_t>(
            std::clamp(std::floor(periodic_length_[k] / min_cell), 1.0, 1048576.0));
        cell_[k] = periodic_length_[k] / static_cast<double>(wrap_[k]);
      }
    }
    int bits = 4;
    while ((std::size_t{1} << bits) < std::max(buckets, 2 * points_.size())) ++bits;
    shift_ = 64 - bits;
    head_.assign(std::size_t{1} << bits, kEnd);
    for (std::uint32_t j = 0; j < points_.size(); ++j) Link(j);
  }

  Vec3 origin_;
  Vec3 periodic_length_;
  double min_cell_ = 0.0;
  double max_radius_ = 0.0;
  std::array<double, 3> cell_{1.0, 1.0, 1.0};
  std::array<std::int64_t, 3> wrap_{0, 0, 0};  // cells per periodic axis, 0 if not periodic
  int shift_ = 60;
  std::vector<std::uint32_t> head_;
  std::vector<std::uint32_t> next_;
  std::vector<std::uint64_t> keys_;
  std::vector<Vec3> points_;
  std::vector<double> radii_;
};

}  // namespace sparsedyn
