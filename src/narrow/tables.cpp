// SPDX-License-Identifier: MIT
#include "narrow/tables.hpp"

#include <utility>

#include "sparsedyn/assert.hpp"

namespace sparsedyn {

TrackedPolyhedron::Tables::Tables(const ConvexPolyhedron& polyhedron)
    : face_slot_(static_cast<std::size_t>(polyhedron.face_count()), -1),
      vertex_slot_(static_cast<std::size_t>(polyhedron.vertex_count()), -1),
      directions_(polyhedron) {
  for (int f = 0; f < polyhedron.face_count(); ++f) {
    if (auto table = narrow::BuildFaceAngleTable(polyhedron, f)) {
      face_slot_[static_cast<std::size_t>(f)] = static_cast<std::int32_t>(face_tables_.size());
      face_tables_.push_back(std::move(*table));
    }
  }
  for (int v = 0; v < polyhedron.vertex_count(); ++v) {
    if (auto table = narrow::BuildVertexAngleTable(polyhedron, v)) {
      vertex_slot_[static_cast<std::size_t>(v)] = static_cast<std::int32_t>(vertex_tables_.size());
      vertex_tables_.push_back(std::move(*table));
    }
  }
}

TrackedPolyhedron::TrackedPolyhedron(std::shared_ptr<const ConvexPolyhedron> polyhedron)
    : polyhedron_(std::move(polyhedron)) {
  SPARSEDYN_ASSERT(polyhedron_ != nullptr, "TrackedPolyhedron needs a polyhedron");
  tables_ = std::make_unique<Tables>(*polyhedron_);
}

TrackedPolyhedron::~TrackedPolyhedron() = default;
TrackedPolyhedron::TrackedPolyhedron(TrackedPolyhedron&&) noexcept = default;
TrackedPolyhedron& TrackedPolyhedron::operator=(TrackedPolyhedron&&) noexcept = default;

FeatureId TrackedPolyhedron::StartingFeature(const Eigen::Vector3d& direction_B) const {
  return FeatureId::Vertex(tables_->directions().VertexFor(direction_B));
}

int TrackedPolyhedron::SupportVertex(const Eigen::Vector3d& direction_B) const {
  return polyhedron_->SupportVertexFrom(direction_B, tables_->directions().VertexFor(direction_B));
}

}  // namespace sparsedyn
