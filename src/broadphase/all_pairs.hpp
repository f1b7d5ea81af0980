// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "broadphase/cell_crossing.hpp"
#include "sparse/mover.hpp"
#include "sparsedyn/assert.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// The thesis's broad phase (§4): an actor is compared with every other element, O(N) per
/// prediction. Also the slow, obviously correct twin of Grid. In a periodic box each element is
/// kept inside the box by "wrap" events (reported as cell crossings) and compared with the 27
/// images of every other element: while both stay in the box their separation per axis is
/// below one box length, so any meeting is with one of those images.
class AllPairs {
 public:
  struct Config {
    Vec3 lo = Vec3::Zero();
    Vec3 hi = Vec3::Ones();
    bool periodic = false;
  };

  AllPairs() = default;
  AllPairs(const Config& config, std::uint32_t element_capacity)
      : lo_(config.lo), hi_(config.hi), periodic_(config.periodic) {
    present_.reserve(element_capacity);
    const Vec3 length = hi_ - lo_;
    shifts_.reserve(periodic_ ? 27 : 1);
    if (!periodic_) {
      shifts_.push_back(Vec3::Zero());
      return;
    }
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          shifts_.emplace_back(dx * length[0], dy * length[1], dz * length[2]);
        }
      }
    }
  }

  void Insert(std::uint32_t e, const Vec3& /*p*/) {
    if (e >= present_.size()) present_.resize(e + 1, false);
    if (!present_[e]) members_.push_back(e);
    present_[e] = true;
  }

  /// dt until the centre leaves the periodic box (a wrap); never in other containers.
  double PredictCrossing(const Mover& m, std::uint32_t /*cell*/, double min_dt, int& axis,
                         int& direction) const {
    axis = 0;
    direction = 1;
    if (!periodic_) return kInfinity;
    double best = kInfinity;
    for (int k = 0; k < 3; ++k) {
      int dir = 1;
      const double dt = SlabExitTime(m.p[k], m.v[k], m.a[k], lo_[k], hi_[k], min_dt, dir);
      if (dt < best) {
        best = dt;
        axis = k;
        direction = dir;
      }
    }
    return best;
  }
  std::uint32_t CellOf(std::uint32_t /*e*/) const { return 0; }

  /// The position shift that wraps the element back into the box.
  Vec3 Move(std::uint32_t /*e*/, int axis, int direction) const {
    Vec3 shift = Vec3::Zero();
    shift[axis] = -direction * (hi_[axis] - lo_[axis]);
    return shift;
  }

  /// Calls fn(j, shift_j) for every element j != e and each of its images (ImageShifts()).
  template <typename Fn>
  void ForEachNeighbor(std::uint32_t e, Fn&& fn) const {
    for (const std::uint32_t j : members_) {
      if (j == e) continue;
      for (const Vec3& shift : shifts_) fn(j, shift);
    }
  }
  /// Calls fn(j) for every element j != e: ForEachNeighbor with the images left to the caller.
  template <typename Fn>
  void ForEachOther(std::uint32_t e, Fn&& fn) const {
    for (const std::uint32_t j : members_) {
      if (j != e) fn(j);
    }
  }
  /// The offsets of the images every neighbour is seen at: the 27 of a periodic box (x fastest,
  /// from -1 to +1 box lengths), else zero alone.
  const std::vector<Vec3>& ImageShifts() const { return shifts_; }
  /// The shift of each step s = 0, 1, 2 (-L, 0, +L) along every axis, as ImageShifts() has
  /// them: image r = sx + 3 sy + 9 sz shifts by StepShifts()[sk][k] along axis k. Periodic only.
  std::array<Vec3, 3> StepShifts() const {
    SPARSEDYN_ASSERT(shifts_.size() == 27, "StepShifts() of a box without images");
    return {shifts_[0], shifts_[13], shifts_[26]};
  }
  /// The largest magnitude of ImageShifts() per axis: the box's lengths if periodic, else 0.
  Vec3 LargestShift() const { return periodic_ ? Vec3(hi_ - lo_) : Vec3::Zero(); }
  /// The index in ImageShifts() of the image nearest along every axis to an element at offset
  /// `d` from the one looking (both in the box, so |d_k| < one length).
  std::size_t NearestImage(const Vec3& d) const {
    if (!periodic_) return 0;
    std::size_t index = 0;
    std::size_t weight = 1;
    for (int k = 0; k < 3; ++k) {
      const double half = 0.5 * (hi_[k] - lo_[k]);
      const std::size_t step = d[k] > half ? 0 : d[k] < -half ? 2 : 1;  // -L, 0 or +L
      index += step * weight;
      weight *= 3;
    }
    return index;
  }

  std::size_t MemoryBytes() const {
    return members_.capacity() * sizeof(std::uint32_t) + present_.capacity() / 8 +
           shifts_.capacity() * sizeof(Vec3);
  }

 private:
  Vec3 lo_ = Vec3::Zero();
  Vec3 hi_ = Vec3::Ones();
  bool periodic_ = false;
  std::vector<std::uint32_t> members_;
  std::vector<bool> present_;
  std::vector<Vec3> shifts_;  // ImageShifts()
};

}  // namespace sparsedyn
