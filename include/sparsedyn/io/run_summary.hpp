// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string>

#include "sparsedyn/io/scene_file.hpp"
#include "sparsedyn/types.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {

/// What a run's summary reports that the World does not know itself: where the bodies came
/// from, how long the run took on the clock and the conserved quantities at its start.
struct RunContext {
  std::string preset;         ///< the scene's name (a preset's or a file's), reported as "preset"
  double density = 0.0;       ///< packing fraction, reported as "density" (see ReportedPacking)
  std::uint64_t seed = 0;     ///< the scene's seed, reported as "seed"
  double wall_seconds = 0.0;  ///< wall-clock seconds spent in AdvanceTo, reported as such
  double kinetic_energy_initial = 0.0;   ///< J, before the first AdvanceTo
  Vec3 momentum_initial = Vec3::Zero();  ///< kg m/s, before the first AdvanceTo
};

/// The packing fraction a summary reports for `scene`: the scene's own `packing` when it gives
/// one, else the bodies' volumes over the container's volume (0 in open space).
double ReportedPacking(const SceneDescription& scene);

/// The summary of a run as one JSON object, the object `sparsedyn run --json` prints (without
/// the recording's keys): bodies, bodies_by_kind (spheres, polyhedra, static: the moving
/// spheres, the moving polyhedra and the static bodies of either shape, adding up to bodies),
/// simulated_time, wall_seconds, events, events_by_kind, stale_events, meetings, collisions,
/// kinetic energy and momentum at the start and now, max_penetration, bytes_per_body and the
/// other counters of Statistics. Rates per second are 0 when `context.wall_seconds` is 0. The
/// Python package's `World.stats()` returns the same.
std::string RunSummaryJson(const World& world, const RunContext& context);

}  // namespace sparsedyn
