// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "broadphase/overlap_index.hpp"
#include "sparsedyn/result.hpp"
#include "sparsedyn/world.hpp"
#include "world/shape_table.hpp"
#include "world/world_core.hpp"

namespace sparsedyn {

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
  /// Checks `def` as body `index`, with the World started or not.
  Result<Accepted> Check(const BodyDef& def, std::uint32_t index, bool started) const;
  /// A body accepted before the start, at `position` with element radius `radius`.
  void NoteAdded(const Vec3& position, double radius) { overlap_index_.Add(position, radius); }
  /// The start: the index is no longer needed.
  void Clear() { overlap_index_.Clear(); }

 private:
  std::optional<Error> CheckInside(const BodyDef& def, const BodyShape* shape, double radius,
                                   const std::string& body) const;
  std::optional<std::uint32_t> FindOverlap(const Vec3& p, double radius, bool started) const;
  std::optional<std::uint32_t> FindPolyhedronOverlap(const BodyDef& def, const BodyShape& shape,
                                                     double& distance) const;

  WorldCore& core_;
  OverlapIndex overlap_index_;  // bodies added before the start, for the overlap check
};

}  // namespace sparsedyn
