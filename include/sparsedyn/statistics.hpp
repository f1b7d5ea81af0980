// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>

namespace sparsedyn {

/// Counters of a World's event loop (world.Stats()). Event kinds are indexed in the order of
/// EventKindName(): cell_crossing, wall_meet, sphere_meet, engagement, static_meet, body_timer.
struct Statistics {
  std::uint64_t events = 0;                        ///< events taken from the queue
  std::array<std::uint64_t, 6> events_by_kind{};   ///< the same, by kind
  /// Meetings whose target changed path (§4.2): predicted again.
  std::uint64_t stale_target_absent = 0;
  std::uint64_t stale_actor_absent = 0;   ///< predictions superseded because the actor changed
  std::uint64_t meetings = 0;             ///< live element meetings (sparse phase)
  std::uint64_t collisions = 0;           ///< body-body impulses
  std::uint64_t wall_collisions = 0;      ///< body-wall impulses
  std::uint64_t static_collisions = 0;    ///< impulses against static bodies (in collisions too)
  std::uint64_t early_events = 0;         ///< a meeting that was not yet touching: predicted again
  std::uint64_t collapse_guarded = 0;     ///< collisions made elastic by the collapse guard
  std::uint64_t wall_holds = 0;  ///< bodies brought to rest by a wall: spheres, polyhedra on a face (also wall collisions)
  std::uint64_t static_holds = 0;  ///< bodies brought to rest on a static's face (also static collisions)
  std::uint64_t static_leaves = 0;  ///< held bodies whose centre of mass left a static's face
  /// Pairs of polyhedra whose bounding spheres started to overlap.
  std::uint64_t engagements_started = 0;
  /// Engaged pairs whose spheres separated again.
  std::uint64_t engagements_ended = 0;
  std::uint64_t predictions = 0;          ///< full predictions (actor against all its candidates)
  std::uint64_t partial_predictions = 0;  ///< after a cell crossing: against the new cells only
  std::uint64_t pair_tests = 0;           ///< element pairs whose meeting time was computed
  std::uint64_t pairs_skipped = 0;        ///< of those, settled by a distance bound without a root
  // The detailed phase (polyhedra, §5.2): contact predictions of engaged pairs and of bodies
  // near walls, the zone events / advancement steps they took, and the predictions that hit
  // their work cap and resumed later (checkpoints).
  /// Contact predictions of the detailed phase (engaged pairs, bodies near walls).
  std::uint64_t detail_predictions = 0;
  /// Zone events and advancement steps those predictions took.
  std::uint64_t detail_iterations = 0;
  /// Predictions that hit their work cap and resumed later.
  std::uint64_t detail_checkpoints = 0;
  /// Drag check events: a body with drag reached the end of its segment's horizon and started
  /// a new one from its true state (App. E.2's out-of-envelope checks).
  std::uint64_t drag_checks = 0;
  /// Refinement steps of contact predictions on the true motion of bodies with drag (each a
  /// local Taylor segment with a narrower envelope).
  std::uint64_t drag_steps = 0;
  std::uint64_t walk_cap_hits = 0;  ///< closest-feature walks that hit their iteration cap (0)
  // Wall-clock seconds by phase, measured only when WorldSettings::profile_phases is set.
  double seconds_sparse = 0;    ///< predictions (sparse phase)
  double seconds_detailed = 0;  ///< closest features and contact predictions (detailed phase)
  double seconds_response = 0;  ///< collision response
  double seconds_queue = 0;     ///< queue maintenance
};

/// Process-wide counts of the iterate-to-convergence loops that ran into their caps (all Worlds
/// and free functions of the process together; docs/reliability.md lists every such loop). A
/// cap keeps each result valid (conservative: a wider root bracket, an earlier prediction), only
/// less tight, so a non-zero count is a numerical corner case to look at; the tests assert 0
/// (the golden runs of tests/world/state_hash_test.cpp). The World's own caps are in Statistics:
/// the closest-feature walk (walk_cap_hits), the detailed phase's work cap (detail_checkpoints)
/// and the stall limit (an error from AdvanceTo).
struct CapCounters {
  std::uint64_t root_narrowing = 0;         ///< math: a root bracket still wide after 256 steps
  std::uint64_t meeting_certification = 0;  ///< sparse: 90 doublings did not certify a meeting time
  std::uint64_t impulse_rounds = 0;         ///< dynamics: 16 impulse rounds left a point approaching
  std::uint64_t level_crossing = 0;         ///< narrow: 200 doublings did not reach the tolerance
  std::uint64_t bisection = 0;              ///< narrow: a first-within bisection past 4096 steps
  /// Every count equal.
  friend bool operator==(const CapCounters&, const CapCounters&) = default;
};

/// The counts so far (relaxed atomic reads).
CapCounters CapHits();
/// Sets every count back to 0 (tests).
void ResetCapHits();

/// The name of event kind `k` in Statistics::events_by_kind ("cell_crossing", ...).
const char* EventKindName(int k);

}  // namespace sparsedyn
