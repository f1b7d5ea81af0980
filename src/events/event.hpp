// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// What a queued event is about. The order is part of the tie-break of simultaneous events
/// (time, kind, slot), so it is fixed: changing it changes every recording.
enum class EventKind : std::uint8_t {
  kCellCrossing = 0,   // an element's centre leaves its grid cell (or wraps in a periodic box)
  kWallMeet = 1,       // an element's sphere reaches a container wall
  kSphereMeet = 2,     // two elements' spheres meet (sparse phase, §3.3)
  kEngagement = 3,     // an engaged pair's detail event: contact or separation (§5.2)
  kStaticMeet = 4,     // an element's sphere reaches a static body's box
  kBodyTimer = 5,      // a change of a body's motion at a given time (a thrust schedule)
  kNone = 6,           // no event (an element with nothing ahead)
};
inline constexpr int kEventKindCount = 6;

/// Names used in statistics and in `sparsedyn run --json` ("events_by_kind").
inline constexpr std::array<std::string_view, kEventKindCount> kEventKindNames = {
    "cell_crossing", "wall_meet", "sphere_meet", "engagement", "static_meet", "body_timer"};

/// An element's one outstanding prediction (§4): the earliest thing that can happen to it.
/// `target` and `target_version` identify the other element of a meeting so that a meeting
/// whose target changed path since (target-absent, §4.2) is recognised when it comes up.
struct Event {
  double time = kInfinity;
  EventKind kind = EventKind::kNone;
  std::uint8_t aux = 0;               // wall index for kWallMeet
  std::uint32_t target = kNoIndex;    // element index for kSphereMeet
  std::uint32_t target_version = 0;   // the target's version when predicted
};

}  // namespace sparsedyn
