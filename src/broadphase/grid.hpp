// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <vector>

#include "broadphase/cell_crossing.hpp"
#include "math/branchless.hpp"
#include "math/fast_divisor.hpp"
#include "base/huge_pages.hpp"
#include "base/prefetch.hpp"
#include "sparse/mover.hpp"
#include "sparsedyn/assert.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// An element's place in the Grid's cell lists: its cell and the next element of that cell's
/// list (kNoIndex at the end; kNoIndex as the cell: not in the grid).
struct GridLinks {
  std::uint32_t cell = kNoIndex;
  std::uint32_t next = kNoIndex;
};

/// log2 of a record's size, for Grid::UseLinks' stride (records are powers of two in size).
template <typename Record>
constexpr unsigned StrideShiftOf() {
  static_assert(std::has_single_bit(sizeof(Record)), "a record's size must be a power of two");
  return static_cast<unsigned>(std::countr_zero(sizeof(Record)));
}

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
    double min_cell_size = 1.0;     // the largest interaction distance; cells are never smaller
    double target_cell_size = 1.0;  // preferred size (>= min) chosen for speed
  };

  /// Whether a grid can be built: a periodic grid needs >= 3 cells per axis so that the 27
  /// neighbours are distinct cells.
  static bool Feasible(const Config& config);

  Grid() = default;
  Grid(const Config& config, std::uint32_t element_capacity);
  // Not copied: the links may point into the grid's own array (a move keeps its buffer).
  Grid(const Grid&) = delete;
  Grid& operator=(const Grid&) = delete;
  Grid(Grid&&) = default;
  Grid& operator=(Grid&&) = default;
  ~Grid() = default;

  /// Keeps the elements' links in the owner's records instead of the grid's own array: element
  /// e's links at byte e << stride_shift from `first`, for `count` elements (and the owner
  /// calls this again whenever the records move). A scan then finds a neighbour's successor
  /// in the same cache line as the neighbour's data, which it reads anyway. The links there
  /// are taken as they are: Relink() rebuilds the lists from their cells.
  void UseLinks(GridLinks* first, unsigned stride_shift, std::size_t count) {
    if (first != own_links_.data()) BigVector<GridLinks>().swap(own_links_);
    links_ = reinterpret_cast<char*>(first);
    links_shift_ = stride_shift;
    elements_ = count;
  }

  /// Places element `e` (centre `p`, inside the box up to round-off) in its cell.
  void Insert(std::uint32_t e, const Vec3& p);
  void Remove(std::uint32_t e);
  std::uint32_t CellOf(std::uint32_t e) const { return Links(e).cell; }

  /// dt until the centre of `m` leaves the cell `cell` (faces on the outer walls of a walled box
  /// never count). Sets `axis` and `direction` (+1/-1) of the face it leaves through.
  double PredictCrossing(const Mover& m, std::uint32_t cell, double min_dt, int& axis,
                         int& direction) const;

  /// A cell and its coordinates, worked out once per event for the scans and the crossing
  /// prediction below (the coordinates cost two integer divisions).
  struct Place {
    std::uint32_t cell;
    std::array<int, 3> at;
  };
  Place PlaceOf(std::uint32_t e) const {
    const std::uint32_t cell = Links(e).cell;
    return {cell, Coordinates(cell)};
  }

  /// PredictCrossing for a centre on a straight line (p0 + v dt, no acceleration): the same
  /// answer with a division per axis instead of the general quadratic. Without branches on the
  /// data: which axis comes first is a coin toss for the branch predictor, and the crossing is
  /// predicted after every event of a gas.
  double PredictLinearCrossing(const Vec3& p0, const Vec3& v, const Place& place, double min_dt,
                               int& axis, int& direction) const {
    std::array<double, 3> dt;
    std::uint32_t ups = 0;  // bit k: moving up along k
#if defined(__SSE2__)
    // x and y as one pair (the same operations per lane as the loop below, so the same bits):
    // half the instructions, the masks kept in vector registers.
    const __m128d zero = _mm_setzero_pd();
    const __m128d v_xy = _mm_loadu_pd(v.data());
    const __m128d up_xy = _mm_cmpgt_pd(v_xy, zero);
    const __m128d moving_xy = _mm_or_pd(up_xy, _mm_cmplt_pd(v_xy, zero));  // NaN: at rest
    const __m128d v_z = _mm_set_sd(v[2]);
    const __m128d up_z = _mm_cmpgt_sd(v_z, zero);
    const __m128d moving_z = _mm_or_pd(up_z, _mm_cmplt_sd(v_z, zero));
    ups = static_cast<std::uint32_t>(_mm_movemask_pd(up_xy) | (_mm_movemask_pd(up_z) & 1) << 2);
    const __m128d face_xy =
        _mm_set_pd(faces_[1][static_cast<std::size_t>(place.at[1]) + ((ups >> 1) & 1u)],
                   faces_[0][static_cast<std::size_t>(place.at[0]) + (ups & 1u)]);
    const __m128d face_z =
        _mm_set_sd(faces_[2][static_cast<std::size_t>(place.at[2]) + (ups >> 2)]);
    const __m128d min = _mm_set1_pd(min_dt), never = _mm_set1_pd(kInfinity);
    __m128d dt_xy = _mm_div_pd(_mm_sub_pd(face_xy, _mm_loadu_pd(p0.data())), v_xy);
    dt_xy = _mm_max_pd(dt_xy, min);  // MaxOf(min_dt, dt) per lane
    dt_xy = _mm_or_pd(_mm_and_pd(moving_xy, dt_xy), _mm_andnot_pd(moving_xy, never));
    __m128d dt_z = _mm_div_sd(_mm_sub_sd(face_z, _mm_set_sd(p0[2])), v_z);
    dt_z = _mm_max_sd(dt_z, min);
    dt_z = _mm_or_pd(_mm_and_pd(moving_z, dt_z), _mm_andnot_pd(moving_z, never));
    dt[0] = _mm_cvtsd_f64(dt_xy);
    dt[1] = _mm_cvtsd_f64(_mm_unpackhi_pd(dt_xy, dt_xy));
    dt[2] = _mm_cvtsd_f64(dt_z);
#else
    for (int k = 0; k < 3; ++k) {
      const bool up = v[k] > 0;
      const bool moving = up | (v[k] < 0);  // at rest along k (or NaN): never leaves
      const double face = faces_[k][static_cast<std::size_t>(place.at[k] + (up ? 1 : 0))];
      dt[k] = Select(moving, MaxOf(min_dt, (face - p0[k]) / v[k]), kInfinity);
      ups |= static_cast<std::uint32_t>(up) << k;
    }
#endif
    // The earliest; ties go to the lower axis; never leaving: axis 0, direction +1 (the general
    // PredictCrossing's answers). Integer selects as arithmetic: GCC branches on `?:` here.
    const double best = MinOf(dt[0], MinOf(dt[1], dt[2]));
    const auto not0 = static_cast<std::uint32_t>(dt[0] != best);
    const auto not1 = static_cast<std::uint32_t>(dt[1] != best);
    const std::uint32_t k = not0 * (1 + not1);  // 0, 1 or 2
    const std::uint32_t leaves = static_cast<std::uint32_t>(best != kInfinity);
    axis = static_cast<int>(k * leaves);
    direction = static_cast<int>(((ups >> k) & 1u) | (1u - leaves)) * 2 - 1;
    return best;
  }

  /// Moves element `e` to the neighbouring cell across (axis, direction) and returns its new
  /// place. Sets `shift` to what must be added to its position to keep it inside a periodic box
  /// (zero unless it wrapped).
  Place Move(std::uint32_t e, int axis, int direction, Vec3& shift);

  /// Calls fn(j, shift_j) for every element j != e in the 27 cells around e's cell (at
  /// `place`, PlaceOf(e)); shift_j is the periodic image offset to add to j's position.
  template <typename Fn>
  void ForEachNeighbor(std::uint32_t e, const Place& place, Fn&& fn) const {
    if (Interior(place)) {
      VisitRows(e, place.cell, around_rows_.data(), 9, fn);
      return;
    }
    const std::array<Span, 3> spans = AroundSpans(place);
    VisitBlock(e, spans[0], spans[1], spans[2], fn);
  }
  template <typename Fn>
  void ForEachNeighbor(std::uint32_t e, Fn&& fn) const {
    ForEachNeighbor(e, PlaceOf(e), fn);
  }

  /// Calls fn(j, shift_j) for the elements in the 9 cells that became adjacent to e (at
  /// `place`, PlaceOf(e)) when it moved into its current cell across (axis, direction).
  template <typename Fn>
  void ForEachNewNeighbor(std::uint32_t e, const Place& place, int axis, int direction,
                          Fn&& fn) const {
    if (Interior(place)) {
      const std::int32_t* offsets = new_cells_[axis * 2 + (direction > 0 ? 1 : 0)].data();
      if (axis == 0) {
        VisitCells(e, place.cell, offsets, 9, fn);  // a plane across x: no runs along x
      } else {
        VisitRows(e, place.cell, offsets, 3, fn);
      }
      return;
    }
    const std::array<Span, 3> spans = NewSpans(place, axis, direction);
    VisitBlock(e, spans[0], spans[1], spans[2], fn);
  }

  /// Whether the cell at `place` is off the grid's outer layer: its 27 neighbours are then in
  /// the grid, unwrapped (no image shift), at fixed index offsets, and ForEachGathered...
  /// below apply.
  bool Interior(const Place& place) const {
    return place.at[0] > 0 && place.at[0] < n_[0] - 1 && place.at[1] > 0 &&
           place.at[1] < n_[1] - 1 && place.at[2] > 0 && place.at[2] < n_[2] - 1;
  }

  /// For an interior `place`: calls fn(j, shift) (shift zero) for every element j of the 27
  /// cells around it, the place's own elements included (what ForEachNeighbor visits, plus e), in
  /// another order and without a branch on which cells are empty or how long their lists are: in a
  /// gas most cells hold zero or one element, and a walk that branches on that is mispredicted
  /// every few cells. `pending` is the work list (resized to hold every element, so it never grows
  /// during a visit); fn may overwrite its entries up to the one it is called for (they have been
  /// read).
  template <typename Fn>
  void ForEachGatheredAround(const Place& place, BigVector<std::uint32_t>& pending, Fn&& fn) const {
    VisitGathered<9, 3>(place.cell, around_rows_.data(), pending, fn);
  }

  /// ForEachGatheredAround for the 9 cells that became adjacent to an interior `place` entered
  /// across (axis, direction): what ForEachNewNeighbor visits.
  template <typename Fn>
  void ForEachGatheredNew(const Place& place, int axis, int direction,
                          BigVector<std::uint32_t>& pending, Fn&& fn) const {
    // Nine single cells whatever the axis: which axis was crossed is a coin toss, and a branch
    // on it (rows along x for y and z) was mispredicted at every third crossing.
    const int side = axis * 2 + (direction > 0 ? 1 : 0);
    VisitGathered<9, 1>(place.cell, new_singles_[side].data(), pending, fn);
  }

  /// ForEachGatheredAround for any `place`, the grid's outer layer included: calls fn(j, shift)
  /// with j's periodic image shift (as ForEachNeighbor), and for e itself (zero shift). The
  /// grid must hold fewer than 2^26 elements (each work-list entry carries its cell).
  template <typename Fn>
  void ForEachGatheredAroundWrapped(const Place& place, BigVector<std::uint32_t>& pending,
                                    Fn&& fn) const {
    if (periodic_) {
      VisitGatheredOuter<27>(place, /*positions=*/nullptr, pending, fn);
      return;
    }
    const std::array<Span, 3> spans = AroundSpans(place);
    VisitGatheredBlock(spans[0], spans[1], spans[2], pending, fn);
  }

  /// ForEachGatheredNew for any `place`: what ForEachNewNeighbor visits, as fn(j, shift).
  template <typename Fn>
  void ForEachGatheredNewWrapped(const Place& place, int axis, int direction,
                                 BigVector<std::uint32_t>& pending, Fn&& fn) const {
    if (periodic_) {
      VisitGatheredOuter<9>(place, new_positions_[axis * 2 + (direction > 0 ? 1 : 0)].data(),
                            pending, fn);
      return;
    }
    const std::array<Span, 3> spans = NewSpans(place, axis, direction);
    VisitGatheredBlock(spans[0], spans[1], spans[2], pending, fn);
  }

  /// The periodic image shift of element j seen from the cell at `from`, as the visits above
  /// report it for a j in one of the 27 cells around it (zero unless the neighbourhood wraps).
  Vec3 ImageShift(const Place& from, std::uint32_t j) const {
    const std::array<int, 3> at = Coordinates(Links(j).cell);
    Vec3 shift = Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
      const int d = at[k] - from.at[k];
      if (d > 1) shift[k] = -length_[k];  // j across the low face: its image below
      if (d < -1) shift[k] = length_[k];
    }
    return shift;
  }

  // The look-ahead of a gas beyond the caches (the World's LookAhead). Fetches only, for
  // guesses: any cell index is accepted (wrapped into the grid, a wrong cell near the outer
  // layer costs a useless fetch).

  /// Fetches the head rows of the 27 cells around `cell`.
  void FetchAround(std::uint32_t cell) const {
    for (const std::int32_t offset : around_rows_) {
      Prefetch(&head_[cells_.Remainder(cell + static_cast<std::uint32_t>(offset))]);
    }
  }
  /// Fetches the records of the first elements of the 9 cells that become adjacent when an
  /// element enters `cell` across (axis, direction), ahead of ForEachGatheredNew. Reads their
  /// heads, which FetchAround should have fetched an event or more before. Indices wrap as in
  /// FetchAround.
  void FetchNewFirsts(std::uint32_t cell, int axis, int direction) const {
    const std::int32_t* offsets = new_cells_[axis * 2 + (direction > 0 ? 1 : 0)].data();
    if (axis == 0) {
      FetchFirsts(cell, offsets, 9, 1);  // a plane across x: single cells
    } else {
      FetchFirsts(cell, offsets, 3, 3);  // rows along x
    }
  }
  /// FetchNewFirsts for the 27 cells around `cell`, ahead of ForEachGatheredAround.
  void FetchAroundFirsts(std::uint32_t cell) const { FetchFirsts(cell, around_rows_.data(), 9, 3); }
  /// The cell across (axis, direction) from `cell`, wrapped into the grid as an index only.
  std::uint32_t CellAcross(std::uint32_t cell, int axis, int direction) const {
    return cells_.Remainder(cell + static_cast<std::uint32_t>(direction) * stride_[axis]);
  }

  /// The elements renumbered: element `old_of_new[e]` becomes element e, keeping its cell.
  /// Each cell's list is rebuilt in increasing element order. With the owner's links (UseLinks)
  /// the owner has moved the records already: only the lists are rebuilt (Relink).
  void Permute(const std::vector<std::uint32_t>& old_of_new);
  /// Rebuilds every cell's list from the elements' cells, in increasing element order.
  void Relink();

  /// A key that orders cells along a Morton (Z-order) curve: cells near in space get keys near
  /// each other, so elements sorted by it are near in memory when they are near in space.
  std::uint64_t MortonKey(std::uint32_t cell) const;

  const std::array<int, 3>& Dimensions() const { return n_; }
  double CellSize(int axis) const { return size_[axis]; }
  std::size_t MemoryBytes() const;

 private:
  std::array<int, 3> Coordinates(std::uint32_t cell) const {
    // Each crossing decodes its cell: two multiplications instead of two integer divisions.
    const std::uint32_t rest = per_row_.Divide(cell);
    const std::uint32_t z = per_layer_.Divide(rest);
    return {static_cast<int>(cell - rest * per_row_.Divisor()),
            static_cast<int>(rest - z * per_layer_.Divisor()), static_cast<int>(z)};
  }
  std::uint32_t Index(const std::array<int, 3>& c) const {
    return static_cast<std::uint32_t>((c[2] * n_[1] + c[1]) * n_[0] + c[0]);
  }
  std::uint32_t CellAt(const Vec3& p) const;
  void BuildOuterTables();
  void Link(std::uint32_t e, std::uint32_t cell);  // pushes e onto the cell's list

  // The first element's record of each cell of `runs` runs of `run` consecutive cells from
  // cell + offsets[r] on, fetched (FetchNewFirsts, FetchAroundFirsts).
  void FetchFirsts(std::uint32_t cell, const std::int32_t* offsets, int runs, int run) const {
    for (int r = 0; r < runs; ++r) {
      const std::uint32_t first = cell + static_cast<std::uint32_t>(offsets[r]);
      for (int c = 0; c < run; ++c) {
        const std::uint32_t h = head_[cells_.Remainder(first + static_cast<std::uint32_t>(c))];
        if (h != kNoIndex) Prefetch(&Links(h));
      }
    }
  }

  // Up to three cells along one axis: their coordinate offsets (already multiplied by the
  // axis stride) and periodic image shifts; cells outside a walled grid are left out.
  // `interior`: the three cells around one inside the grid (consecutive, no shift).
  struct Span {
    std::array<std::uint32_t, 3> offset;
    std::array<double, 3> shift;
    int count;
    bool interior;
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
    span.count = 0;
    span.interior = at > 0 && at < n_[axis] - 1;
    if (span.interior) {  // most cells: no wrap, no wall
      const std::uint32_t stride = stride_[axis];
      const std::uint32_t middle = static_cast<std::uint32_t>(at) * stride;
      span.offset = {middle - stride, middle, middle + stride};
      span.shift = {0.0, 0.0, 0.0};
      span.count = 3;
      return;
    }
    for (int d = -1; d <= 1; ++d) Single(axis, at + d, span);
  }
  // The block of 27 cells around `place`, and the 9 that became adjacent when it was entered
  // across (axis, direction): the layer beyond it along the axis.
  std::array<Span, 3> AroundSpans(const Place& place) const {
    std::array<Span, 3> spans;
    for (int k = 0; k < 3; ++k) Around(k, place.at[k], spans[k]);
    return spans;
  }
  std::array<Span, 3> NewSpans(const Place& place, int axis, int direction) const {
    std::array<Span, 3> spans;
    for (int k = 0; k < 3; ++k) {
      if (k == axis) {
        spans[k].count = 0;
        spans[k].interior = false;
        Single(k, place.at[k] + direction, spans[k]);
      } else {
        Around(k, place.at[k], spans[k]);
      }
    }
    return spans;
  }
  // The runs of kRun consecutive cells from cell + offsets[r] on (r < kRuns): their heads are
  // written to `pending` first, each counted only if not empty (a select, not a branch; a run
  // of three is read as one row, a third of the address work); then each pending element, in
  // turn, has its list successor appended in the same way and is handed to fn. Its successor
  // and its data are then fetched together, as a walk along the list would.
  template <int kRuns, int kRun, typename Fn>
  void VisitGathered(std::uint32_t cell, const std::int32_t* offsets,
                     BigVector<std::uint32_t>& pending, Fn& fn) const {
    // Room for every element and the heads: no check in the loop (a call there would make it
    // keep fn's values in memory).
    constexpr int kCount = kRuns * kRun;
    if (pending.size() < elements_ + kCount + 1) pending.resize(elements_ + kCount + 1);
    std::uint32_t* buffer = pending.data();
    std::uint32_t n = 0;
    for (int r = 0; r < kRuns; ++r) {
      const std::uint32_t* heads = &head_[cell + static_cast<std::uint32_t>(offsets[r])];
      for (int c = 0; c < kRun; ++c) {
        const std::uint32_t h = heads[c];
        buffer[n] = h;
        n += h != kNoIndex ? 1u : 0u;
      }
    }
    const Vec3 no_shift = Vec3::Zero();  // interior cells
    // The link array's address and stride in registers: the buffer's writes (unsigned, like
    // links_shift_) would otherwise make the compiler reload them for every element.
    const char* const links = links_;
    const unsigned links_shift = links_shift_;
    for (std::uint32_t k = 0; k < n; ++k) {
      const std::uint32_t j = buffer[k];
      const std::uint32_t next = NextIn(links, links_shift, j);
      buffer[n] = next;
      n += next != kNoIndex ? 1u : 0u;
      fn(j, no_shift);
    }
  }
  // VisitGathered over the cells x × y × z of any place (wrapped, or cut off by walls): each
  // work-list entry carries its cell's position in the block (ix | iy << 2 | iz << 4) in the
  // bits above kIndexBits, and the list successors it appends inherit it.
  static constexpr unsigned kIndexBits = 26;
  template <typename Fn>
  void VisitGatheredBlock(const Span& x, const Span& y, const Span& z,
                          BigVector<std::uint32_t>& pending, Fn& fn) const {
    SPARSEDYN_ASSERT(elements_ < (std::size_t{1} << kIndexBits), "too many elements to gather");
    if (pending.size() < elements_ + 28) pending.resize(elements_ + 28);
    std::uint32_t* buffer = pending.data();
    std::uint32_t n = 0;
    for (std::uint32_t iz = 0; iz < static_cast<std::uint32_t>(z.count); ++iz) {
      for (std::uint32_t iy = 0; iy < static_cast<std::uint32_t>(y.count); ++iy) {
        const std::uint32_t row = z.offset[iz] + y.offset[iy];
        for (std::uint32_t ix = 0; ix < static_cast<std::uint32_t>(x.count); ++ix) {
          const std::uint32_t h = head_[row + x.offset[ix]];
          buffer[n] = h | (ix | iy << 2 | iz << 4) << kIndexBits;  // empty: overwritten
          n += h != kNoIndex ? 1u : 0u;
        }
      }
    }
    WalkTagged(buffer, n, x.shift.data(), y.shift.data(), z.shift.data(), fn);
  }
  // The walk of a tagged work list of n heads (VisitGatheredBlock, VisitGatheredOuter): each
  // entry's successor is appended with its tag, and fn gets the shift the tag names
  // (sx[ix], sy[iy], sz[iz]). Inline: out of line (GCC's choice since the World split) it
  // cost the wrapped gathers 9 M instructions at N = 10^4 (fn's values kept in memory).
  template <typename Fn>
  [[gnu::always_inline]] void WalkTagged(std::uint32_t* buffer, std::uint32_t n, const double* sx, const double* sy,
                  const double* sz, Fn& fn) const {
    constexpr std::uint32_t kIndexMask = (1u << kIndexBits) - 1;
    const char* const links = links_;  // in registers, as in VisitGathered
    const unsigned links_shift = links_shift_;
    for (std::uint32_t k = 0; k < n; ++k) {
      const std::uint32_t entry = buffer[k];
      const std::uint32_t j = entry & kIndexMask;
      const std::uint32_t next = NextIn(links, links_shift, j);
      buffer[n] = next | (entry & ~kIndexMask);
      n += next != kNoIndex ? 1u : 0u;
      const std::uint32_t tag = entry >> kIndexBits;
      fn(j, Vec3(sx[tag & 3], sy[(tag >> 2) & 3], sz[tag >> 4]));
    }
  }
  // The outer layer of a periodic grid. A cell's kind along an axis is 0 on the grid's first
  // layer, 2 on its last, 1 between; the 27 kinds of cell (13: interior) each have their 27
  // neighbours at fixed index offsets with the wrap built in (wrap_offsets_), by position
  // r = ix + 3 iy + 9 iz (i = 0, 1, 2 for -1, 0, +1 along each axis), and each axis's three
  // image shifts by kind (wrap_shifts_). A gather then walks a fixed list of positions as
  // an interior one does, instead of working out spans: at N = 10^4 the outer layer holds a
  // seventh of the cells, and its gathers, through spans, cost twice an interior one.
  static int KindAlong(int at, int n) { return (at != 0 ? 1 : 0) + (at == n - 1 ? 1 : 0); }
  // kCount 27: every position, in order (`positions` unused); 9: the crossing's `positions`.
  template <int kCount, typename Fn>
  void VisitGatheredOuter(const Place& place, const std::uint8_t* positions,
                          BigVector<std::uint32_t>& pending, Fn& fn) const {
    SPARSEDYN_ASSERT(elements_ < (std::size_t{1} << kIndexBits), "too many elements to gather");
    if (pending.size() < elements_ + 28) pending.resize(elements_ + 28);
    const int kx = KindAlong(place.at[0], n_[0]), ky = KindAlong(place.at[1], n_[1]),
              kz = KindAlong(place.at[2], n_[2]);
    const std::int32_t* offsets =
        wrap_offsets_[static_cast<std::size_t>(kx + 3 * ky + 9 * kz)].data();
    const double* sx = wrap_shifts_[0][static_cast<std::size_t>(kx)].data();
    const double* sy = wrap_shifts_[1][static_cast<std::size_t>(ky)].data();
    const double* sz = wrap_shifts_[2][static_cast<std::size_t>(kz)].data();
    std::uint32_t* buffer = pending.data();
    std::uint32_t n = 0;
    for (int k = 0; k < kCount; ++k) {
      // All 27: constants once unrolled.
      const std::uint32_t r = kCount == 27 ? static_cast<std::uint32_t>(k) : positions[k];
      const std::uint32_t h = head_[place.cell + static_cast<std::uint32_t>(offsets[r])];
      buffer[n] = h | std::uint32_t{kPositionTags[r]} << kIndexBits;  // empty: overwritten
      n += h != kNoIndex ? 1u : 0u;
    }
    WalkTagged(buffer, n, sx, sy, sz, fn);
  }
  // Position r as the work list's tag, ix | iy << 2 | iz << 4 (no division in the walk).
  static constexpr std::array<std::uint8_t, 27> kPositionTags = [] {
    std::array<std::uint8_t, 27> tags{};
    for (int r = 0; r < 27; ++r) {
      tags[r] = static_cast<std::uint8_t>(r % 3 | r / 3 % 3 << 2 | r / 9 << 4);
    }
    return tags;
  }();

  // Rows of three cells along x starting at cell + offsets[r]; cells + offsets[r] one by one.
  // Indices wrap as unsigned numbers: cell + offset stays inside the grid for an interior cell.
  template <typename Fn>
  void VisitRows(std::uint32_t e, std::uint32_t cell, const std::int32_t* offsets, int count,
                 Fn& fn) const {
    const Vec3 shift = Vec3::Zero();
    for (int r = 0; r < count; ++r) {
      VisitRowOfThree(e, &head_[cell + static_cast<std::uint32_t>(offsets[r])], shift, fn);
    }
  }
  // Three consecutive cells from `heads` on, all with image shift `shift`. Most cells are empty
  // (a gas has a few cells per element), so an empty row costs one test of its three heads.
  template <typename Fn>
  void VisitRowOfThree(std::uint32_t e, const std::uint32_t* heads, const Vec3& shift,
                       Fn& fn) const {
    const std::uint32_t h0 = heads[0], h1 = heads[1], h2 = heads[2];
    if ((h0 & h1 & h2) == kNoIndex) return;  // kNoIndex is all ones
    VisitList(e, h0, shift, fn);
    VisitList(e, h1, shift, fn);
    VisitList(e, h2, shift, fn);
  }
  template <typename Fn>
  void VisitCells(std::uint32_t e, std::uint32_t cell, const std::int32_t* offsets, int count,
                  Fn& fn) const {
    const Vec3 shift = Vec3::Zero();
    for (int r = 0; r < count; ++r) {
      const std::uint32_t j = head_[cell + static_cast<std::uint32_t>(offsets[r])];
      if (j != kNoIndex) VisitList(e, j, shift, fn);
    }
  }
  template <typename Fn>
  void VisitList(std::uint32_t e, std::uint32_t j, const Vec3& shift, Fn& fn) const {
    for (; j != kNoIndex; j = Links(j).next) {
      if (j != e) fn(j, shift);
    }
  }
  // The cells of x × y × z, row by row along x (an interior x span as one row of three).
  template <typename Fn>
  void VisitBlock(std::uint32_t e, const Span& x, const Span& y, const Span& z, Fn& fn) const {
    for (int iz = 0; iz < z.count; ++iz) {
      for (int iy = 0; iy < y.count; ++iy) {
        const std::uint32_t row = z.offset[iz] + y.offset[iy];
        if (x.interior) {
          VisitRowOfThree(e, &head_[row + x.offset[0]], Vec3(0.0, y.shift[iy], z.shift[iz]), fn);
          continue;
        }
        for (int ix = 0; ix < x.count; ++ix) {
          const std::uint32_t j = head_[row + x.offset[ix]];
          if (j == kNoIndex) continue;
          VisitList(e, j, Vec3(x.shift[ix], y.shift[iy], z.shift[iz]), fn);
        }
      }
    }
  }

  Vec3 lo_ = Vec3::Zero();
  Vec3 length_ = Vec3::Ones();
  std::array<double, 3> size_{};
  std::array<int, 3> n_{1, 1, 1};
  std::array<std::uint32_t, 3> stride_{1, 1, 1};  // cell index step per axis (hot in scans)
  FastDivisor per_row_, per_layer_;               // by n_[0] and by n_[1], for Coordinates
  FastDivisor cells_;  // by the cell count: the look-ahead wraps its guessed cells with it
  // The positions of the n_[k] + 1 faces along each axis, as PredictCrossing works them out
  // (the box faces exact: lo_ and lo_ + length_); the outer faces of a walled box, which are
  // no crossings, at -/+ infinity, which a centre never reaches.
  std::array<std::vector<double>, 3> faces_;
  // Around an interior cell: the index offsets of the 9 rows of three cells along x that make
  // up its 27 neighbours (to each row's first cell), and for each crossing (axis * 2 + (1 if
  // direction > 0)) the 9 cells that became adjacent: 9 single cells for axis x, else 3 rows.
  std::array<std::int32_t, 9> around_rows_{};
  std::array<std::array<std::int32_t, 9>, 6> new_cells_{};
  // The same 9 cells as single cells for every side (ForEachGatheredNew).
  std::array<std::array<std::int32_t, 9>, 6> new_singles_{};
  // The outer layer of a periodic grid (VisitGatheredOuter): by kind kx + 3 ky + 9 kz, the
  // index offsets of the 27 neighbours by position; by axis and kind, the three image shifts;
  // for each crossing, the positions of the 9 new cells.
  std::array<std::array<std::int32_t, 27>, 27> wrap_offsets_{};
  std::array<std::array<std::array<double, 3>, 3>, 3> wrap_shifts_{};
  std::array<std::array<std::uint8_t, 9>, 6> new_positions_{};
  bool periodic_ = false;
  BigVector<std::uint32_t> head_;  // first element of each cell
  // Each element's links (an intrusive singly linked list per cell: a cell holds about one
  // element, so unlinking walks a step or two where a back link would be one more array, and
  // one more cache miss per move beyond the caches): in own_links_ or in the owner's records
  // (UseLinks).
  const GridLinks& Links(std::uint32_t e) const {
    return *reinterpret_cast<const GridLinks*>(links_ + (std::size_t{e} << links_shift_));
  }
  GridLinks& Links(std::uint32_t e) {
    return *reinterpret_cast<GridLinks*>(links_ + (std::size_t{e} << links_shift_));
  }
  // Links(j).next from the link array's address and stride, which a loop holds in registers.
  static std::uint32_t NextIn(const char* links, unsigned links_shift, std::uint32_t j) {
    return reinterpret_cast<const GridLinks*>(links + (std::size_t{j} << links_shift))->next;
  }
  bool OwnsLinks() const { return links_ == reinterpret_cast<const char*>(own_links_.data()); }
  void UseOwnLinks() { UseLinks(own_links_.data(), StrideShiftOf<GridLinks>(), own_links_.size()); }
  BigVector<GridLinks> own_links_;
  char* links_ = nullptr;
  unsigned links_shift_ = StrideShiftOf<GridLinks>();
  std::size_t elements_ = 0;
};

// The cell move of every crossing, inline in the crossing handler: as a call, 1.1% of the
// instructions at N = 10^4.
inline void Grid::Link(std::uint32_t e, std::uint32_t cell) {
  GridLinks& links = Links(e);
  links.cell = cell;
  links.next = head_[cell];
  head_[cell] = e;
}

inline void Grid::Remove(std::uint32_t e) {
  GridLinks& links = Links(e);
  SPARSEDYN_ASSERT(links.cell != kNoIndex, "Grid::Remove of an element not in the grid");
  std::uint32_t* at = &head_[links.cell];  // the link that names e
  while (*at != e) {
    SPARSEDYN_ASSERT(*at != kNoIndex, "Grid::Remove: the element is not in its cell's list");
    at = &Links(*at).next;
  }
  *at = links.next;
  links.cell = kNoIndex;
}

inline Grid::Place Grid::Move(std::uint32_t e, int axis, int direction, Vec3& shift) {
  std::array<int, 3> c = Coordinates(Links(e).cell);
  c[axis] += direction;
  shift = Vec3::Zero();
  if (c[axis] < 0) {
    c[axis] += n_[axis];
    shift[axis] = length_[axis];
  } else if (c[axis] >= n_[axis]) {
    c[axis] -= n_[axis];
    shift[axis] = -length_[axis];
  }
  SPARSEDYN_ASSERT(c[axis] >= 0 && c[axis] < n_[axis], "Grid::Move outside a walled grid");
  Remove(e);
  const std::uint32_t cell = Index(c);
  Link(e, cell);
  return {cell, c};
}

}  // namespace sparsedyn
