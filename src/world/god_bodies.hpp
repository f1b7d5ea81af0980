// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "dynamics/god_plan.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// The god objects (App. H.3, issue #36 part 7): elements driven along a plan of
/// constant-acceleration pieces (GodPlan), of infinite mass to every other body. Each piece
/// switch is an event of the body's (EventKind::kBodyTimer); between switches its path is the
/// piece, exact, so it needs no envelope. Empty until some body is a god object.
class GodBodies {
 public:
  bool Any() const { return any_; }
  /// A god object: what it was given (its maximum acceleration and track) and its plan.
  struct God {
    GodDef def;
    GodPlan plan;
    /// The piece of the plan the body's path follows (its acceleration).
    std::size_t piece = 0;
    /// The targets of def.track not reached by `now` (those the plan arrives at later).
    GodDef Remaining(double now) const;
    /// The path takes up the plan's piece at `now`.
    const GodPiece& Follow(double now) {
      const GodPiece& at = plan.PieceAt(now);
      piece = static_cast<std::size_t>(&at - plan.pieces().data());
      return at;
    }
  };

  bool IsGod(std::uint32_t i) const { return any_ && of_[i].has_value(); }
  const God& Of(std::uint32_t i) const { return *of_[i]; }
  const GodPlan& PlanOf(std::uint32_t i) const { return of_[i]->plan; }
  /// When god i's path takes up the piece after the one it follows, or infinity (not a god,
  /// or on its final piece). Counted from the piece followed, not from the clock, so that a
  /// switch that ties with another of the body's events (a cell crossing at the same instant)
  /// is still taken.
  double NextSwitch(std::uint32_t i) const {
    if (!IsGod(i)) return kInfinity;
    const God& god = *of_[i];
    const std::vector<GodPiece>& pieces = god.plan.pieces();
    return god.piece + 1 < pieces.size() ? pieces[god.piece + 1].t0 : kInfinity;
  }
  /// God i's path takes up its plan's piece at `now`: the plan's state then.
  GodState Follow(std::uint32_t i, double now) {
    of_[i]->Follow(now);
    return of_[i]->plan.StateAt(now);
  }

  /// A new element (index `index`), a god object when `god` is given.
  void Append(std::uint32_t index, std::optional<God> god) {
    if (god && !any_) {
      any_ = true;
      of_.resize(index);
    }
    if (any_) of_.push_back(std::move(god));
  }
  /// God i's track and plan from now on (a new track, or a teleport).
  void Replace(std::uint32_t i, God god) { of_[i] = std::move(god); }

  template <typename PermuteFn>
  void Permute(PermuteFn&& permute) {
    if (any_) permute(of_);
  }
  std::size_t MemoryBytes() const {
    std::size_t bytes = of_.capacity() * sizeof(std::optional<God>);
    for (const std::optional<God>& god : of_) {
      if (god) {
        bytes += god->plan.pieces().capacity() * sizeof(GodPiece) +
                 god->def.track.capacity() * sizeof(GodTarget);
      }
    }
    return bytes;
  }

 private:
  bool any_ = false;
  std::vector<std::optional<God>> of_;
};

inline GodDef GodBodies::God::Remaining(double now) const {
  GodDef left{def.max_acceleration, {}};
  const std::vector<double>& arrivals = plan.arrival_times();
  for (std::size_t k = 0; k < def.track.size(); ++k) {
    if (arrivals[k] > now) left.track.push_back(def.track[k]);
  }
  return left;
}

}  // namespace sparsedyn
