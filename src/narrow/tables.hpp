// SPDX-License-Identifier: MIT
// The per-polyhedron tables of TrackedPolyhedron: J.1.1 angle tables of the faces and vertices
// with many edges and the J.1.2 direction table.
#pragma once

#include <cstdint>
#include <vector>

#include "narrow/angle_tables.hpp"
#include "narrow/direction_table.hpp"
#include "sparsedyn/narrow/closest_features.hpp"

namespace sparsedyn {

class TrackedPolyhedron::Tables {
 public:
  explicit Tables(const ConvexPolyhedron& polyhedron);

  /// The J.1.1 table of face f / vertex v, or nullptr when it has too few edges (or, for a
  /// vertex, a cone too wide for a central projection).
  /// Inline: the walk asks for them at every zone test.
  const narrow::FaceAngleTable* face(int f) const {
    const std::int32_t slot = face_slot_[static_cast<std::size_t>(f)];
    return slot < 0 ? nullptr : &face_tables_[static_cast<std::size_t>(slot)];
  }
  const narrow::VertexAngleTable* vertex(int v) const {
    const std::int32_t slot = vertex_slot_[static_cast<std::size_t>(v)];
    return slot < 0 ? nullptr : &vertex_tables_[static_cast<std::size_t>(slot)];
  }
  const narrow::DirectionTable& directions() const { return directions_; }

  int face_table_count() const { return static_cast<int>(face_tables_.size()); }
  int vertex_table_count() const { return static_cast<int>(vertex_tables_.size()); }

 private:
  std::vector<std::int32_t> face_slot_, vertex_slot_;  // -1: no table
  std::vector<narrow::FaceAngleTable> face_tables_;
  std::vector<narrow::VertexAngleTable> vertex_tables_;
  narrow::DirectionTable directions_;
};

}  // namespace sparsedyn
