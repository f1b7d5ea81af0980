// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "broadphase/overlap_index.hpp"
#include "sparsedyn/result.hpp"
#include "sparsedyn/world.hpp"
#include "world/shape_table.hpp"
#include "world/world_core.hpp"

namespace sparsedyn {

/// Checks a thrust schedule: times finite and strictly increasing, none before `now`, thrusts
/// finite; the error starts with `body` and names the change.
std::optional<Error> CheckSchedule(const std::vector<ThrustChange>& schedule, double now,
                                   const std::string& body);

/// The checks a body passes before the World takes it (AddBody): every value finite and in
/// range, inside the container, and apart from the bodies already there. Nothing is changed by
/// a refusal; the error names the body and the field.
class Admission {
 public:
  explicit Admission(WorldCore& core)
      : core_(core), overlap_index_(core.settings.container.lo, core.period) {}

  /// What an accepted body brings: its shape (an index into the World's shapes, or a shape
  /// built for it and not added yet; none for a sphere) and its element radius.
  struct Accepted {
    std::uint32_t shape = kNoIndex;
    std::optional<BodyShape> new_shape;
    double radius = 0.0;
  };
  /// Checks `def` as body `index` (public slot `slot`), with the World started or not.
  Result<Accepted> Check(const BodyDef& def, std::uint32_t slot, bool started) const;
  /// Checks that element i (public slot `slot`) may be placed at `position` with
  /// `orientation` now: inside the container, apart from every other body.
  Status CheckPose(std::uint32_t i, std::uint32_t slot, const Vec3& position,
                   const Eigen::Quaterniond& orientation, bool started) const;
  /// A god object's maximum acceleration and track (ValidateGodTrack, no magnitude beyond
  /// 1e100, not before the clock); the error starts with `body`.
  std::optional<Error> CheckGodTrack(const GodDef& god, const std::string& body) const;
  /// A body accepted before the start, at `position` with element radius `radius`.
  void NoteAdded(const Vec3& position, double radius) { overlap_index_.Add(position, radius); }
  /// The start: the index is no longer needed.
  void Clear() { overlap_index_.Clear(); }
  /// Before the start, after a removal: the index again from the bodies there are.
  void Rebuild();

 private:
  /// A body placed at a pose: its shape (null for a sphere) and element radius.
  struct Placement {
    Vec3 position;
    Eigen::Quaterniond orientation;
    const BodyShape* shape;
    double radius;
    bool is_static = false;  // may touch other bodies (not overlap them)
    bool is_god = false;     // may overlap other god objects and statics
  };
  /// Drag where it is not supported yet (a polyhedron, a static body, a god object, an envelope
  /// of its own, a World with polyhedra, static bodies or god objects) or without the contact
  /// band it needs.
  std::optional<Error> CheckDragCombination(const BodyDef& def, const std::string& body) const;
  /// What a static body may not have (a motion of any kind, an envelope, a periodic box).
  std::optional<Error> CheckStatic(const BodyDef& def, const std::string& body) const;
  /// A god object's definition: its track (ValidateGodTrack, not before the clock) and what it
  /// may not have (thrust, an envelope, a spin, static, a periodic box).
  std::optional<Error> CheckGod(const BodyDef& def, const std::string& body) const;
  /// The static bodies `placement` overlaps (touching is allowed with a static).
  std::optional<Error> CheckApartFromStatics(const Placement& placement,
                                             const std::string& body) const;
  std::optional<Error> CheckInside(const Placement& placement, const std::string& body) const;
  std::optional<Error> CheckApart(const Placement& placement, std::uint32_t exclude, bool started,
                                  const std::string& body) const;
  /// Calls fn(j, position, orientation) for the elements j != exclude that may be within
  /// `reach` of p now (before the start: through the overlap index).
  template <typename Fn>
  void ForEachNear(const Vec3& p, double reach, std::uint32_t exclude, bool started,
                   Fn&& fn) const;

  WorldCore& core_;
  OverlapIndex overlap_index_;  // bodies added before the start, for the overlap check
};

}  // namespace sparsedyn
