// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <limits>

#include <Eigen/Core>

namespace sparsedyn {

using Vec3 = Eigen::Vector3d;

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline constexpr std::uint32_t kNoIndex = 0xffffffffu;

/// Handle of a body in a World; passed by value. `generation` guards against slot reuse.
struct BodyId {
  std::uint32_t index = kNoIndex;
  std::uint32_t generation = 0;
  bool valid() const { return index != kNoIndex; }
  friend bool operator==(BodyId, BodyId) = default;
};

/// E(t) = e0 + e1 (t - t0) + e2 (t - t0)^2 / 2 >= 0 (App. F.1, F.3): how far the body may stray
/// from its path P(t) during a segment that starts at t0. Each new segment starts it afresh.
struct Envelope {
  double e0 = 0.0;
  double e1 = 0.0;
  double e2 = 0.0;
  /// The radius added to the bounding sphere `dt` after the segment start.
  double At(double dt) const { return e0 + dt * (e1 + 0.5 * e2 * dt); }
  bool IsZero() const { return e0 == 0.0 && e1 == 0.0 && e2 == 0.0; }
};

/// A change of a body's own acceleration (App. F.3, a rocket's thrust): from `time` (s) on it is
/// `thrust` (m/s^2, added to gravity).
struct ThrustChange {
  double time = 0.0;
  Vec3 thrust = Vec3::Zero();
};

}  // namespace sparsedyn
