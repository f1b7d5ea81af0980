// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "broadphase/cell_crossing.hpp"
#include "sparse/mover.hpp"
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

  template <typename Fn>
  void ForEachNeighbor(std::uint32_t e, Fn&& fn) const {
    const Vec3 length = hi_ - lo_;
    for (const std::uint32_t j : members_) {
      if (j == e) continue;
      if (!periodic_) {
        fn(j, Vec3::Zero());
        continue;
      }
      for (int dz = -1; dz <= 1; ++dz) {
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            fn(j, Vec3(dx * length[0], dy * length[1], dz * length[2]));
          }
        }
      }
    }
  }

  std::size_t MemoryBytes() const {
    return members_.capacity() * sizeof(std::uint32_t) + present_.capacity() / 8;
  }

 private:
  Vec3 lo_ = Vec3::Zero();
  Vec3 hi_ = Vec3::Ones();
  bool periodic_ = false;
  std::vector<std::uint32_t> members_;
  std::vector<bool> present_;
};

}  // namespace sparsedyn
