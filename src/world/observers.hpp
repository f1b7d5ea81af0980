// SPDX-License-Identifier: MIT
#pragma once

#include <functional>

#include "sparsedyn/statistics.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {

/// What the World tells the outside about its run: the collision and segment callbacks, the
/// statistics, and the deepest overlap seen at any processed event.
class Observers {
 public:
  Statistics& stats() { return stats_; }
  const Statistics& stats() const { return stats_; }

  void OnCollision(std::function<void(const CollisionEvent&)> callback) {
    on_collision_ = std::move(callback);
  }
  void OnSegment(std::function<void(const MotionSegment&)> callback) {
    on_segment_ = std::move(callback);
  }
  /// Whether anyone listens (so that an event builds its report only then).
  bool WantsCollisions() const { return static_cast<bool>(on_collision_); }
  bool WantsSegments() const { return static_cast<bool>(on_segment_); }
  void Collision(const CollisionEvent& event) const { on_collision_(event); }
  void Segment(const MotionSegment& segment) const { on_segment_(segment); }

  /// Notes the gap (negative: an overlap) of a contact being processed, whose contact band is
  /// `band` (contact_tolerance times the radii): an overlap deeper than the band breaks the
  /// no-penetration invariant, and the first such one is kept for the event loop to report.
  void NotePenetration(double gap, double band) {
    if (-gap > max_penetration_) max_penetration_ = -gap;
    if (-gap > band && !breached_) {
      breached_ = true;
      breach_depth_ = -gap;
      breach_band_ = band;
    }
  }
  double MaxPenetration() const { return max_penetration_; }
  /// Whether some contact overlapped beyond its band; then how deep, and the band.
  bool Breached() const { return breached_; }
  double BreachDepth() const { return breach_depth_; }
  double BreachBand() const { return breach_band_; }

 private:
  Statistics stats_;
  std::function<void(const CollisionEvent&)> on_collision_;
  std::function<void(const MotionSegment&)> on_segment_;
  double max_penetration_ = 0.0;
  bool breached_ = false;
  double breach_depth_ = 0.0;
  double breach_band_ = 0.0;
};

}  // namespace sparsedyn
