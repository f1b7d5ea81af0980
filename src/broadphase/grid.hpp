// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "broadphase/cell_crossing.hpp"
#include "sparse/mover.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// A uniform grid over a box with cell-crossing events (the standard event-driven cell list,
/// e.g. Rapaport's book and DynamO): an element is compared only with the elements of the 27
/// cells around its own, which is exact as long as the cell side is at least the largest
/// interaction distance (sum of two bounding radii). When an element crosses into a new cell
/// it only has to be compared with the 9 cells that became adjacent (O(1) work per event on
/// average). In a periodic box the grid wraps and reports the image shift of each neighbour.
class Grid {
 public:
  struct Config {
    Vec3 lo = Vec3::Zero();
    Vec3 hi = Vec3::Ones();
    bool periodic = false;
    double min_cell_size = 1.0;   // the largest interaction distance; cells are never smaller
    double target_cell_size = 1.0;  // preferred size (>= min) chosen for speed
  };

  /// Whether a grid can be built: a periodic grid needs >= 3 cells per axis so that the 27
  /// neighbours are distinct cells.
  static bool Feasible(const Config& config);

  Grid() = default;
  Grid(const Config& config, std::uint32_t element_capacity);

  /// Places element `e` (centre `p`, inside the box up to round-off) in its cell.
  void Insert(std::uint32_t e, const Vec3& p);
  void Remove(std::uint32_t e);
  std::uint32_t CellOf(std::uint32_t e) const { return cell_of_[e]; }

  /// dt until the centre of `m` leaves the cell `cell` (faces on the outer walls of a walled box
  /// never count). Sets `axis` and `direction` (+1/-1) of the face it leaves through.
  double PredictCrossing(const Mover& m, std::uint32_t cell, double min_dt, int& axis,
                         int& direction) const;

  /// PredictCrossing for a centre on a straight line (p0 + v dt, no acceleration): the same
  /// answer with a division per axis instead of the general quadratic.
  double PredictLinearCrossing(const Vec3& p0, const Vec3& v, std::uint32_t cell, double min_dt,
                               int& axis, int& direction) const {
    const std::array<int, 3> c = Coordinates(cell);
    double best = kInfinity;
    axis = 0;
    direction = 1;
    for (int k = 0; k < 3; ++k) {
      double dt = kInfinity;
      int dir = 1;
      if (v[k] > 0) {
        if (periodic_ || c[k] != n_[k] - 1) {
          const double hi = c[k] == n_[k] - 1 ? lo_[k] + length_[k] : lo_[k] + (c[k] + 1) * size_[k];
          dt = std::max(min_dt, (hi - p0[k]) / v[k]);
        }
      } else if (v[k] < 0) {
        if (periodic_ || c[k] != 0) {
          dt = std::max(min_dt, (lo_[k] + c[k] * size_[k] - p0[k]) / v[k]);
          dir = -1;
        }
      }
      if (dt < best) {
        best = dt;
        axis = k;
        direction = dir;
      }
    }
    return best;
  }

  /// Moves element `e` to the neighbouring cell across (axis, direction). Returns the shift to
  /// add to its position to keep it inside a periodic box (zero unless it wrapped).
  Vec3 Move(std::uint32_t e, int axis, int direction);

  /// Calls fn(j, shift_j) for every element j != e in the 27 cells around e's cell; shift_j is
  /// the periodic image offset to add to j's position.
  template <typename Fn>
  void ForEachNeighbor(std::uint32_t e, Fn&& fn) const {
    const std::array<int, 3> c = Coordinates(cell_of_[e]);
    Span x, y, z;  // Single() fills them from count 0; no need to zero the arrays
    x.count = y.count = z.count = 0;
    Around(0, c[0], x);
    Around(1, c[1], y);
    Around(2, c[2], z);
    VisitBlock(e, x, y, z, fn);
  }

  /// Calls fn(j, shift_j) for the elements in the 9 cells that became adjacent to e when it
  /// moved into its current cell across (axis, direction).
  template <typename Fn>
  void ForEachNewNeighbor(std::uint32_t e, int axis, int direction, Fn&& fn) const {
    const std::array<int, 3> c = Coordinates(cell_of_[e]);
    std::array<Span, 3> spans;
    for (int k = 0; k < 3; ++k) {
      spans[k].count = 0;
      if (k == axis) {
        Single(k, c[k] + direction, spans[k]);
      } else {
        Around(k, c[k], spans[k]);
      }
    }
    VisitBlock(e, spans[0], spans[1], spans[2], fn);
  }

  /// The elements renumbered: element `old_of_new[e]` becomes element e, keeping its cell.
  /// Each cell's list is rebuilt in increasing element order.
  void Permute(const std::vector<std::uint32_t>& old_of_new);

  /// A key that orders cells along a Morton (Z-order) curve: cells near in space get keys near
  /// each other, so elements sorted by it are near in memory when they are near in space.
  std::uint64_t MortonKey(std::uint32_t cell) const;

  const std::array<int, 3>& Dimensions() const { return n_; }
  double CellSize(int axis) const { return size_[axis]; }
  std::size_t MemoryBytes() const;

 private:
  std::array<int, 3> Coordinates(std::uint32_t cell) const {
    const int x = static_cast<int>(cell % static_cast<std::uint32_t>(n_[0]));
    const std::uint32_t rest = cell / static_cast<std::uint32_t>(n_[0]);
    return {x, static_cast<int>(rest % static_cast<std::uint32_t>(n_[1])),
            static_cast<int>(rest / static_cast<std::uint32_t>(n_[1]))};
  }
  std::uint32_t Index(const std::array<int, 3>& c) const {
    return static_cast<std::uint32_t>((c[2] * n_[1] + c[1]) * n_[0] + c[0]);
  }
  std::uint32_t CellAt(const Vec3& p) const;
  void Link(std::uint32_t e, std::uint32_t cell);  // pushes e onto the cell's list

  // Up to three cells along one axis: their coordinate offsets (already multiplied by the
  // axis stride) and periodic image shifts; cells outside a walled grid are left out.
  struct Span {
    std::array<std::uint32_t, 3> offset;
    std::array<double, 3> shift;
    int count;
  };
  void Single(int axis, int at, Span& span) const {
    double shift = 0.0;
    if (at < 0) {
      if (!periodic_) return;
      at += n_[axis];
      shift = -length_[axis];
    } else if (at >= n_[axis]) {
      if (!periodic_) return;
      at -= n_[axis];
      shift = length_[axis];
    }
    span.offset[span.count] = static_cast<std::uint32_t>(at) * stride_[axis];
    span.shift[span.count] = shift;
    ++span.count;
  }
  void Around(int axis, int at, Span& span) const {
    for (int d = -1; d <= 1; ++d) Single(axis, at + d, span);
  }
  template <typename Fn>
  void VisitBlock(std::uint32_t e, const Span& x, const Span& y, const Span& z, Fn& fn) const {
    for (int iz = 0; iz < z.count; ++iz) {
      for (int iy = 0; iy < y.count; ++iy) {
        const std::uint32_t row = z.offset[iz] + y.offset[iy];
        for (int ix = 0; ix < x.count; ++ix) {
          std::uint32_t j = head_[row + x.offset[ix]];
          if (j == kNoIndex) continue;
          const Vec3 shift(x.shift[ix], y.shift[iy], z.shift[iz]);
          for (; j != kNoIndex; j = next_[j]) {
            if (j != e) fn(j, shift);
          }
        }
      }
    }
  }

  Vec3 lo_ = Vec3::Zero();
  Vec3 length_ = Vec3::Ones();
  std::array<double, 3> size_{};
  std::array<int, 3> n_{1, 1, 1};
  std::array<std::uint32_t, 3> stride_{1, 1, 1};  // cell index step per axis (hot in scans)
  bool periodic_ = false;
  std::vector<std::uint32_t> head_;     // first element of each cell
  std::vector<std::uint32_t> next_;     // intrusive doubly linked lists of each cell
  std::vector<std::uint32_t> prev_;
  std::vector<std::uint32_t> cell_of_;
};

}  // namespace sparsedyn
