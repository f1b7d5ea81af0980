// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/narrow/closest_features.hpp"
#include "sparsedyn/result.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {

/// A polyhedral shape as the World uses it, shared by every body of that shape.
struct BodyShape {
  std::shared_ptr<const ConvexPolyhedron> given;       // BodyDef::shape (keeps its address)
  std::shared_ptr<const ConvexPolyhedron> polyhedron;  // centroid at the body-frame origin
  std::shared_ptr<const TrackedPolyhedron> tracked;    // the walk's tables
  Eigen::Matrix3d unit_inertia;      // inertia per unit mass, body frame (RotationModel)
  Eigen::Matrix3d unit_inv_inertia;  // its inverse
};

/// The distinct polyhedra of a World, each built once (recentred, with the walk's tables and
/// the inertia its rotation model gives it), found again by the address of the given shape.
class ShapeTable {
 public:
  explicit ShapeTable(RotationModel model) : model_(model) {}

  /// The index of `shape` if it is there.
  std::optional<std::uint32_t> Find(const ConvexPolyhedron* shape) const {
    const auto found = index_.find(shape);
    if (found == index_.end()) return std::nullopt;
    return found->second;
  }
  /// `shape` built for the World (recentred, with the walk's tables and the inertia of the
  /// rotation model), not yet added. Refused when its inertia tensor is singular.
  Result<BodyShape> Build(const std::shared_ptr<const ConvexPolyhedron>& shape) const;
  /// Adds a built shape (one not there yet); returns its index.
  std::uint32_t Insert(BodyShape shape);
  const BodyShape& operator[](std::uint32_t s) const { return shapes_[s]; }
  std::size_t size() const { return shapes_.size(); }

 private:
  RotationModel model_;
  std::vector<BodyShape> shapes_;
  std::map<const ConvexPolyhedron*, std::uint32_t> index_;  // as given in BodyDef::shape
};

}  // namespace sparsedyn
