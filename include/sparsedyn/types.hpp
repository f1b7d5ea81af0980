// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace sparsedyn {

using Vec3 = Eigen::Vector3d;

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline constexpr std::uint32_t kNoIndex = 0xffffffffu;

/// Handle of a body in a World; passed by value. `generation` guards against slot reuse.
struct BodyId {
  /// The body's slot in the World (kNoIndex: no body); its row in per-body arrays.
  std::uint32_t index = kNoIndex;
  /// Bumped when a slot is reused, so that an old handle is recognised as stale.
  std::uint32_t generation = 0;
  /// Whether the handle names a slot at all (not whether the body still exists).
  bool valid() const { return index != kNoIndex; }
  /// Handles are equal when slot and generation are.
  friend bool operator==(BodyId, BodyId) = default;
};

/// E(t) = e0 + e1 (t - t0) + e2 (t - t0)^2 / 2 >= 0 (App. F.1, F.3): how far the body may stray
/// from its path P(t) during a segment that starts at t0. Each new segment starts it afresh.
struct Envelope {
  /// m: the growth at the segment start.
  double e0 = 0.0;
  /// m/s: the growth rate.
  double e1 = 0.0;
  /// m/s^2: the growth acceleration (a bound on unmodelled acceleration).
  double e2 = 0.0;
  /// The radius added to the bounding sphere `dt` after the segment start.
  double At(double dt) const { return e0 + dt * (e1 + 0.5 * e2 * dt); }
  /// Whether the envelope adds nothing at any time.
  bool IsZero() const { return e0 == 0.0 && e1 == 0.0 && e2 == 0.0; }
};

/// A change of a body's own acceleration (App. F.3, a rocket's thrust): from `time` (s) on it is
/// `thrust` (m/s^2, added to gravity).
struct ThrustChange {
  double time = 0.0;           ///< s
  Vec3 thrust = Vec3::Zero();  ///< m/s^2, the body's own acceleration from `time` on
};

/// Aerodynamic drag on a body's centre (App. H.2, "wind resistance"): the acceleration
/// a = g - linear v - quadratic |v| v, with g the body's constant acceleration (gravity plus its
/// thrust) and v its velocity in the world frame (still air). `linear` (c1, 1/s) is Stokes drag,
/// `quadratic` (c2, 1/m) is Newton drag (c2 = rho Cd A / (2 m)); both must be finite and >= 0.
/// The true motion is src/motion/drag_motion.hpp's DragMotion (docs/dynamics.md, "Drag").
struct Drag {
  double linear = 0.0;     ///< c1, 1/s
  double quadratic = 0.0;  ///< c2, 1/m
  /// No drag at all: the body's path is the constant-acceleration polynomial of App. F.3.
  bool IsZero() const { return linear == 0.0 && quadratic == 0.0; }
};

/// One target of a god object's track (App. H.3): be at `position` at `time` (s, absolute),
/// moving at `velocity` if one is given (otherwise the plan chooses it: docs/dynamics.md,
/// "God objects").
struct GodTarget {
  double time = 0.0;                ///< s
  Vec3 position = Vec3::Zero();     ///< m, the centre of mass
  std::optional<Vec3> velocity;     ///< m/s; unset: a sweep through the waypoints
};

/// A god object (App. H.3): a body driven from outside along `track` with |acceleration| <=
/// `max_acceleration`; it lags behind a target it cannot reach in time. To other bodies it has
/// infinite mass (it pushes them, nothing pushes it).
struct GodDef {
  double max_acceleration = 1.0;  ///< A, m/s^2, > 0
  std::vector<GodTarget> track;   ///< times strictly increasing, none before the World's clock
};

}  // namespace sparsedyn
