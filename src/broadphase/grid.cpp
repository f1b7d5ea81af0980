// SPDX-License-Identifier: MIT
#include "broadphase/grid.hpp"

#include <algorithm>
#include <cmath>

#include "sparsedyn/assert.hpp"

namespace sparsedyn {
namespace {

// A cell must exceed the largest interaction distance by a relative margin that covers the
// round-off of crossing times (a crossing handled a few ulps early or late).
constexpr double kCellSlack = 1e-9;

std::array<int, 3> CellCounts(const Grid::Config& config) {
  std::array<int, 3> n{};
  const double size = std::max(config.min_cell_size * (1 + kCellSlack), config.target_cell_size);
  for (int k = 0; k < 3; ++k) {
    const double length = config.hi[k] - config.lo[k];
    n[k] = std::max(1, static_cast<int>(std::floor(length / size)));
    // Never a cell smaller than the interaction distance, even after the floor above.
    while (n[k] > 1 && length / n[k] < config.min_cell_size * (1 + kCellSlack)) --n[k];
  }
  return n;
}

}  // namespace

bool Grid::Feasible(const Config& config) {
  if (!config.periodic) return true;
  const std::array<int, 3> n = CellCounts(config);
  return n[0] >= 3 && n[1] >= 3 && n[2] >= 3;
}

Grid::Grid(const Config& config, std::uint32_t element_capacity)
    : lo_(config.lo), length_(config.hi - config.lo), periodic_(config.periodic) {
  n_ = CellCounts(config);
  for (int k = 0; k < 3; ++k) {
    size_[k] = length_[k] / n_[k];
    faces_[k].resize(static_cast<std::size_t>(n_[k]) + 1);
    for (int face = 0; face < n_[k]; ++face) faces_[k][face] = lo_[k] + face * size_[k];
    faces_[k][n_[k]] = lo_[k] + length_[k];
    if (!periodic_) {
      faces_[k][0] = -kInfinity;
      faces_[k][n_[k]] = kInfinity;
    }
  }
  stride_ = {1u, static_cast<std::uint32_t>(n_[0]), static_cast<std::uint32_t>(n_[0] * n_[1])};
  per_row_ = FastDivisor(static_cast<std::uint32_t>(n_[0]));
  per_layer_ = FastDivisor(static_cast<std::uint32_t>(n_[1]));
  const std::int32_t sy = n_[0], sz = n_[0] * n_[1];
  for (int dz = -1, r = 0; dz <= 1; ++dz) {
    for (int dy = -1; dy <= 1; ++dy, ++r) around_rows_[r] = dz * sz + dy * sy - 1;
  }
  for (int direction = -1; direction <= 1; direction += 2) {
    const int side = direction > 0 ? 1 : 0;
    for (int a = -1, r = 0; a <= 1; ++a) {
      for (int b = -1; b <= 1; ++b, ++r) new_cells_[side][r] = direction + a * sy + b * sz;
      new_cells_[2 + side][a + 1] = direction * sy + a * sz - 1;
      new_cells_[4 + side][a + 1] = direction * sz + a * sy - 1;
      for (int b = -1; b <= 1; ++b) {
        new_singles_[2 + side][(a + 1) * 3 + b + 1] = direction * sy + a * sz + b;
        new_singles_[4 + side][(a + 1) * 3 + b + 1] = direction * sz + a * sy + b;
      }
    }
  }
  new_singles_[0] = new_cells_[0];
  new_singles_[1] = new_cells_[1];
  BuildOuterTables();
  head_.assign(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2], kNoIndex);
  cells_ = FastDivisor(static_cast<std::uint32_t>(head_.size()));
  own_links_.assign(element_capacity, GridLinks{});
  UseOwnLinks();
}

void Grid::BuildOuterTables() {
  if (!periodic_) return;  // walled grids gather through spans (cells beyond a wall are left out)
  // Along axis k, a cell of each kind sees the spans a cell on that layer sees (Around: the
  // first layer's -1 neighbour wraps to the last layer, its image a box length below, and the
  // last layer's +1 neighbour to the first), as offsets from the cell itself.
  std::array<std::array<std::array<std::int32_t, 3>, 3>, 3> step{};  // [axis][kind][i]
  for (int k = 0; k < 3; ++k) {
    for (int kind = 0; kind < 3; ++kind) {
      const int at = kind == 0 ? 0 : (kind == 2 ? n_[k] - 1 : 1);
      Span span{};
      Around(k, at, span);
      SPARSEDYN_ASSERT(span.count == 3, "a periodic grid has 3 neighbours per axis");
      const std::uint32_t middle = static_cast<std::uint32_t>(at) * stride_[k];
      for (int i = 0; i < 3; ++i) {
        step[k][kind][i] = static_cast<std::int32_t>(span.offset[i] - middle);
        wrap_shifts_[k][kind][i] = span.shift[i];
      }
    }
  }
  for (std::size_t kind = 0; kind < 27; ++kind) {
    for (std::size_t r = 0; r < 27; ++r) {
      wrap_offsets_[kind][r] =
          step[0][kind % 3][r % 3] + step[1][kind / 3 % 3][r / 3 % 3] + step[2][kind / 9][r / 9];
    }
  }
  // The 9 new cells across (axis, direction): the layer at i = direction + 1 along the axis.
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      std::size_t count = 0;
      for (std::uint8_t r = 0; r < 27; ++r) {
        const int i = axis == 0 ? r % 3 : (axis == 1 ? r / 3 % 3 : r / 9);
        if (i == side * 2) new_positions_[static_cast<std::size_t>(axis * 2 + side)][count++] = r;
      }
    }
  }
}

std::uint32_t Grid::CellAt(const Vec3& p) const {
  std::array<int, 3> c{};
  for (int k = 0; k < 3; ++k) {
    const int i = static_cast<int>(std::floor((p[k] - lo_[k]) / size_[k]));
    c[k] = std::clamp(i, 0, n_[k] - 1);
  }
  return Index(c);
}

void Grid::Insert(std::uint32_t e, const Vec3& p) {
  if (e >= elements_) {
    SPARSEDYN_ASSERT(OwnsLinks(), "Grid::Insert beyond the owner's links");
    const std::size_t size = std::max<std::size_t>(e + 1, elements_ * 2);
    own_links_.resize(size, GridLinks{});
    UseOwnLinks();
  }
  Link(e, CellAt(p));
}

double Grid::PredictCrossing(const Mover& m, std::uint32_t cell, double min_dt, int& axis,
                             int& direction) const {
  const std::array<int, 3> c = Coordinates(cell);
  double best = kInfinity;
  axis = 0;
  direction = 1;
  for (int k = 0; k < 3; ++k) {
    // Faces on the outside of a walled box are not crossings: the walls keep the centre in.
    const bool first = c[k] == 0;
    const bool last = c[k] == n_[k] - 1;
    // The box faces are exact (lo_ and lo_ + length_), so that periodic wraps happen at the same
    // times as with AllPairs.
    double lo = lo_[k] + c[k] * size_[k];
    double hi = last ? lo_[k] + length_[k] : lo_[k] + (c[k] + 1) * size_[k];
    if (!periodic_) {
      if (first) lo = -kInfinity;
      if (last) hi = kInfinity;
    }
    int dir = 1;
    const double dt = SlabExitTime(m.p[k], m.v[k], m.a[k], lo, hi, min_dt, dir);
    if (dt < best) {
      best = dt;
      axis = k;
      direction = dir;
    }
  }
  return best;
}

void Grid::Permute(const std::vector<std::uint32_t>& old_of_new) {
  if (OwnsLinks()) {
    const BigVector<GridLinks> old = own_links_;
    for (std::size_t e = 0; e < old_of_new.size(); ++e) own_links_[e] = old[old_of_new[e]];
  }
  Relink();
}

void Grid::Relink() {
  std::fill(head_.begin(), head_.end(), kNoIndex);
  // Linking pushes to the front: link in decreasing order so lists run in increasing order.
  for (std::size_t e = elements_; e-- > 0;) {
    const auto element = static_cast<std::uint32_t>(e);
    const std::uint32_t cell = Links(element).cell;
    if (cell != kNoIndex) Link(element, cell);
  }
}

std::uint64_t Grid::MortonKey(std::uint32_t cell) const {
  // Spreads the low 21 bits of x so that they occupy every third bit.
  auto spread = [](std::uint64_t x) {
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffULL;
    x = (x | x << 16) & 0x1f0000ff0000ffULL;
    x = (x | x << 8) & 0x100f00f00f00f00fULL;
    x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2) & 0x1249249249249249ULL;
    return x;
  };
  const std::array<int, 3> c = Coordinates(cell);
  return spread(static_cast<std::uint64_t>(c[0])) | spread(static_cast<std::uint64_t>(c[1])) << 1 |
         spread(static_cast<std::uint64_t>(c[2])) << 2;
}

std::size_t Grid::MemoryBytes() const {
  // The owner counts its records, links included.
  return head_.capacity() * sizeof(std::uint32_t) + own_links_.capacity() * sizeof(GridLinks) +
         (faces_[0].capacity() + faces_[1].capacity() + faces_[2].capacity()) * sizeof(double);
}

}  // namespace sparsedyn
