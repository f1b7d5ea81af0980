// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "sparsedyn/types.hpp"
#include "world/static_bodies.hpp"

namespace sparsedyn {

/// Which element holds which body. A body's public handle is a slot (BodyId::index) and the
/// slot's generation: a removed body's slot may hold a new body later, under a new generation,
/// so that the old handle is refused rather than silently taken for the new body. Internal
/// (element) indices follow space (the World's memory order renumbers them).
class BodyIds {
 public:
  /// The slot a new body, element `element`, takes: a freed one (the last freed first), else a
  /// new one.
  BodyId Add(std::uint32_t element) {
    const BodyId id = TakeSlot(element);
    if (element >= public_of_.size()) public_of_.resize(element + 1);
    public_of_[element] = id.index;
    return id;
  }
  /// The slot a new static body takes; it holds the static's key (StaticBodies::KeyOf).
  BodyId AddStatic(std::uint32_t key) { return TakeSlot(key); }
  /// Whether `slot` holds a static body (its InternalOf is then the static's key).
  bool IsStaticSlot(std::uint32_t slot) const {
    return StaticBodies::IsKey(slots_[slot].element) && slots_[slot].element != kNoIndex;
  }

 private:
  BodyId TakeSlot(std::uint32_t body) {
    std::uint32_t slot;
    if (!free_.empty()) {
      slot = free_.back();
      free_.pop_back();
    } else {
      slot = static_cast<std::uint32_t>(slots_.size());
      slots_.push_back(Slot{});
    }
    slots_[slot].element = body;
    return BodyId{slot, slots_[slot].generation};
  }

 public:
  /// The body in `slot` is removed (its element goes away with Permute).
  void Remove(std::uint32_t slot) {
    slots_[slot].element = kNoIndex;
    ++slots_[slot].generation;
    free_.push_back(slot);
  }

  /// Whether `id` names a body the World holds now.
  bool Valid(BodyId id) const {
    return id.index < slots_.size() && slots_[id.index].element != kNoIndex &&
           slots_[id.index].generation == id.generation;
  }
  std::uint32_t PublicOf(std::uint32_t element) const { return public_of_[element]; }
  std::uint32_t InternalOf(std::uint32_t slot) const { return slots_[slot].element; }
  BodyId IdOf(std::uint32_t element) const {
    const std::uint32_t slot = public_of_[element];
    return BodyId{slot, slots_[slot].generation};
  }
  /// The handle of the body in `slot`, or an invalid one for an empty slot.
  BodyId IdOfSlot(std::uint32_t slot) const {
    if (slot >= slots_.size() || slots_[slot].element == kNoIndex) return BodyId{};
    return BodyId{slot, slots_[slot].generation};
  }
  std::uint32_t SlotCount() const { return static_cast<std::uint32_t>(slots_.size()); }
  /// The elements in slot order (sums over bodies in this order do not depend on the memory
  /// order).
  std::vector<std::uint32_t> InPublicOrder() const {
    std::vector<std::uint32_t> elements;
    elements.reserve(public_of_.size());
    for (const Slot& slot : slots_) {
      if (slot.element != kNoIndex && !StaticBodies::IsKey(slot.element)) {
        elements.push_back(slot.element);
      }
    }
    return elements;
  }

  /// The elements were renumbered (or some removed): new element e is old element
  /// old_of_new[e]; `permute` reorders a per-element vector that way.
  template <typename PermuteFn>
  void Permute(PermuteFn&& permute) {
    permute(public_of_);
    for (std::uint32_t e = 0; e < public_of_.size(); ++e) slots_[public_of_[e]].element = e;
  }

  std::size_t MemoryBytes() const {
    return public_of_.capacity() * sizeof(std::uint32_t) + slots_.capacity() * sizeof(Slot) +
           free_.capacity() * sizeof(std::uint32_t);
  }

 private:
  struct Slot {
    std::uint32_t element = kNoIndex;  // kNoIndex: empty
    std::uint32_t generation = 0;
  };
  std::vector<std::uint32_t> public_of_;  // element -> slot
  std::vector<Slot> slots_;               // slot -> element and generation
  std::vector<std::uint32_t> free_;       // empty slots
};

}  // namespace sparsedyn
