// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "events/event.hpp"
#include "events/heap_queue.hpp"
#include "math/branchless.hpp"
#include "base/huge_pages.hpp"
#include "base/prefetch.hpp"
#include "sparsedyn/assert.hpp"

namespace sparsedyn {

/// An indexed calendar queue of slots keyed by (time, kind, slot), a drop-in replacement for
/// HeapQueue: the same interface, one entry per slot, and the same total order, so a World
/// processes the same events in the same order with either.
///
/// Structure (R. Brown, "Calendar queues", CACM 31(10), 1988; the bounded priority queue of
/// DynamO, Bannerman et al. 2011, which keeps only near-future events sorted):
/// - a *year* of `BucketCount()` buckets of width `BucketWidth()` starting at an origin time;
///   an entry with t in [origin + b w, origin + (b + 1) w) lives in bucket b, an unsorted
///   intrusive list threaded through a per-slot array (no allocation per bucket), so inserting,
///   erasing or moving it is O(1);
/// - the *current* bucket (`near`) also takes every entry at or before it, including times
///   earlier than the head. It holds a few entries (about 2.5 by the width rule below), so it
///   is an unsorted list whose earliest entry is found by a scan without branches (a heap's
///   sifts branch on comparisons of random times, which the processor guesses wrong every
///   other time); beyond kListLimit entries (equal times, a burst) it becomes an indexed binary
///   heap until it is used up;
/// - entries beyond the year wait unsorted in an overflow list; when the year is used up the
///   origin moves to the earliest of them and they are re-bucketed.
/// Because the bucket of a time is a monotone function of the time, every entry of the current
/// bucket precedes every entry in a later bucket, so its earliest is the queue's head; ties of
/// equal times always share a bucket and are ordered by (kind, slot) there.
///
/// Resizing rule (amortised O(1) per operation): the queue is rebuilt with a bucket count of
/// the next power of two >= Size() when Size() exceeds twice the bucket count or drops below a
/// quarter of it; and when, over a window of at least BucketCount() pops, the average pop
/// either scanned more than 4 empty buckets (width too small) or found more than 24 entries in
/// the current bucket (width too large), i.e. the event spacing drifted. A rebuild sets the
/// width to 2.5 times the mean spacing of the earliest min(Size() - 1, 256) finite times, and
/// the origin to the earliest time.
///
/// Valid for any non-NaN times, +/-infinity and times earlier than the head included.
///
/// Each slot can carry a `Payload`, the user's per-slot record (an element's prediction), kept
/// in the slot's entry: the lines the queue's own walks fetch (the buckets' lists, the
/// look-ahead) then hold what the user reads next, and a slot's entry and record take 1.5
/// lines on average instead of 2.5 in two arrays. A payload lives as long as its slot, with or
/// without an entry; Clear keeps it.
struct NoPayload {};

template <typename Payload>
class BasicCalendarQueue {
 public:
  BasicCalendarQueue();

  /// True if no slot has an entry.
  bool Empty() const { return size_ == 0; }

  /// The number of slots with an entry.
  std::size_t Size() const { return size_; }

  /// True if `slot` has an entry.
  bool Contains(std::uint32_t slot) const {
    return slot < entries_.size() && entries_[slot].where != kAbsent;
  }

  /// The time of `slot`'s entry (which must exist).
  double TimeOf(std::uint32_t slot) const {
    SPARSEDYN_ASSERT(Contains(slot), "TimeOf() a slot without entry");
    return entries_[slot].time;
  }

  /// The earliest entry by (time, kind, slot). The queue must not be empty.
  QueueTop Top() const {
    SPARSEDYN_ASSERT(!near_.empty(), "Top() of an empty queue");
    const Node& top = near_[top_];
    return {top.time, static_cast<EventKind>(top.order >> 32),
            static_cast<std::uint32_t>(top.order)};
  }

  /// Up to `count` slots likely to be the next heads after the current one, earliest first as
  /// far as the queue knows it cheaply (the current bucket in order, then the next
  /// non-empty buckets' lists in list order); for fetching their data ahead. Not exact: each
  /// event's handling may move entries. Returns how many it wrote.
  int Upcoming(std::uint32_t* out, int count) const;
  /// Fetches `slot`'s entry into the caches ahead of a Set.
  void Prefetch(std::uint32_t slot) const {
    const Entry* entry = &entries_[slot];
    sparsedyn::Prefetch(entry);
    // Its last byte: an entry with a payload spans two cache lines every other time.
    if constexpr (sizeof(Entry) > 32) {
      sparsedyn::Prefetch(reinterpret_cast<const char*>(entry) + sizeof(Entry) - 1);
    }
  }

  /// Has every refill fetch, for each slot whose entry it moves into the current bucket, that
  /// slot's record in an array of the owner's (record s at byte s << stride_shift from `first`;
  /// null: none), an event or two before the slot's event is handled. The owner calls this
  /// again whenever the array moves. Fetches only: any address is harmless.
  void FetchWithRefills(const void* first, unsigned stride_shift) {
    companion_ = static_cast<const char*>(first);
    companion_shift_ = stride_shift;
  }

  /// Fetches the head of the bucket an entry at `time` would join into the caches, ahead of a
  /// Set (nothing for the current bucket or beyond the year).
  void PrefetchListOf(double time) const {
    const double q = Key(time);
    if (q >= current_end_ && q < year_end_) {
      sparsedyn::Prefetch(&heads_[static_cast<std::uint32_t>(q)]);
    }
  }

  /// Inserts the slot or moves its entry to the new key. `time` must not be NaN. (Always
  /// inline: GCC made it a call from the World's prediction, 1.3% of its instructions.)
  [[gnu::always_inline]] void Set(std::uint32_t slot, double time, EventKind kind) {
    if (MoveHeadToBucket(slot, time, kind)) return;
    if (MoveListedToBucket(slot, time, kind)) return;
    SetAnyhow(slot, time, kind);
  }

  /// Removes the slot's entry if it has one.
  void Erase(std::uint32_t slot);

  /// Removes the head entry. The queue must not be empty.
  void Pop();

  /// Removes every entry and returns to the initial bucket layout. The slots and their
  /// payloads stay.
  void Clear();

  /// Makes slots 0 .. slots - 1 exist (without entries; new payloads value-initialised). Grows
  /// only: a slot's entry may be linked into a list.
  void Resize(std::size_t slots) {
    SPARSEDYN_ASSERT(slots >= entries_.size(), "CalendarQueue::Resize: slots only grow");
    entries_.resize(slots, Entry{0.0, kNoIndex, kNoIndex, kAbsent, EventKind::kNone, Payload{}});
    prefetch_ = entries_.size() * sizeof(Entry) >= kPrefetchBytes;
  }

  /// Keeps only slots 0 .. slots - 1, with their payloads; the queue must be empty (Clear).
  void Truncate(std::size_t slots) {
    SPARSEDYN_ASSERT(size_ == 0 && slots <= entries_.size(),
                     "CalendarQueue::Truncate: an empty queue, to fewer slots");
    entries_.resize(slots);
    prefetch_ = entries_.size() * sizeof(Entry) >= kPrefetchBytes;
  }

  /// Frees the slot array's room beyond Slots() (a slot array grown one slot at a time holds
  /// up to twice what it needs).
  void ShrinkToFit() { entries_.shrink_to_fit(); }

  /// The number of slots (the highest slot ever set or resized to, plus one).
  std::size_t Slots() const { return entries_.size(); }

  /// The payload of `slot`, which must exist (Slots() > slot).
  Payload& PayloadOf(std::uint32_t slot) { return entries_[slot].payload; }
  const Payload& PayloadOf(std::uint32_t slot) const { return entries_[slot].payload; }

  /// Bytes held, for the memory-per-body figure.
  std::size_t MemoryBytes() const;

  /// The number of buckets in a year (diagnostics and tests).
  std::size_t BucketCount() const { return heads_.size(); }

  /// The time span of one bucket (diagnostics and tests).
  double BucketWidth() const { return width_; }

  /// How many times the buckets were rebuilt (diagnostics and tests).
  std::uint64_t RebuildCount() const { return rebuilds_; }

 private:
  // An entry of the current bucket: the key, with the slot in the low bits of `order`.
  struct Node {
    double time;
    std::uint64_t order;  // kind << 32 | slot: the deterministic tie-break, as in HeapQueue
  };

  // A slot's entry. In a bucket or the overflow list it is a node of an intrusive doubly
  // linked list (no allocation per bucket, O(1) unlink); in the current bucket, `next` is its
  // index in near_.
  struct Entry {
    double time;
    std::uint32_t next;
    std::uint32_t prev;
    std::uint32_t where;  // a bucket index, or kNear, kOverflow, kAbsent
    EventKind kind;
    [[no_unique_address]] Payload payload;
  };
  // The smallest year; below it the bookkeeping costs more than the buckets save.
  static constexpr std::size_t kMinBuckets = 16;

  // Bucket width in units of the mean spacing of the events. Brown suggests about 3; 1.5, 2.5
  // and 4 measured alike within the noise of bench/micro/queue_bench.cpp at N = 2^14 (and 4 was
  // slower at 2^20), see docs/decisions/0002-event-queue.md.
  static constexpr double kWidthFactor = 2.5;

  // How many of the earliest finite times the width estimate looks at: enough to average out
  // the randomness of single spacings, few enough to describe the head rather than the tail.
  static constexpr std::size_t kHeadSample = 256;

  // Fewer pops than this since the last check say too little about the spacing.
  static constexpr std::uint64_t kMinPopSample = 32;

  // Width adaptation thresholds, per pop: more empty buckets scanned (plus entries re-bucketed
  // at a year's end) than kMaxScanPerPop means the buckets are too narrow, more entries in the
  // current bucket than kMaxNearPerPop means they are too wide.
  // Whole numbers: Refill, on every refill, compares in integers.
  static constexpr std::uint64_t kMaxScanPerPop = 4;
  static constexpr std::uint64_t kMaxNearPerPop = 24;

  // From this many bytes of entries on (beyond a core's L2 cache) Refill fetches the next
  // buckets' entries ahead.
  static constexpr std::size_t kPrefetchBytes = std::size_t{3} << 19;

  static constexpr std::uint32_t kAbsent = 0xffffffffu;
  static constexpr std::uint32_t kNear = 0xfffffffeu;
  static constexpr std::uint32_t kOverflow = 0xfffffffdu;

  static bool Less(const Node& a, const Node& b) {
    return a.time < b.time || (a.time == b.time && a.order < b.order);
  }
  static std::uint32_t SlotOf(const Node& node) { return static_cast<std::uint32_t>(node.order); }
  Node NodeOf(std::uint32_t slot) const {
    return {entries_[slot].time, (static_cast<std::uint64_t>(entries_[slot].kind) << 32) | slot};
  }

  // A time's bucket key: buckets are its whole part, from 0 at the origin.
  double Key(double time) const { return (time - origin_) * inverse_width_; }
  std::uint32_t Classify(double time) const;
  // The list of a key at or after the current bucket's end: its bucket, or beyond the year the
  // overflow list. Selects: which one is a coin toss after every event of a gas.
  std::uint32_t ListOf(double q) const {
    const auto bucket = static_cast<std::uint32_t>(MinOf(q, year_end_ - 1.0));  // in range
    const bool beyond = q >= year_end_;
    return ZeroUnless(!beyond, bucket) | ZeroUnless(beyond, kOverflow);
  }
  // The head of a bucket's list, or of the overflow list (kOverflow), without a branch.
  std::uint32_t& HeadOf(std::uint32_t list) {
    const bool beyond = list == kOverflow;
    return *SelectPointer(beyond, &overflow_head_, &heads_[ZeroUnless(!beyond, list)]);
  }
  // The entry `index` names, or the spare one when it names none (kNoIndex): the target of a
  // link written without a branch on whether there is a neighbour.
  Entry& EntryOrSpare(std::uint32_t index) {
    const bool some = index != kNoIndex;
    return *SelectPointer(some, &entries_[ZeroUnless(some, index)], &spare_);
  }
  // Puts `entry` (slot `slot`) at the front of `list` (a bucket or kOverflow), and takes it out
  // of the list it is in: intrusive doubly linked lists, relinked without branches on the data
  // (whether a list is empty, whether an entry has neighbours: coin tosses in a gas, known
  // late, when the links arrive from memory).
  void ListLink(Entry& entry, std::uint32_t slot, std::uint32_t list) {
    std::uint32_t& head = HeadOf(list);
    entry.where = list;
    entry.prev = kNoIndex;
    entry.next = head;
    EntryOrSpare(head).prev = slot;
    head = slot;
  }
  void ListUnlink(const Entry& entry, std::uint32_t list) {
    const bool first = entry.prev == kNoIndex;
    *SelectPointer(first, &HeadOf(list), &entries_[ZeroUnless(!first, entry.prev)].next) =
        entry.next;
    EntryOrSpare(entry.next).prev = entry.prev;
  }
  // Set's common case, inline: the head's slot (the element an event was just handled for)
  // moves to a later bucket or beyond the year. Returns false, changing nothing, in any other
  // case, which SetAnyhow handles (the same result either way).
  bool MoveHeadToBucket(std::uint32_t slot, double time, EventKind kind) {
    if (slot >= entries_.size() || near_heap_) return false;
    Entry& entry = entries_[slot];
    const std::uint32_t at = entry.next;
    if (entry.where != kNear || at != top_) return false;
    const double q = Key(time);
    if (!(q >= current_end_)) return false;  // the current bucket, or NaN
    ListErase(at);
    entry.time = time;
    entry.kind = kind;
    ListLink(entry, slot, ListOf(q));
    if (near_.empty()) Refill();
    return true;
  }
  // Set's second case, inline: a slot in a later bucket or the overflow list (a collision's
  // second element) moves to a later bucket or beyond the year. The list orders do not
  // matter: a bucket is searched when it becomes current.
  bool MoveListedToBucket(std::uint32_t slot, double time, EventKind kind) {
    if (slot >= entries_.size()) return false;
    Entry& entry = entries_[slot];
    const std::uint32_t was = entry.where;
    if (was == kNear || was == kAbsent) return false;
    const double q = Key(time);
    if (!(q >= current_end_)) return false;  // the current bucket, or NaN
    ListUnlink(entry, was);
    entry.time = time;
    entry.kind = kind;
    ListLink(entry, slot, ListOf(q));
    return true;
  }
  void SetAnyhow(std::uint32_t slot, double time, EventKind kind);
  // Classify's bounds as doubles, kept with current_ and the bucket count: converting them
  // on every call (a size_t to double takes several instructions) was a third of Classify.
  void SetCurrent(std::uint32_t bucket) {
    current_ = bucket;
    current_end_ = static_cast<double>(bucket) + 1.0;
  }
  void SetYear() { year_end_ = static_cast<double>(heads_.size()); }
  void Link(std::uint32_t slot, std::uint32_t where);
  void Unlink(std::uint32_t slot);
  void AfterRemoval();
  void Refill();
  void Rollover();
  void Rebuild();
  void EstimateWidth();
  double HeadSpacing();
  void ResetCounters();

  // The current bucket: an unsorted list with its earliest entry at top_, or, beyond
  // kListLimit entries, an indexed binary heap (top_ = 0).
  static constexpr std::size_t kListLimit = 32;
  void FindTop() {
    // The earliest entry by a scan of selects: no branch on the (random) comparisons.
    std::uint32_t best = 0;
    const auto size = static_cast<std::uint32_t>(near_.size());
    for (std::uint32_t at = 1; at < size; ++at) {
      const std::uint32_t earlier = EarlierOf(near_[at], near_[best]);
      best = (at & (0u - earlier)) | (best & (earlier - 1u));
    }
    top_ = best;
  }
  // Less as 0 or 1 without a branch: GCC compiles Less's short circuit, and even `|` and `?:`
  // on its parts, to jumps on the (random) times; the compare masks below it keeps as data.
  static std::uint32_t EarlierOf(const Node& a, const Node& b) {
#if defined(__SSE2__)
    const __m128d ta = _mm_set_sd(a.time), tb = _mm_set_sd(b.time);
    const auto lt = static_cast<std::uint32_t>(_mm_movemask_pd(_mm_cmplt_sd(ta, tb)) & 1);
    const auto eq = static_cast<std::uint32_t>(_mm_movemask_pd(_mm_cmpeq_sd(ta, tb)) & 1);
    return lt | (eq & static_cast<std::uint32_t>(a.order < b.order));
#else
    return Less(a, b) ? 1u : 0u;
#endif
  }
  void MakeHeap();
  void NearPlace(std::uint32_t at, const Node& node) {
    near_[at] = node;
    entries_[SlotOf(node)].next = at;
  }
  // Takes entry `at` out of the current bucket as a list: the last entry fills the hole; the
  // earliest is looked for again only if it left.
  void ListErase(std::uint32_t at) {
    // Unconditional: when `at` is the last entry it is written onto itself (and its slot's
    // link, which a leaving entry rewrites or no longer uses), instead of a branch on where
    // the entry sat.
    const Node last = near_.back();
    NearPlace(at, last);
    near_.pop_back();
    const auto size = static_cast<std::uint32_t>(near_.size());
    if (top_ == at) {
      FindTop();
    } else if (top_ == size) {
      top_ = at;  // the earliest was the last entry, now at `at`
    }
  }
  void NearPush(const Node& node);
  void NearErase(std::uint32_t at);
  void NearUpdate(std::uint32_t at, const Node& node);
  void NearSiftUp(std::uint32_t at);
  void NearSiftDown(std::uint32_t at);

  BigVector<Entry> entries_;                // per slot
  Entry spare_{};                           // takes the back link written to an empty list
  std::vector<Node> near_;                  // the current bucket and anything earlier
  std::uint32_t top_ = 0;                   // the earliest of near_
  bool near_heap_ = false;                  // near_ is a heap (else an unsorted list)
  BigVector<std::uint32_t> heads_;          // the year: first slot of each bucket's list
  std::uint32_t overflow_head_ = kNoIndex;  // entries at or beyond the end of the year
  std::vector<std::uint32_t> scratch_;      // slots, reused by Rollover and Rebuild
  std::vector<double> sample_;              // reused by EstimateWidth
  std::size_t size_ = 0;
  double origin_ = 0.0;         // start time of bucket 0
  double width_ = 1.0;          // time span of one bucket
  double inverse_width_ = 1.0;  // 1 / width_: Classify multiplies
  std::uint32_t current_ = 0;   // the bucket whose entries are in near_
  double current_end_ = 1.0;    // current_ + 1: the first bucket after the current one
  double year_end_ = 0.0;       // BucketCount()

  // Cost observed since the last rebuild or check, for the width adaptation.
  std::uint64_t pops_ = 0;
  std::uint64_t scan_cost_ = 0;  // empty buckets scanned + entries re-bucketed at year ends
  std::uint64_t near_sizes_ = 0;
  double first_pop_time_ = 0.0;  // of the pops counted in pops_
  double last_pop_time_ = 0.0;
  std::uint64_t rebuilds_ = 0;
  bool prefetch_ = false;  // the slot array outgrew the caches: Refill fetches ahead
  const char* companion_ = nullptr;  // FetchWithRefills' array
  unsigned companion_shift_ = 0;
};

/// The plain queue: slots and times, no payload.
using CalendarQueue = BasicCalendarQueue<NoPayload>;
extern template class BasicCalendarQueue<NoPayload>;

}  // namespace sparsedyn
