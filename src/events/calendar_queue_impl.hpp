// SPDX-License-Identifier: MIT
// BasicCalendarQueue's out-of-line members. Included by the translation units that instantiate
// the queue explicitly (calendar_queue.cpp for the plain queue, the world for its elements'
// queue), not by its users.
#pragma once

#include "events/calendar_queue.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

namespace sparsedyn {

template <typename Payload>
BasicCalendarQueue<Payload>::BasicCalendarQueue() : heads_(kMinBuckets, kNoIndex) { SetYear(); }

template <typename Payload>
std::uint32_t BasicCalendarQueue<Payload>::Classify(double time) const {
  // A monotone map of time to a bucket: t1 <= t2 gives q1 <= q2 (IEEE subtraction and
  // multiplication by a positive constant are monotone), so an earlier bucket never holds a
  // later time. NaN q (t and the origin the same infinity) goes to the current bucket, which orders
  // exactly.
  const double q = Key(time);
  if (!(q >= current_end_)) return kNear;
  return ListOf(q);
}

// Inline in Rollover's passes, which call it for every entry.
template <typename Payload>
[[gnu::always_inline]] inline void BasicCalendarQueue<Payload>::Link(std::uint32_t slot,
                                                                     std::uint32_t where) {
  if (where == kNear) {
    NearPush(NodeOf(slot));
    return;
  }
  ListLink(entries_[slot], slot, where);
}

template <typename Payload>
void BasicCalendarQueue<Payload>::Unlink(std::uint32_t slot) {
  Entry& entry = entries_[slot];
  const std::uint32_t where = entry.where;
  entry.where = kAbsent;
  if (where == kNear) {
    NearErase(entry.next);
    return;
  }
  ListUnlink(entry, where);
}

template <typename Payload>
void BasicCalendarQueue<Payload>::SetAnyhow(std::uint32_t slot, double time, EventKind kind) {
  SPARSEDYN_ASSERT(!std::isnan(time), "CalendarQueue::Set: time is NaN");
  if (slot >= entries_.size()) {
    Resize(slot + 1);
  }

  // An empty queue can start its year anywhere: start it at this entry.
  if (size_ == 0) {
    origin_ = time;
    SetCurrent(0);
  }
  const std::uint32_t where = Classify(time);
  const std::uint32_t was = entries_[slot].where;

  // An update that stays in the same bucket needs no move.
  if (was == where) {
    entries_[slot].time = time;
    entries_[slot].kind = kind;
    if (where == kNear) NearUpdate(entries_[slot].next, NodeOf(slot));
    return;
  }

  // A new entry; grow the year when it holds too few buckets for the entries.
  if (was == kAbsent) {
    entries_[slot].time = time;
    entries_[slot].kind = kind;
    ++size_;
    Link(slot, where);
    if (size_ > 2 * heads_.size()) Rebuild();
    return;
  }
  Unlink(slot);
  entries_[slot].time = time;
  entries_[slot].kind = kind;
  Link(slot, where);
  if (near_.empty()) Refill();
}

template <typename Payload>
int BasicCalendarQueue<Payload>::Upcoming(std::uint32_t* out, int count) const {
  // The current bucket's entries after its earliest, in order: the earliest 14 of the list;
  // of a heap, the three levels below the root (14 entries), which hold the next three for
  // certain (the k-th entry after the root is on one of the k levels below it).
  std::array<Node, 14> near;  // not value-initialised: a sixth of the call
  std::size_t taken = 0;
  const std::size_t end = near_heap_ ? std::min<std::size_t>(near_.size(), 15) : near_.size();
  for (std::size_t at = 0; at < end; ++at) {
    if (at == top_) continue;
    // Insertion into the sorted prefix, the latest dropped when it is full (std::sort here
    // draws a false -Warray-bounds).
    if (taken == near.size() && !Less(near_[at], near[taken - 1])) continue;
    std::size_t k = taken < near.size() ? taken++ : taken - 1;
    for (; k > 0 && Less(near_[at], near[k - 1]); --k) near[k] = near[k - 1];
    near[k] = near_[at];
  }
  int written = 0;
  for (std::size_t k = 0; k < taken && written < count; ++k) out[written++] = SlotOf(near[k]);
  // Then the next few buckets' lists, unsorted. The refills fetch their first entries ahead.
  // The link after the last slot taken is not read: beyond the caches it is a wait for nothing
  // (the load holds up retirement even though no one uses it; 2% at N = 10^5).
  const auto buckets = static_cast<std::uint32_t>(heads_.size());
  for (std::uint32_t b = current_ + 1; b < buckets && b <= current_ + 4 && written < count; ++b) {
    for (std::uint32_t slot = heads_[b]; slot != kNoIndex; slot = entries_[slot].next) {
      out[written++] = slot;
      if (written == count) return written;
    }
  }
  return written;
}

template <typename Payload>
void BasicCalendarQueue<Payload>::Erase(std::uint32_t slot) {
  if (!Contains(slot)) return;
  Unlink(slot);
  --size_;
  AfterRemoval();
}

template <typename Payload>
void BasicCalendarQueue<Payload>::Pop() {
  SPARSEDYN_ASSERT(!near_.empty(), "Pop() of an empty queue");
  if (pops_ == 0) first_pop_time_ = near_[top_].time;
  last_pop_time_ = near_[top_].time;
  ++pops_;
  near_sizes_ += near_.size();
  entries_[SlotOf(near_[top_])].where = kAbsent;
  NearErase(top_);
  --size_;

  // Once per window of a year's worth of pops: does the width still fit the event spacing?
  if (pops_ >= heads_.size()) {
    if (near_sizes_ > kMaxNearPerPop * pops_ || scan_cost_ > kMaxScanPerPop * pops_) {
      Rebuild();
      return;
    }
    ResetCounters();
  }
  AfterRemoval();
}

template <typename Payload>
void BasicCalendarQueue<Payload>::AfterRemoval() {
  if (size_ == 0) return;
  if (size_ * 4 < heads_.size() && heads_.size() > kMinBuckets) {
    Rebuild();
  } else if (near_.empty()) {
    Refill();
  }
}

template <typename Payload>
void BasicCalendarQueue<Payload>::Refill() {
  while (near_.empty() && size_ > 0) {
    // The next non-empty bucket of this year becomes the current one.
    const auto count = static_cast<std::uint32_t>(heads_.size());
    std::uint32_t b = current_ + 1;
    while (b < count && heads_[b] == kNoIndex) ++b;
    scan_cost_ += b - current_ - 1;
    if (b == count) {
      Rollover();
      continue;
    }
    SetCurrent(b);

    // The next refills' entries, fetched while this bucket's few entries are handled: a
    // bucket's list is threaded through the slot array in no order of memory, so once the
    // array outgrows the caches each step of that walk is a cache miss (in Upcoming's walk
    // too). Three deep: of the next three non-empty buckets, the first's third entry, the
    // second's second and the third's first, so that the links read on the way are ones that
    // earlier refills fetched (two deep: 2% slower at 10^6). Not for small arrays, where the
    // look-ahead costs instructions and saves nothing.
    if (prefetch_) {
      int found = 0;
      for (std::uint32_t ahead = b + 1; ahead < count && ahead <= b + 12 && found < 3; ++ahead) {
        std::uint32_t slot = heads_[ahead];
        if (slot == kNoIndex) continue;
        for (int step = found; step < 2 && slot != kNoIndex; ++step) slot = entries_[slot].next;
        if (slot != kNoIndex) sparsedyn::Prefetch(&entries_[slot]);
        ++found;
      }
    }

    // Its list becomes the current one (a heap if it is long). Each slot's record in the
    // owner's array is fetched on the way: its event reads it first, and at N = 10^4 (beyond a
    // core's second-level cache here) that read waited for memory in a fifth of the crossings'
    // time, and fetching it here gave +2.3% at 10^4 on a Zen 5 (2026-11-28;
    // docs/lab/measurements.md#twenty-eighth-measurement).
    for (std::uint32_t slot = heads_[b]; slot != kNoIndex;) {
      Entry& entry = entries_[slot];
      const std::uint32_t next = entry.next;
      if (companion_ != nullptr) {
        sparsedyn::Prefetch(companion_ + (std::size_t{slot} << companion_shift_));
      }
      entry.where = kNear;
      entry.next = static_cast<std::uint32_t>(near_.size());
      near_.push_back(NodeOf(slot));
      slot = next;
    }
    heads_[b] = kNoIndex;
    near_heap_ = false;
    if (near_.size() > kListLimit) {
      MakeHeap();
    } else {
      FindTop();
    }
  }

  // Too much scanning for the pops it served (many empty buckets or year ends): the buckets
  // are too narrow. The rebuild costs O(Size()), which this wasted work already paid for.
  if (scan_cost_ > kMaxScanPerPop * std::max<std::uint64_t>(pops_, heads_.size())) Rebuild();
}

template <typename Payload>
void BasicCalendarQueue<Payload>::Rollover() {
  // The year is used up (current bucket and buckets empty): the next year starts at the earliest
  // overflow entry, so a long quiet stretch costs one pass, not one pass per empty year.
  // Every entry is in the overflow list now (a time before the end of the year has a bucket
  // or the current one). When the entries fill at least half of the slot array, two passes over it
  // in slot order replace the walk along the list: each step of the walk waits for a cache
  // miss (at N = 10^6 most of a rollover's time), the passes stream. The order the entries
  // are linked in does not matter: the current bucket finds its earliest itself.
  scan_cost_ += size_;
  if (2 * size_ >= entries_.size()) {
    double earliest = kInfinity;
    for (const Entry& entry : entries_) {
      if (entry.where == kOverflow) earliest = std::min(earliest, entry.time);
    }
    overflow_head_ = kNoIndex;
    origin_ = earliest;
    SetCurrent(0);
    const auto count = static_cast<std::uint32_t>(entries_.size());
    for (std::uint32_t slot = 0; slot < count; ++slot) {
      if (entries_[slot].where == kOverflow) Link(slot, Classify(entries_[slot].time));
    }
    return;
  }
  scratch_.clear();
  double earliest = kInfinity;
  for (std::uint32_t slot = overflow_head_; slot != kNoIndex; slot = entries_[slot].next) {
    scratch_.push_back(slot);
    earliest = std::min(earliest, entries_[slot].time);
  }
  overflow_head_ = kNoIndex;
  origin_ = earliest;
  SetCurrent(0);
  for (const std::uint32_t slot : scratch_) Link(slot, Classify(entries_[slot].time));
}

template <typename Payload>
void BasicCalendarQueue<Payload>::Rebuild() {
  // Gather every entry.
  scratch_.clear();
  for (const Node& node : near_) scratch_.push_back(SlotOf(node));
  near_.clear();
  near_heap_ = false;
  for (std::uint32_t& head : heads_) {
    for (std::uint32_t slot = head; slot != kNoIndex; slot = entries_[slot].next) {
      scratch_.push_back(slot);
    }
    head = kNoIndex;
  }
  for (std::uint32_t slot = overflow_head_; slot != kNoIndex; slot = entries_[slot].next) {
    scratch_.push_back(slot);
  }
  overflow_head_ = kNoIndex;

  // New year: about one bucket per entry, the width from the event spacing, starting at the
  // earliest entry (which therefore lands in the current bucket: the head is always there).
  heads_.assign(std::max(kMinBuckets, std::bit_ceil(size_)), kNoIndex);
  SetYear();
  if (!scratch_.empty()) {
    EstimateWidth();
    double earliest = kInfinity;
    for (const std::uint32_t slot : scratch_) earliest = std::min(earliest, entries_[slot].time);
    origin_ = earliest;
    SetCurrent(0);
    for (const std::uint32_t slot : scratch_) Link(slot, Classify(entries_[slot].time));
  }
  ++rebuilds_;
  ResetCounters();
}

template <typename Payload>
void BasicCalendarQueue<Payload>::EstimateWidth() {
  // What a bucket's width trades off is the time the head advances per pop: the mean
  // spacing of the pops since the last check, when there were enough of them.
  double gap = 0.0;
  if (pops_ >= kMinPopSample) {
    gap = (last_pop_time_ - first_pop_time_) / static_cast<double>(pops_ - 1);
  }

  // Otherwise (a first build, or pops at infinite times) the spacing of the earliest
  // entries; separations over twice their mean are dropped once, as Brown does, so that a
  // sparse tail in the sample does not widen the buckets of a dense head.
  if (!(gap > 0.0 && std::isfinite(gap))) gap = HeadSpacing();

  // Keep the old width when the spacing is zero or not representable.
  const double width = kWidthFactor * gap;
  if (width > 0.0 && std::isfinite(width) && std::isfinite(1.0 / width)) {
    width_ = width;
    inverse_width_ = 1.0 / width;
  }
}

template <typename Payload>
double BasicCalendarQueue<Payload>::HeadSpacing() {
  sample_.clear();
  for (const std::uint32_t slot : scratch_) {
    if (std::isfinite(entries_[slot].time)) sample_.push_back(entries_[slot].time);
  }
  if (sample_.size() < 2) return 0.0;

  // The earliest k + 1 finite times, sorted.
  const std::size_t k = std::min(sample_.size() - 1, kHeadSample);
  const auto head_end = sample_.begin() + static_cast<std::ptrdiff_t>(k + 1);
  std::nth_element(sample_.begin(), head_end - 1, sample_.end());
  std::sort(sample_.begin(), head_end);
  const double mean = (sample_[k] - sample_[0]) / static_cast<double>(k);
  if (!(mean > 0.0)) {
    // All equal at the head: the mean spacing of all of them instead.
    const double last = *std::max_element(sample_.begin(), sample_.end());
    return (last - sample_[0]) / static_cast<double>(sample_.size() - 1);
  }
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < k; ++i) {
    const double separation = sample_[i + 1] - sample_[i];
    if (separation <= 2.0 * mean) {
      sum += separation;
      ++count;
    }
  }
  return sum > 0.0 ? sum / static_cast<double>(count) : mean;
}

template <typename Payload>
void BasicCalendarQueue<Payload>::ResetCounters() {
  pops_ = 0;
  scan_cost_ = 0;
  near_sizes_ = 0;
}

template <typename Payload>
void BasicCalendarQueue<Payload>::Clear() {
  // The slots and their payloads stay: only the entries go.
  for (Entry& entry : entries_) entry.where = kAbsent;
  near_.clear();
  near_heap_ = false;
  top_ = 0;
  heads_.assign(kMinBuckets, kNoIndex);
  SetYear();
  overflow_head_ = kNoIndex;
  size_ = 0;
  origin_ = 0.0;
  width_ = 1.0;
  inverse_width_ = 1.0;
  SetCurrent(0);
  rebuilds_ = 0;
  ResetCounters();
}

template <typename Payload>
std::size_t BasicCalendarQueue<Payload>::MemoryBytes() const {
  return entries_.capacity() * sizeof(Entry) + near_.capacity() * sizeof(Node) +
         (heads_.capacity() + scratch_.capacity()) * sizeof(std::uint32_t) +
         sample_.capacity() * sizeof(double);
}

// --- The current bucket: an unsorted list, or beyond kListLimit an indexed binary heap ------

template <typename Payload>
void BasicCalendarQueue<Payload>::MakeHeap() {
  // Floyd's bottom-up heap construction; the heap stays until the bucket is used up.
  near_heap_ = true;
  top_ = 0;
  for (auto i = static_cast<std::uint32_t>(near_.size() / 2); i-- > 0;) NearSiftDown(i);
}

template <typename Payload>
void BasicCalendarQueue<Payload>::NearPush(const Node& node) {
  const auto at = static_cast<std::uint32_t>(near_.size());
  near_.push_back(node);
  Entry& entry = entries_[SlotOf(node)];
  entry.where = kNear;
  entry.next = at;
  if (near_heap_) {
    NearSiftUp(at);
  } else if (near_.size() > kListLimit) {
    MakeHeap();
  } else {
    top_ = at == 0 || Less(node, near_[top_]) ? at : top_;
  }
}

template <typename Payload>
void BasicCalendarQueue<Payload>::NearErase(std::uint32_t at) {
  if (!near_heap_) {
    ListErase(at);
    return;
  }
  const Node last = near_.back();
  near_.pop_back();
  const auto size = static_cast<std::uint32_t>(near_.size());
  if (at == size) return;
  NearPlace(at, last);
  if (at > 0 && Less(last, near_[(at - 1) / 2])) {
    NearSiftUp(at);
  } else {
    NearSiftDown(at);
  }
}

template <typename Payload>
void BasicCalendarQueue<Payload>::NearUpdate(std::uint32_t at, const Node& node) {
  const bool earlier = Less(node, near_[at]);
  near_[at] = node;
  if (!near_heap_) {
    if (Less(node, near_[top_])) {
      top_ = at;
    } else if (top_ == at && !earlier) {
      FindTop();
    }
    return;
  }
  if (earlier) {
    NearSiftUp(at);
  } else {
    NearSiftDown(at);
  }
}

template <typename Payload>
void BasicCalendarQueue<Payload>::NearSiftUp(std::uint32_t at) {
  const Node node = near_[at];
  while (at > 0) {
    const std::uint32_t parent = (at - 1) / 2;
    if (!Less(node, near_[parent])) break;
    NearPlace(at, near_[parent]);
    at = parent;
  }
  NearPlace(at, node);
}

template <typename Payload>
void BasicCalendarQueue<Payload>::NearSiftDown(std::uint32_t at) {
  const Node node = near_[at];
  const auto size = static_cast<std::uint32_t>(near_.size());
  while (true) {
    std::uint32_t child = 2 * at + 1;
    if (child >= size) break;
    if (child + 1 < size && Less(near_[child + 1], near_[child])) ++child;
    if (!Less(near_[child], node)) break;
    NearPlace(at, near_[child]);
    at = child;
  }
  NearPlace(at, node);
}

}  // namespace sparsedyn
