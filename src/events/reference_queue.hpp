// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <tuple>

#include "events/heap_queue.hpp"

namespace sparsedyn {

/// The slow, obviously correct twin of the event queues (a sorted set), used by tests to check
/// HeapQueue and CalendarQueue on the same operation streams. Same interface.
class ReferenceQueue {
 public:
  bool Empty() const { return set_.empty(); }
  std::size_t Size() const { return set_.size(); }
  bool Contains(std::uint32_t slot) const { return keys_.count(slot) != 0; }
  QueueTop Top() const {
    const Key& k = *set_.begin();
    return {std::get<0>(k), static_cast<EventKind>(std::get<1>(k)), std::get<2>(k)};
  }
  void Set(std::uint32_t slot, double time, EventKind kind) {
    Erase(slot);
    const Key key{time, static_cast<int>(kind), slot};
    set_.insert(key);
    keys_[slot] = key;
  }
  void Erase(std::uint32_t slot) {
    const auto it = keys_.find(slot);
    if (it == keys_.end()) return;
    set_.erase(it->second);
    keys_.erase(it);
  }
  void Pop() { Erase(std::get<2>(*set_.begin())); }
  void Clear() {
    set_.clear();
    keys_.clear();
  }

 private:
  using Key = std::tuple<double, int, std::uint32_t>;
  std::set<Key> set_;
  std::map<std::uint32_t, Key> keys_;
};

}  // namespace sparsedyn
