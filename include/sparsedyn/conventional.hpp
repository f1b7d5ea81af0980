// SPDX-License-Identifier: MIT
// The conventional, time-stepped method (thesis §2.4, App. I.2) on the same bodies as the World,
// for side-by-side comparison (docs/conventional.md).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include "sparsedyn/result.hpp"
#include "sparsedyn/types.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {

/// How the conventional method steps: fixed steps of `dt`, and a collision found at the end of
/// a step is located by bisection to `digits` more decimal digits (interval < dt 10^-digits).
struct ConventionalSettings {
  double dt = 1e-3;  ///< s, > 0
  int digits = 4;    ///< A2 of App. I.2, in [0, 15]
};

/// Counters of a ConventionalWorld (Stats()).
struct ConventionalStatistics {
  /// Time steps taken.
  std::uint64_t steps = 0;
  std::uint64_t pair_tests = 0;             ///< bounding-box overlaps found by the broad phase
  std::uint64_t narrow_queries = 0;         ///< closest-feature queries at step ends and re-checks
  std::uint64_t bisection_evaluations = 0;  ///< distances evaluated while locating collisions
  std::uint64_t collisions = 0;             ///< body-body impulses
  std::uint64_t wall_collisions = 0;        ///< body-wall impulses
  std::uint64_t walk_cap_hits = 0;          ///< closest-feature walks that hit their cap (0)
  double max_penetration = 0.0;  ///< deepest overlap (pair or wall) seen at a step end, m
};

/// Bodies moved in fixed time steps (§2.4). At the end of each step every body's pose is
/// evaluated from its path (the World's motion model: polynomial centre, constant world-frame
/// angular velocity), bounding boxes are swept for overlaps, overlapping pairs are measured by
/// closest features, and a pair found touching is moved back to its collision time by
/// bisection, where it gets the World's impulse. A pair that passes through another within one
/// step is never seen: that aliasing is inherent to the method, not a bug.
///
/// Convex polyhedra only, in open space or a walled box (no spheres, no periodic box).
class ConventionalWorld {
 public:
  /// An empty world at time 0; check the settings first with CheckSettings.
  ConventionalWorld(const WorldSettings& settings, const ConventionalSettings& conventional);
  ~ConventionalWorld();
  /// Moves the whole world.
  ConventionalWorld(ConventionalWorld&&) noexcept;
  /// Moves the whole world.
  ConventionalWorld& operator=(ConventionalWorld&&) noexcept;
  ConventionalWorld(const ConventionalWorld&) = delete;
  ConventionalWorld& operator=(const ConventionalWorld&) = delete;

  /// Checks the settings (dt > 0 and finite, digits in [0, 15], no periodic box).
  static Status CheckSettings(const WorldSettings& settings,
                              const ConventionalSettings& conventional);

  /// Adds a polyhedral body before the first AdvanceTo. Refused, with nothing changed, for a
  /// sphere (no shape), a static body, a god object, bad values (as World::AddBody), a body
  /// outside a walled box or touching one already present, or after the start.
  Result<BodyId> AddBody(const BodyDef& def);

  /// Steps until time t (the last step is shortened to end at t). Fails when one step needs an
  /// unbounded number of collisions (a stuck configuration).
  Status AdvanceTo(double t);

  /// The state of `id` at t, within the current step (free flight from the last step end).
  BodyState StateAt(BodyId id, double t) const;
  /// The time stepped to, s.
  double Time() const;
  /// The number of bodies.
  std::size_t BodyCount() const;
  /// The World settings it was made with.
  const WorldSettings& Settings() const;
  /// The step and digits it was made with.
  const ConventionalSettings& Conventional() const;

  /// Called after every resolved collision (body-body and body-wall), in time order.
  void OnCollision(std::function<void(const CollisionEvent&)> callback);

  /// The counters so far.
  const ConventionalStatistics& Stats() const;
  double KineticEnergy() const;  ///< at Time(), translational + rotational
  Vec3 Momentum() const;         ///< at Time()

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sparsedyn
