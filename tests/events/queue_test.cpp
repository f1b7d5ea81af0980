// SPDX-License-Identifier: MIT
// The event queues (HeapQueue<2>, HeapQueue<4>, CalendarQueue) against their slow twin
// ReferenceQueue on long random operation streams, plus small exact cases.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "events/calendar_queue.hpp"
#include "events/calendar_queue_impl.hpp"
#include "events/heap_queue.hpp"
#include "events/reference_queue.hpp"
#include "support/fp_traps.hpp"

namespace sparsedyn {

// A payload as the world's: a record per slot that the queue keeps but never reads.
struct TestPayload {
  std::uint64_t stamp = 0;
  std::uint32_t owner = 0;
};
template class BasicCalendarQueue<TestPayload>;

namespace {

constexpr double kHuge = 1e300;

// A queue and the reference driven by the same operations.
template <typename Queue>
struct Twin {
  Queue queue;
  ReferenceQueue reference;

  void Set(std::uint32_t slot, double time, EventKind kind) {
    queue.Set(slot, time, kind);
    reference.Set(slot, time, kind);
  }
  void Erase(std::uint32_t slot) {
    queue.Erase(slot);
    reference.Erase(slot);
  }
  void Pop() {
    queue.Pop();
    reference.Pop();
  }
  void Clear() {
    queue.Clear();
    reference.Clear();
  }

  // Same emptiness, size, membership of `slot` and head.
  ::testing::AssertionResult Agrees(std::uint32_t slot) const {
    if (queue.Empty() != reference.Empty() || queue.Size() != reference.Size()) {
      return ::testing::AssertionFailure()
             << "size " << queue.Size() << ", reference " << reference.Size();
    }
    if (queue.Contains(slot) != reference.Contains(slot)) {
      return ::testing::AssertionFailure() << "Contains(" << slot << ") differs";
    }
    if (reference.Empty()) return ::testing::AssertionSuccess();
    const QueueTop a = queue.Top();
    const QueueTop b = reference.Top();
    if (a.time != b.time || a.kind != b.kind || a.slot != b.slot) {
      return ::testing::AssertionFailure() << "top (" << a.time << ", " << static_cast<int>(a.kind)
                                           << ", " << a.slot << "), reference (" << b.time << ", "
                                           << static_cast<int>(b.kind) << ", " << b.slot << ")";
    }
    return ::testing::AssertionSuccess();
  }
};

// Draws the keys of the random streams. Kinds and quantised times make ties frequent.
class KeySource {
 public:
  explicit KeySource(std::uint64_t seed) : rng_(seed) {}

  std::uint32_t Slot(std::uint32_t count) {
    return std::uniform_int_distribution<std::uint32_t>(0, count - 1)(rng_);
  }
  EventKind Kind() { return static_cast<EventKind>(Slot(kEventKindCount)); }
  double Uniform() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_); }
  double Exponential(double mean) {
    return std::exponential_distribution<double>(1.0 / mean)(rng_);
  }
  // Multiples of 1/8 tie often but not always.
  static double Quantised(double t) { return std::floor(t * 8.0) / 8.0; }

  // Any time, relative to the current head `now`: later, equal, earlier, huge or infinite.
  double AnyTime(double now) {
    const double u = Uniform();
    if (u < 0.35) return Quantised(now + Exponential(1.0));
    if (u < 0.50) return static_cast<double>(Slot(64));  // absolute, often before the head
    if (u < 0.60) return now - Exponential(2.0);         // earlier than the head
    if (u < 0.70) return now + 1000.0 * Uniform();       // far, beyond a year
    if (u < 0.75) return now;                            // equal to the head
    if (u < 0.79) return std::numeric_limits<double>::infinity();
    if (u < 0.82) return kHuge * Uniform();
    if (u < 0.83) return -kHuge;
    if (u < 0.835) return -std::numeric_limits<double>::infinity();
    return now + Exponential(0.01);
  }

 private:
  std::mt19937_64 rng_;
};

template <typename Queue>
double HeadTime(const Queue& queue) {
  return queue.Empty() ? 0.0 : queue.Top().time;
}

// `holds` holds: the head's slot set again at the head's time plus increment(), quantised,
// with its kind; popped first, or (as the World does) moved in place. Checked after each.
template <typename Queue, typename Increment>
::testing::AssertionResult Hold(Twin<Queue>& twin, int holds, bool in_place, Increment increment) {
  for (int hold = 0; hold < holds; ++hold) {
    const QueueTop top = twin.reference.Top();
    if (!in_place) twin.Pop();
    twin.Set(top.slot, KeySource::Quantised(top.time + increment()), top.kind);
    if (auto agrees = twin.Agrees(top.slot); !agrees) return agrees << " at hold " << hold;
  }
  return ::testing::AssertionSuccess();
}

template <typename Queue>
class QueueOracle : public ::testing::Test {};

class QueueNames {
 public:
  template <typename T>
  static std::string GetName(int) {
    if constexpr (std::is_same_v<T, HeapQueue<2>>) return "Heap2";
    if constexpr (std::is_same_v<T, HeapQueue<4>>) return "Heap4";
    return "Calendar";
  }
};

using QueueTypes = ::testing::Types<HeapQueue<2>, HeapQueue<4>, CalendarQueue>;
TYPED_TEST_SUITE(QueueOracle, QueueTypes, QueueNames);

// Random Set (insert, earlier, later), Erase and Pop with any times, in phases that grow the
// queue to thousands of entries and drain it again so that every resize path runs.
TYPED_TEST(QueueOracle, AgreesWithReferenceOnRandomOperations) {
  // Floating-point traps paused (docs/reliability.md): huge times overflow
  // the calendar's bucket key to +infinity, which puts them in the overflow list.
  const sparsedyn::testing::FloatingPointTrapsPaused traps_paused;
  for (const std::uint64_t seed : {20260611u, 7u, 424242u}) {
    SCOPED_TRACE("seed=" + std::to_string(seed));
    KeySource keys(seed);
    Twin<TypeParam> twin;
    for (int phase = 0; phase < 8; ++phase) {
      // Even phases mostly insert, odd phases mostly remove; slot ranges vary per phase.
      const bool grow = phase % 2 == 0;
      const std::uint32_t slots = phase < 4 ? 300u : 6000u;
      for (int op = 0; op < 12000; ++op) {
        const double u = keys.Uniform();
        std::uint32_t slot = keys.Slot(slots);
        if (u < (grow ? 0.70 : 0.35)) {
          twin.Set(slot, keys.AnyTime(HeadTime(twin.reference)), keys.Kind());
        } else if (u < (grow ? 0.80 : 0.55)) {
          twin.Erase(slot);
        } else if (!twin.reference.Empty()) {
          slot = twin.reference.Top().slot;
          twin.Pop();
        }
        ASSERT_TRUE(twin.Agrees(slot)) << "phase " << phase << ", operation " << op;
      }
    }
    twin.Clear();
    ASSERT_TRUE(twin.Agrees(0));
  }
}

// The classic priority-queue benchmark as a test: pop the head and re-insert its slot at the
// head time plus an exponential increment (quantised, so that equal times occur).
TYPED_TEST(QueueOracle, AgreesWithReferenceOnHoldModel) {
  for (const std::uint32_t n : {100u, 1000u, 20000u}) {
    const std::uint64_t seed = 1000 + n;
    SCOPED_TRACE("seed=" + std::to_string(seed) + " n=" + std::to_string(n));
    KeySource keys(seed);
    Twin<TypeParam> twin;
    for (std::uint32_t slot = 0; slot < n; ++slot) {
      twin.Set(slot, KeySource::Quantised(keys.Exponential(1.0)), keys.Kind());
    }
    ASSERT_TRUE(Hold(twin, 60000, false, [&keys] { return keys.Exponential(1.0); }));
  }
}

// The World's hold: the head's slot is moved to a later time without a Pop. The slots in use
// are every `stride`-th of the slot array: dense (stride 1), with absent slots between them
// (3 of 4 in use) and sparse (1 in 7), so that the calendar queue's year ends both stream the
// slot array (entries fill at least half of it) and walk the overflow list (they do not).
TYPED_TEST(QueueOracle, AgreesWithReferenceOnHoldInPlaceWithAbsentSlots) {
  for (const std::uint32_t stride : {1u, 4u, 7u}) {
    const std::uint64_t seed = 77 + stride;
    SCOPED_TRACE("seed=" + std::to_string(seed) + " stride=" + std::to_string(stride));
    KeySource keys(seed);
    Twin<TypeParam> twin;
    constexpr std::uint32_t kSlots = 5000;
    for (std::uint32_t slot = 0; slot < kSlots; ++slot) {
      // Stride 4 keeps three slots of four: the fourth stays absent.
      const bool used = stride == 4 ? slot % 4 != 3 : slot % stride == 0;
      if (used) twin.Set(slot, keys.Exponential(1.0), keys.Kind());
    }
    ASSERT_TRUE(Hold(twin, 40000, true, [&keys] { return keys.Exponential(1.0); }));
  }
}

// A hold whose increments have a long tail: most are about one mean spacing per entry, one in
// ten 1-6 years of a calendar queue ahead on average, one in fifty 30 years. The calendar's
// year is used up hundreds of times, so entries wait in its overflow list through one or many
// year ends before their bucket comes round.
TYPED_TEST(QueueOracle, AgreesWithReferenceWithEntriesYearsAhead) {
  for (const bool in_place : {false, true}) {
    const std::uint64_t seed = in_place ? 4242 : 4243;
    SCOPED_TRACE("seed=" + std::to_string(seed));
    KeySource keys(seed);
    Twin<TypeParam> twin;
    // A year: 256 buckets of 2.5 mean spacings (1 / 200 each), about 3.2 time units.
    constexpr std::uint32_t kSlots = 200;
    for (std::uint32_t slot = 0; slot < kSlots; ++slot) {
      twin.Set(slot, keys.Exponential(1.0), keys.Kind());
    }
    ASSERT_TRUE(Hold(twin, 60000, in_place, [&keys] {
      const double u = keys.Uniform();
      return keys.Exponential(u < 0.02 ? 100.0 : u < 0.12 ? 3.2 + 16.0 * keys.Uniform() : 1.0);
    }));
  }
}

// The World's pattern on a slot array beyond the caches (over 65,536 slots: a calendar queue
// then fetches ahead in its refills): each event moves the head's slot (or pops and sets it
// again) and sets or erases one or two others, with long-tailed increments (some beyond the
// year); then a drain to a few entries (a year of 16 buckets) and a refill.
TYPED_TEST(QueueOracle, AgreesWithReferenceOnALargeSlotArray) {
  for (const bool in_place : {false, true}) {
    const std::uint64_t seed = in_place ? 6060 : 6061;
    SCOPED_TRACE("seed=" + std::to_string(seed));
    KeySource keys(seed);
    Twin<TypeParam> twin;
    constexpr std::uint32_t kSlots = 70000;
    constexpr std::uint32_t kStride = 5;  // 14,000 entries
    for (std::uint32_t slot = 0; slot < kSlots; slot += kStride) {
      twin.Set(slot, keys.Exponential(1.0), keys.Kind());
    }
    const auto ahead = [&keys] {
      const double u = keys.Uniform();
      return keys.Exponential(u < 0.02 ? 30.0 : u < 0.1 ? 3.0 : 1.0);
    };
    const auto events = [&](int count) {
      for (int event = 0; event < count; ++event) {
        const QueueTop top = twin.reference.Top();
        if (!in_place) twin.Pop();
        twin.Set(top.slot, KeySource::Quantised(top.time + ahead()), top.kind);
        ASSERT_TRUE(twin.Agrees(top.slot)) << "event " << event;
        const int others = keys.Uniform() < 0.5 ? 1 : 2;
        for (int k = 0; k < others; ++k) {
          const std::uint32_t slot = kStride * keys.Slot(kSlots / kStride);
          if (keys.Uniform() < 0.05) {
            twin.Erase(slot);
          } else {
            twin.Set(slot, top.time + ahead(), keys.Kind());
          }
          ASSERT_TRUE(twin.Agrees(slot)) << "event " << event;
        }
      }
    };
    events(60000);
    while (twin.reference.Size() > 8) {
      twin.Pop();
      ASSERT_TRUE(twin.Agrees(0));
    }
    events(20000);
  }
}

// The World's pattern: each event re-predicts its own slot and a few others, always at or
// after the current time, with an event spacing that drifts over twelve orders of magnitude
// (the calendar queue must re-adapt its width both ways). The head's slot popped and set
// again, or (as the World does) moved in place.
TYPED_TEST(QueueOracle, AgreesWithReferenceOnDriftingSparseDynamics) {
  for (const bool in_place : {false, true}) {
    const std::uint64_t seed = in_place ? 99992 : 99991;
    SCOPED_TRACE("seed=" + std::to_string(seed));
    KeySource keys(seed);
    Twin<TypeParam> twin;
    constexpr std::uint32_t kSlots = 3000;
    for (std::uint32_t slot = 0; slot < kSlots; ++slot) {
      twin.Set(slot, keys.Exponential(1.0), EventKind::kSphereMeet);
    }
    const double scales[] = {1.0, 1e-6, 1e6, 1.0};
    for (const double scale : scales) {
      for (int event = 0; event < 25000; ++event) {
        const QueueTop top = twin.reference.Top();
        if (!in_place) twin.Pop();
        twin.Set(top.slot, top.time + keys.Exponential(scale), keys.Kind());
        ASSERT_TRUE(twin.Agrees(top.slot)) << "scale " << scale << ", event " << event;
        const int others = keys.Uniform() < 0.5 ? 1 : 2;
        for (int k = 0; k < others; ++k) {
          const std::uint32_t slot = keys.Slot(kSlots);
          if (keys.Uniform() < 0.05) {
            twin.Erase(slot);
          } else {
            twin.Set(slot, top.time + keys.Exponential(scale), keys.Kind());
          }
          ASSERT_TRUE(twin.Agrees(slot)) << "scale " << scale << ", event " << event;
        }
      }
    }
  }
}

// Every entry at the same time: the order is by kind, then slot.
TYPED_TEST(QueueOracle, AgreesWithReferenceWhenAllTimesAreEqual) {
  KeySource keys(5);
  Twin<TypeParam> twin;
  for (int op = 0; op < 20000; ++op) {
    const std::uint32_t slot = keys.Slot(2000);
    if (keys.Uniform() < 0.6) {
      twin.Set(slot, 3.0, keys.Kind());
    } else if (!twin.reference.Empty()) {
      twin.Pop();
    }
    ASSERT_TRUE(twin.Agrees(slot)) << "operation " << op;
  }
}

// Bursts of entries a hair apart (one bucket of a calendar queue, whose current bucket is a
// list up to 32 entries and a heap beyond) around the list's limit, with moves inside the burst,
// erasures and pops, between stretches of ordinary spacing.
TYPED_TEST(QueueOracle, AgreesWithReferenceThroughBurstsInOneBucket) {
  KeySource keys(6);
  Twin<TypeParam> twin;
  for (const std::uint32_t burst : {5u, 31u, 32u, 33u, 40u, 100u, 3u, 64u}) {
    for (int op = 0; op < 300; ++op) {  // ordinary spacing
      const std::uint32_t slot = keys.Slot(500);
      twin.Set(slot, HeadTime(twin.reference) + keys.Exponential(1.0), keys.Kind());
      if (keys.Uniform() < 0.5) twin.Pop();
      ASSERT_TRUE(twin.Agrees(slot)) << "burst " << burst << ", operation " << op;
    }
    const double at = HeadTime(twin.reference) + 0.5;
    for (std::uint32_t k = 0; k < burst; ++k) {
      const std::uint32_t slot = keys.Slot(500);
      twin.Set(slot, at + 1e-12 * static_cast<double>(keys.Slot(8)), keys.Kind());
      ASSERT_TRUE(twin.Agrees(slot)) << "burst " << burst << ", entry " << k;
    }
    for (int op = 0; op < static_cast<int>(3 * burst); ++op) {  // moves, erasures, pops
      const std::uint32_t slot = keys.Slot(500);
      const double u = keys.Uniform();
      if (u < 0.4) {
        twin.Set(slot, at + 1e-12 * static_cast<double>(keys.Slot(8)), keys.Kind());
      } else if (u < 0.5) {
        twin.Erase(slot);
      } else if (!twin.reference.Empty()) {
        twin.Pop();
      }
      ASSERT_TRUE(twin.Agrees(slot)) << "burst " << burst << ", operation " << op;
    }
  }
}

TYPED_TEST(QueueOracle, EmptyQueueHasNoEntries) {
  TypeParam queue;
  EXPECT_TRUE(queue.Empty());
  EXPECT_EQ(queue.Size(), 0u);
  EXPECT_FALSE(queue.Contains(0));
  EXPECT_FALSE(queue.Contains(123456));
  queue.Erase(7);  // erasing an absent slot is a no-op
  EXPECT_TRUE(queue.Empty());
  queue.Set(7, 1.0, EventKind::kWallMeet);
  queue.Pop();
  EXPECT_TRUE(queue.Empty());
  EXPECT_FALSE(queue.Contains(7));
}

TYPED_TEST(QueueOracle, TiesAreBrokenByKindThenSlot) {
  TypeParam queue;
  queue.Set(5, 2.0, EventKind::kSphereMeet);
  queue.Set(9, 2.0, EventKind::kCellCrossing);
  queue.Set(1, 2.0, EventKind::kSphereMeet);
  queue.Set(3, 2.0, EventKind::kEngagement);
  queue.Set(4, 2.0, EventKind::kCellCrossing);
  queue.Set(8, 1.5, EventKind::kEngagement);
  const std::uint32_t expected[] = {8, 4, 9, 1, 5, 3};
  for (const std::uint32_t slot : expected) {
    ASSERT_FALSE(queue.Empty());
    EXPECT_EQ(queue.Top().slot, slot);
    queue.Pop();
  }
  EXPECT_TRUE(queue.Empty());
}

TYPED_TEST(QueueOracle, ErasingTheHeadExposesTheNextEntry) {
  TypeParam queue;
  queue.Set(0, 3.0, EventKind::kWallMeet);
  queue.Set(1, 1.0, EventKind::kWallMeet);
  queue.Set(2, 2.0, EventKind::kWallMeet);
  queue.Erase(1);
  EXPECT_EQ(queue.Top().slot, 2u);
  EXPECT_EQ(queue.Top().time, 2.0);
  EXPECT_EQ(queue.Size(), 2u);
  EXPECT_FALSE(queue.Contains(1));
}

TYPED_TEST(QueueOracle, UpdatingTheHeadMovesIt) {
  TypeParam queue;
  queue.Set(0, 1.0, EventKind::kSphereMeet);
  queue.Set(1, 2.0, EventKind::kSphereMeet);
  queue.Set(2, 3.0, EventKind::kSphereMeet);
  queue.Set(0, 2.5, EventKind::kSphereMeet);  // the head moves later, past slot 1
  EXPECT_EQ(queue.Top().slot, 1u);
  queue.Set(2, 0.5, EventKind::kWallMeet);  // the last moves before the head
  EXPECT_EQ(queue.Top().slot, 2u);
  EXPECT_EQ(queue.Top().kind, EventKind::kWallMeet);
  EXPECT_EQ(queue.Size(), 3u);
  queue.Pop();
  queue.Pop();
  EXPECT_EQ(queue.Top().slot, 0u);
  EXPECT_EQ(queue.Top().time, 2.5);
}

TYPED_TEST(QueueOracle, InfiniteAndHugeTimesComeLastInOrder) {
  // Floating-point traps paused (docs/reliability.md): huge and infinite
  // times make infinite (or, at an infinite origin, NaN) bucket keys on purpose.
  const sparsedyn::testing::FloatingPointTrapsPaused traps_paused;
  TypeParam queue;
  const double inf = std::numeric_limits<double>::infinity();
  queue.Set(0, inf, EventKind::kSphereMeet);
  queue.Set(1, kHuge, EventKind::kSphereMeet);
  queue.Set(2, inf, EventKind::kWallMeet);
  queue.Set(3, 1.0, EventKind::kSphereMeet);
  queue.Set(4, -inf, EventKind::kSphereMeet);
  const std::uint32_t expected[] = {4, 3, 1, 2, 0};
  for (const std::uint32_t slot : expected) {
    EXPECT_EQ(queue.Top().slot, slot);
    queue.Pop();
  }
  EXPECT_TRUE(queue.Empty());
}

// The calendar's bucket count follows the size, and its width follows the event spacing.
TEST(CalendarQueue, ResizesWithSizeAndAdaptsWidthToSpacing) {
  CalendarQueue queue;
  std::mt19937_64 rng(31337);
  std::exponential_distribution<double> increment(1.0);
  constexpr std::uint32_t kSlots = 1 << 14;
  for (std::uint32_t slot = 0; slot < kSlots; ++slot) {
    queue.Set(slot, increment(rng), EventKind::kSphereMeet);
  }
  EXPECT_GE(queue.BucketCount(), kSlots / 2);
  EXPECT_LE(queue.BucketCount(), kSlots * 2);

  // Hold model with mean increment `scale`; after the change the width must follow the
  // spacing of the popped times (measured over the last holds).
  for (const double scale : {1.0, 1e-5, 1e4}) {
    constexpr int kHolds = 8 * static_cast<int>(kSlots);
    constexpr int kMeasured = 2000;
    double first = 0.0;
    for (int hold = 0; hold < kHolds; ++hold) {
      const QueueTop top = queue.Top();
      if (hold == kHolds - kMeasured) first = top.time;
      queue.Pop();
      queue.Set(top.slot, top.time + scale * increment(rng), top.kind);
    }
    const double spacing = (queue.Top().time - first) / kMeasured;
    EXPECT_GT(queue.BucketWidth(), 0.2 * spacing) << "scale " << scale;
    EXPECT_LT(queue.BucketWidth(), 50.0 * spacing) << "scale " << scale;
  }

  // Draining shrinks the year again.
  while (queue.Size() > 100) queue.Pop();
  EXPECT_LE(queue.BucketCount(), 512u);
  EXPECT_GT(queue.MemoryBytes(), 0u);
  queue.Clear();
  EXPECT_TRUE(queue.Empty());
}

// Upcoming guesses the next heads for the look-ahead: never the head itself, no slot twice,
// only slots with entries, and in a gas-like stream (each head moved to a later time) the next
// head is its first guess most of the time.
TEST(CalendarQueue, UpcomingGuessesTheNextHeads) {
  CalendarQueue queue;
  std::mt19937_64 rng(2718);
  std::exponential_distribution<double> gap(1.0);
  constexpr std::uint32_t kSlots = 1 << 12;
  std::uniform_real_distribution<double> start(0.0, kSlots);
  for (std::uint32_t slot = 0; slot < kSlots; ++slot) {
    queue.Set(slot, start(rng), EventKind::kSphereMeet);  // about one event per unit of time
  }
  int right = 0;
  constexpr int kEvents = 20000;
  for (int e = 0; e < kEvents; ++e) {
    const QueueTop top = queue.Top();
    std::uint32_t next[4];
    const int count = queue.Upcoming(next, 4);
    ASSERT_GE(count, 0);  // none when the next buckets are empty
    ASSERT_LE(count, 4);
    for (int k = 0; k < count; ++k) {
      EXPECT_NE(next[k], top.slot);
      EXPECT_TRUE(queue.Contains(next[k]));
      for (int m = 0; m < k; ++m) EXPECT_NE(next[k], next[m]);
    }
    queue.Set(top.slot, top.time + gap(rng) * kSlots, EventKind::kSphereMeet);
    right += count > 0 && queue.Top().slot == next[0] ? 1 : 0;
  }
  EXPECT_GT(right, kEvents * 7 / 10) << "next head guessed " << right << " times in " << kEvents;

  // A queue of one entry has nothing upcoming.
  CalendarQueue single;
  single.Set(5, 1.0, EventKind::kCellCrossing);
  std::uint32_t none[2];
  EXPECT_EQ(single.Upcoming(none, 2), 0);
}

// A queue with payloads orders exactly as the plain one on the same stream (sets, moves,
// erases, pops, with the rebuilds and year ends they cause), and every payload stays with its
// slot through all of it, through Clear, and through Resize, which adds value-initialised ones.
TEST(CalendarQueue, PayloadsStayWithTheirSlots) {
  BasicCalendarQueue<TestPayload> carrying;
  CalendarQueue plain;
  constexpr std::uint32_t kSlots = 3000;
  carrying.Resize(kSlots);
  ASSERT_EQ(carrying.Slots(), kSlots);
  for (std::uint32_t slot = 0; slot < kSlots; ++slot) {
    EXPECT_EQ(carrying.PayloadOf(slot).stamp, 0u);
    EXPECT_FALSE(carrying.Contains(slot));
    carrying.PayloadOf(slot) = TestPayload{0, slot};
  }
  std::mt19937_64 rng(1618);
  std::uniform_int_distribution<std::uint32_t> pick(0, kSlots - 1);
  std::exponential_distribution<double> gap(1.0);
  std::vector<std::uint64_t> stamp(kSlots, 0);
  double now = 0.0;
  for (std::uint64_t op = 1; op <= 200000; ++op) {
    const std::uint32_t slot = pick(rng);
    const std::uint64_t kind = op % 7;
    if (kind == 0) {
      carrying.Erase(slot);
      plain.Erase(slot);
    } else if (kind == 1 && !plain.Empty()) {
      const QueueTop top = plain.Top();
      const QueueTop same = carrying.Top();
      ASSERT_EQ(same.slot, top.slot) << "op " << op;
      ASSERT_EQ(same.time, top.time) << "op " << op;
      now = top.time;
      carrying.Pop();
      plain.Pop();
    } else {
      // Mostly near the head, now and then far beyond the year.
      const double t = now + gap(rng) * (kind == 2 ? 1e6 : 50.0);
      carrying.Set(slot, t, EventKind::kCellCrossing);
      plain.Set(slot, t, EventKind::kCellCrossing);
    }
    stamp[slot] = op;
    carrying.PayloadOf(slot).stamp = op;
    ASSERT_EQ(carrying.Size(), plain.Size());
  }
  EXPECT_GT(carrying.RebuildCount(), 0u);
  carrying.Clear();
  EXPECT_TRUE(carrying.Empty());
  ASSERT_EQ(carrying.Slots(), kSlots);
  for (std::uint32_t slot = 0; slot < kSlots; ++slot) {
    EXPECT_FALSE(carrying.Contains(slot));
    EXPECT_EQ(carrying.PayloadOf(slot).owner, slot);
    EXPECT_EQ(carrying.PayloadOf(slot).stamp, stamp[slot]);
  }
  carrying.Resize(kSlots + 2);
  EXPECT_EQ(carrying.PayloadOf(kSlots + 1).stamp, 0u);
  EXPECT_EQ(carrying.PayloadOf(kSlots - 1).owner, kSlots - 1);
  carrying.ShrinkToFit();
  EXPECT_EQ(carrying.Slots(), kSlots + 2);
  // A cleared queue works as a new one.
  carrying.Set(7, 2.0, EventKind::kSphereMeet);
  carrying.Set(3, 1.0, EventKind::kSphereMeet);
  EXPECT_EQ(carrying.Top().slot, 3u);
  EXPECT_EQ(carrying.PayloadOf(3).owner, 3u);
}

}  // namespace
}  // namespace sparsedyn
