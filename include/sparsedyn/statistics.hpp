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
  std::uint64_t early_events = 0;         ///< a meeting that was not yet touching: predicted again
  std::uint64_t collapse_guarded = 0;     ///< collisions made elastic by the collapse guard
  std::uint64_t wall_holds = 0;  ///< spheres brought to rest by a wall (also wall collisions)
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
  std::uint64_t walk_cap_hits = 0;  ///< closest-feature walks that hit their iteration cap (0)
  // Wall-clock seconds by phase, measured only when WorldSettings::profile_phases is set.
  double seconds_sparse = 0;    ///< predictions (sparse phase)
  double seconds_detailed = 0;  ///< closest features and contact predictions (detailed phase)
  double seconds_response = 0;  ///< collision response
  double seconds_queue = 0;     ///< queue maintenance
};

/// The name of event kind `k` in Statistics::events_by_kind ("cell_crossing", ...).
const char* EventKindName(int k);

}  // namespace sparsedyn
