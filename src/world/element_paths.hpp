// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

#include "base/huge_pages.hpp"
#include "broadphase/grid.hpp"
#include "motion/path.hpp"
#include "sparsedyn/types.hpp"
#include "world/accelerations.hpp"
#include "world/drag_motions.hpp"

namespace sparsedyn {

/// Where every element's path starts and how it accelerates, and the clock the World's "now"
/// reads (a body's state now is its path evaluated there).
class ElementPaths {
 public:
  /// A body's path start and its place in the grid's cell lists in one aligned cache line: a
  /// scan reads a neighbour's start and its list successor together, and an event's element its
  /// start and cell.
  struct alignas(64) Record : PathStart {
    GridLinks links;
  };
  static_assert(sizeof(Record) == 64, "one cache line per element");

  explicit ElementPaths(const Vec3& gravity) : accelerations_(gravity) {}

  std::uint32_t Size() const { return static_cast<std::uint32_t>(records_.size()); }
  double Now() const { return now_; }
  void SetNow(double t) { now_ = t; }
  /// Whether every element moves on a straight line without envelope (as the World's start
  /// decided): the fast forms below and in the sparse phase.
  bool StraightLines() const { return straight_lines_; }
  void SetStraightLines(bool straight) { straight_lines_ = straight; }

  const PathStart& Start(std::uint32_t i) const { return records_[i]; }
  void SetStart(std::uint32_t i, const PathStart& start) {
    static_cast<PathStart&>(records_[i]) = start;
  }
  /// Moves body i's path by `shift` (a periodic wrap: the same motion, seen in the box).
  void ShiftStart(std::uint32_t i, const Vec3& shift) {
    records_[i].p0 += shift;
    if (drags_.Has(i)) drags_.Shift(i, shift);
  }
  /// The records themselves (the grid keeps its links there; memory order permutes them).
  BigVector<Record>& Records() { return records_; }
  const BigVector<Record>& Records() const { return records_; }

  /// Body i's element path: its exact motion, or for a body with drag the Taylor path its
  /// element follows (within its envelope of the true motion, TruePositionAt).
  Path PathOf(std::uint32_t i) const {
    const PathStart& s = records_[i];
    return Path{s.p0, s.v0, drags_.Has(i) ? drags_.PathAcceleration(i) : accelerations_.Of(i),
                s.t0};
  }
  /// Body i's true position and velocity at t (in its current segment): its path, or for a body
  /// with drag its DragMotion (docs/dynamics.md, "Drag in the World").
  Vec3 TruePositionAt(std::uint32_t i, double t) const {
    return drags_.Has(i) ? drags_.StateAt(i, t).position : PathOf(i).PositionAt(t);
  }
  Vec3 TrueVelocityAt(std::uint32_t i, double t) const {
    return drags_.Has(i) ? drags_.StateAt(i, t).velocity : PathOf(i).VelocityAt(t);
  }
  // Body i's position and velocity now. On straight lines without the zero acceleration's terms
  // (the same numbers up to the sign of a zero) and without building its Path: a collision of a
  // gas asks for them six times.
  Vec3 PositionNow(std::uint32_t i) const {
    const PathStart& s = records_[i];
    return straight_lines_ ? Vec3(s.p0 + (now_ - s.t0) * s.v0) : TruePositionAt(i, now_);
  }
  Vec3 VelocityNow(std::uint32_t i) const {
    return straight_lines_ ? records_[i].v0 : TrueVelocityAt(i, now_);
  }

  /// Body i's new drag segment from its path start (the true state there, just set): a new
  /// DragMotion under its acceleration (gravity plus thrust, held components zero) and the
  /// Taylor path its element follows; returns the element's envelope. Body i has drag.
  Envelope StartDrag(std::uint32_t i) {
    PathStart& s = records_[i];
    const TaylorSegment segment = drags_.Start(i, s.t0, s.p0, s.v0, accelerations_.Of(i));
    s.p0 = segment.path.p0;
    s.v0 = segment.path.v0;
    return segment.envelope;
  }

  DragMotions& drags() { return drags_; }
  const DragMotions& drags() const { return drags_; }
  Accelerations& accelerations() { return accelerations_; }
  const Accelerations& accelerations() const { return accelerations_; }

  /// A new element: its path starts at `start` with the free acceleration `a`.
  void Append(const PathStart& start, const Vec3& a) {
    accelerations_.Append(Size(), a);
    records_.push_back(Record{start, GridLinks{}});
  }

  std::size_t MemoryBytes() const {
    return records_.capacity() * sizeof(Record) + accelerations_.MemoryBytes() +
           drags_.MemoryBytes();
  }

 private:
  double now_ = 0.0;
  bool straight_lines_ = false;
  BigVector<Record> records_;
  Accelerations accelerations_;
  DragMotions drags_;
};

}  // namespace sparsedyn
