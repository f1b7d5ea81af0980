// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// The bodies' thrust schedules (App. F.3's rockets): at each of its times a body's own
/// acceleration changes, which is an event of the body's (EventKind::kBodyTimer). Empty until
/// some body has a schedule.
class ThrustSchedules {
 public:
  bool Any() const { return any_; }
  /// The time of body i's next thrust change, or infinity.
  double NextTime(std::uint32_t i) const {
    if (!any_) return kInfinity;
    const Entry& e = of_[i];
    return e.next < e.changes.size() ? e.changes[e.next].time : kInfinity;
  }
  /// Body i's next change, which is due: its thrust; the schedule moves past it.
  Vec3 TakeNext(std::uint32_t i) {
    Entry& e = of_[i];
    return e.changes[e.next++].thrust;
  }

  /// A new body (index `index`) with `changes` (times increasing), of which those before `now`
  /// are past.
  void Append(std::uint32_t index, const std::vector<ThrustChange>& changes) {
    if (!changes.empty() && !any_) {
      any_ = true;
      of_.resize(index);
    }
    if (!any_) return;
    of_.push_back(Entry{changes, 0});
  }
  /// Body i's schedule from now on (a new one replaces what was left).
  void Replace(std::uint32_t i, const std::vector<ThrustChange>& changes, std::size_t count) {
    if (!any_) {
      any_ = true;
      of_.resize(count);
    }
    of_[i] = Entry{changes, 0};
  }

  template <typename PermuteFn>
  void Permute(PermuteFn&& permute) {
    if (any_) permute(of_);
  }
  std::size_t MemoryBytes() const {
    std::size_t bytes = of_.capacity() * sizeof(Entry);
    for (const Entry& e : of_) bytes += e.changes.capacity() * sizeof(ThrustChange);
    return bytes;
  }

 private:
  struct Entry {
    std::vector<ThrustChange> changes;
    std::size_t next = 0;
  };
  bool any_ = false;
  std::vector<Entry> of_;
};

}  // namespace sparsedyn
