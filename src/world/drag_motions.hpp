// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "math/event_time.hpp"
#include "sparsedyn/assert.hpp"
#include "motion/drag_motion.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// The envelope a body with drag may grow to over one segment, as a fraction of its radius: its
/// element sphere stays within (1 + kDragErrorFraction) r, so the grid's cells only grow by
/// that much. Larger means fewer check events (the horizon grows like the cube root of it) and
/// more element meetings that come to nothing; 0.1 of the radius measured best for the gas with
/// drag (bench/scenes/drag_bench.cpp, docs/benchmarks.md).
inline constexpr double kDragErrorFraction = 0.1;

/// The true motions of the bodies with drag (App. H.2, docs/dynamics.md "Drag in the World"):
/// each such body's DragMotion since its last event, the acceleration of the Taylor path its
/// element follows meanwhile, and the time of its next check (the end of the horizon over which
/// the element's envelope holds the true motion). Empty until some body has drag.
class DragMotions {
 public:
  /// Whether some body has drag.
  bool Any() const { return any_; }
  /// Whether body i has drag.
  bool Has(std::uint32_t i) const { return any_ && !entries_[i].drag.IsZero(); }
  /// Body i's drag coefficients (zero for a body without).
  Drag DragOf(std::uint32_t i) const { return any_ ? entries_[i].drag : Drag{}; }

  /// Body i's true state at t (>= its segment's start): the DragMotion's, moved by the periodic
  /// wraps since the segment began. Body i has drag.
  DragState StateAt(std::uint32_t i, double t) const {
    const Entry& e = entries_[i];
    DragState state = e.motion->StateAt(t);
    state.position += e.shift;
    return state;
  }
  /// The Taylor segment of body i's true motion about t with an envelope of at most
  /// `max_error` (m) over its horizon (at most `max_horizon`), in the box's coordinates.
  TaylorSegment LocalSegment(std::uint32_t i, double t, double max_error,
                             double max_horizon) const {
    const Entry& e = entries_[i];
    TaylorSegment segment = e.motion->SegmentFor(t, max_error, max_horizon);
    segment.path.p0 += e.shift;
    return segment;
  }
  /// The acceleration of body i's element path (its Taylor path) in the current segment.
  const Vec3& PathAcceleration(std::uint32_t i) const { return entries_[i].path_a; }
  /// A bound on |acceleration| of body i's true motion from its segment's start on.
  double AccelerationBound(std::uint32_t i) const {
    return entries_[i].motion->AccelerationBound();
  }
  /// The time of body i's next check event (infinity: none, or no drag).
  double CheckTime(std::uint32_t i) const { return any_ ? entries_[i].check_time : kInfinity; }
  /// The envelope body i's segments may grow to, m.
  double MaxError(std::uint32_t i) const { return entries_[i].max_error; }

  /// A new body (index `index`) with `drag` (zero: none) and envelope limit `max_error`.
  void Append(std::uint32_t index, const Drag& drag, double max_error) {
    if (!drag.IsZero() && !any_) {
      any_ = true;
      entries_.resize(index);
    }
    if (!any_) return;
    Entry entry;
    entry.drag = drag;
    entry.max_error = max_error;
    entries_.push_back(std::move(entry));
  }
  /// Body i's new segment at t from position p and velocity v under the constant acceleration
  /// g (gravity plus thrust, held components zero): a new DragMotion and the Taylor segment its
  /// element follows until the check at the end of the horizon. Body i has drag.
  TaylorSegment Start(std::uint32_t i, double t, const Vec3& p, const Vec3& v, const Vec3& g) {
    Entry& e = entries_[i];
    e.motion.emplace(t, p, v, g, e.drag);
    e.shift = Vec3::Zero();
    const TaylorSegment segment = e.motion->SegmentFor(t, e.max_error);
    SPARSEDYN_ASSERT(segment.horizon > 0.0, "a drag segment's state is not known to max_error");
    e.path_a = segment.path.a;
    e.check_time = segment.horizon == kInfinity ? kInfinity : EventTime(t, segment.horizon);
    return segment;
  }
  /// A periodic wrap of body i: the same motion, seen moved by `shift`.
  void Shift(std::uint32_t i, const Vec3& shift) { entries_[i].shift += shift; }

  template <typename PermuteFn>
  void Permute(PermuteFn&& permute) {
    if (any_) permute(entries_);
  }
  std::size_t MemoryBytes() const { return entries_.capacity() * sizeof(Entry); }

 private:
  struct Entry {
    std::optional<DragMotion> motion;  // engaged for a body with drag (AddBody starts it)
    Vec3 shift = Vec3::Zero();         // the periodic wraps since the motion began
    Vec3 path_a = Vec3::Zero();        // the Taylor path's acceleration
    double check_time = kInfinity;
    double max_error = 0.0;
    Drag drag;
  };
  bool any_ = false;
  std::vector<Entry> entries_;
};

}  // namespace sparsedyn
