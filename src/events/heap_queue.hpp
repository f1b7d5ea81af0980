// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "events/event.hpp"
#include "sparsedyn/assert.hpp"

namespace sparsedyn {

/// The head of an event queue: the earliest (time, kind, slot).
struct QueueTop {
  double time;
  EventKind kind;
  std::uint32_t slot;
};

/// An indexed d-ary min-heap of slots (an element or an engagement each own one slot) keyed by
/// (time, kind, slot): at most one entry per slot, updated in place. Replacing a slot's entry is
/// how a superseded prediction leaves the queue (the "actor-absent" events of §4.2 never reach
/// the head). Ties are broken by kind then slot, which makes runs deterministic.
template <int kArity>
class HeapQueue {
 public:
  bool Empty() const { return heap_.empty(); }
  std::size_t Size() const { return heap_.size(); }
  bool Contains(std::uint32_t slot) const {
    return slot < position_.size() && position_[slot] != kNoIndex;
  }

  QueueTop Top() const {
    SPARSEDYN_ASSERT(!heap_.empty(), "Top() of an empty queue");
    return {heap_[0].time, static_cast<EventKind>(heap_[0].order >> 32),
            static_cast<std::uint32_t>(heap_[0].order)};
  }

  /// Inserts the slot or moves its entry to the new key.
  void Set(std::uint32_t slot, double time, EventKind kind) {
    if (slot >= position_.size()) position_.resize(slot + 1, kNoIndex);
    const Node node{time, (static_cast<std::uint64_t>(kind) << 32) | slot};
    std::uint32_t at = position_[slot];
    if (at == kNoIndex) {
      at = static_cast<std::uint32_t>(heap_.size());
      heap_.push_back(node);
      SiftUp(at);
      return;
    }
    const bool earlier = Less(node, heap_[at]);
    heap_[at] = node;
    if (earlier) {
      SiftUp(at);
    } else {
      SiftDown(at);
    }
  }

  /// Removes the slot's entry if it has one.
  void Erase(std::uint32_t slot) {
    if (!Contains(slot)) return;
    const std::uint32_t at = position_[slot];
    position_[slot] = kNoIndex;
    const Node last = heap_.back();
    heap_.pop_back();
    if (at == heap_.size()) return;
    heap_[at] = last;
    position_[static_cast<std::uint32_t>(last.order)] = at;
    if (at > 0 && Less(last, heap_[(at - 1) / kArity])) {
      SiftUp(at);
    } else {
      SiftDown(at);
    }
  }

  void Pop() { Erase(static_cast<std::uint32_t>(heap_[0].order)); }

  void Clear() {
    heap_.clear();
    position_.clear();
  }

  /// Bytes held, for the memory-per-body figure.
  std::size_t MemoryBytes() const {
    return heap_.capacity() * sizeof(Node) + position_.capacity() * sizeof(std::uint32_t);
  }

 private:
  struct Node {
    double time;
    std::uint64_t order;  // kind << 32 | slot: the deterministic tie-break
  };

  static bool Less(const Node& a, const Node& b) {
    return a.time < b.time || (a.time == b.time && a.order < b.order);
  }

  void Place(std::uint32_t at, const Node& node) {
    heap_[at] = node;
    position_[static_cast<std::uint32_t>(node.order)] = at;
  }

  void SiftUp(std::uint32_t at) {
    const Node node = heap_[at];
    while (at > 0) {
      const std::uint32_t parent = (at - 1) / kArity;
      if (!Less(node, heap_[parent])) break;
      Place(at, heap_[parent]);
      at = parent;
    }
    Place(at, node);
  }

  void SiftDown(std::uint32_t at) {
    const Node node = heap_[at];
    const auto size = static_cast<std::uint32_t>(heap_.size());
    while (true) {
      const std::uint32_t first = at * kArity + 1;
      if (first >= size) break;
      std::uint32_t best = first;
      const std::uint32_t end = first + kArity < size ? first + kArity : size;
      for (std::uint32_t c = first + 1; c < end; ++c) {
        if (Less(heap_[c], heap_[best])) best = c;
      }
      if (!Less(heap_[best], node)) break;
      Place(at, heap_[best]);
      at = best;
    }
    Place(at, node);
  }

  std::vector<Node> heap_;
  std::vector<std::uint32_t> position_;  // slot -> index in heap_, kNoIndex if absent
};

}  // namespace sparsedyn
