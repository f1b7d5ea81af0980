// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "motion/rigid_path.hpp"
#include "sparse/mover.hpp"
#include "sparsedyn/types.hpp"
#include "sparsedyn/world.hpp"
#include "world/body_ids.hpp"
#include "world/body_materials.hpp"
#include "world/element_paths.hpp"
#include "world/god_bodies.hpp"
#include "world/rigid_bodies.hpp"
#include "world/static_bodies.hpp"
#include "world/thrust_schedules.hpp"

namespace sparsedyn {

/// The envelopes of the bodies (App. F): empty until some body has one.
class Envelopes {
 public:
  /// Whether some body has an envelope (its own, or its drag segment's).
  bool Any() const { return any_; }
  /// Whether some body has an envelope of its own (BodyDef::envelope), which grows without
  /// bound; a drag segment's stays below its limit (DragMotions::MaxError).
  bool AnyOwn() const { return any_own_; }
  const Envelope& Of(std::uint32_t i) const { return of_[i]; }
  void Append(std::uint32_t index, const Envelope& envelope) {
    if (!envelope.IsZero() && !any_) {
      any_ = true;
      of_.resize(index);
    }
    any_own_ = any_own_ || !envelope.IsZero();
    if (any_) of_.push_back(envelope);
  }
  /// Body i's envelope is a drag segment's from now on.
  void SetDrag(std::uint32_t i, const Envelope& envelope, std::size_t count) {
    if (!any_) {
      any_ = true;
      of_.resize(count);
    }
    of_[i] = envelope;
  }
  template <typename PermuteFn>
  void Permute(PermuteFn&& permute) {
    if (any_) permute(of_);
  }
  std::size_t MemoryBytes() const { return of_.capacity() * sizeof(Envelope); }

 private:
  bool any_ = false;
  bool any_own_ = false;
  std::vector<Envelope> of_;
};

/// Every body's state between events, per element (structure of arrays): its path, material,
/// rotation (polyhedra), envelope and public id. The parts that predict and handle events read
/// it; the path changes (world/path_changes.hpp) write it.
struct BodyStore {
  explicit BodyStore(const WorldSettings& settings)
      : paths(settings.gravity), rigid(settings.rotation_model) {}

  std::uint32_t Size() const { return paths.Size(); }

  /// Body i's element sphere (its envelope included) seen at time t.
  Mover MoverOf(std::uint32_t i, double t) const {
    if (envelopes.Any()) return MoverAt(paths.PathOf(i), materials.Radius(i), envelopes.Of(i), t);
    return MoverAt(paths.PathOf(i), materials.Radius(i), t);
  }
  /// The body itself (its sphere without envelope) seen at time t.
  Mover BodyMoverOf(std::uint32_t i, double t) const {
    return MoverAt(paths.PathOf(i), materials.Radius(i), t);
  }
  /// Whether some pair of elements engages when they meet (Engages): else no engagement
  /// can exist, and the hot paths skip looking for one.
  bool EngagesOnMeet() const {
    return envelopes.AnyOwn() || rigid.AnyPolyhedron() || !statics.Empty() || gods.Any();
  }
  /// Whether every element is a sphere without an envelope on a straight line, and nothing
  /// changes a path but collisions.
  bool AllOnStraightLines() const {
    const Accelerations& a = paths.accelerations();
    return !envelopes.Any() && !paths.drags().Any() && !rigid.AnyPolyhedron() &&
           !thrusts.Any() && !gods.Any() && a.Uniform() && a.UniformValue().isZero(0.0);
  }
  /// Whether body i has drag: its element follows a Taylor path within an envelope of its true
  /// motion (ElementPaths::TruePositionAt), renewed at each of its events.
  bool HasDrag(std::uint32_t i) const { return paths.drags().Has(i); }
  /// Body i's new drag segment from its path start (just set to its true state): the
  /// DragMotion, the Taylor path and the envelope of its element. Body i has drag.
  void StartDragSegment(std::uint32_t i) { envelopes.SetDrag(i, paths.StartDrag(i), Size()); }

  RigidPath RigidPathOf(std::uint32_t i) const {
    return RigidPath{paths.PathOf(i), rigid.Orientation0(i), rigid.Omega(i)};
  }
  /// Body i's rigid path as the contact handlers see it now: its own, or for a body with drag
  /// the path through its true state now (exact at now, its Taylor acceleration after).
  RigidPath RigidPathNow(std::uint32_t i) const {
    RigidPath path = RigidPathOf(i);
    if (!HasDrag(i)) return path;
    const double now = paths.Now();
    const DragState state = paths.drags().StateAt(i, now);
    return RigidPath{Path{state.position, state.velocity, path.centre.a, now},
                     path.OrientationAt(now), path.omega};
  }
  /// A bound on |acceleration| of body i's true motion from now until its path changes.
  double AccelerationBound(std::uint32_t i) const {
    return HasDrag(i) ? paths.drags().AccelerationBound(i) : paths.PathOf(i).a.norm();
  }
  bool IsPolyhedron(std::uint32_t i) const { return rigid.IsPolyhedron(i); }
  bool IsGod(std::uint32_t i) const { return gods.IsGod(i); }
  /// Whether body i has an envelope of its own (not a drag segment's).
  bool HasEnvelope(std::uint32_t i) const {
    return envelopes.AnyOwn() && !envelopes.Of(i).IsZero() && !HasDrag(i);
  }
  /// Whether the element spheres of i and j, when they meet, are engaged and watched by the
  /// detailed phase (a polyhedron, or a sphere whose envelope is wider than the body); else
  /// the meeting is the contact of two spheres (with drag: the sparse phase predicted the
  /// contact on the true motions, world/drag_contacts.hpp). Two god objects are engaged too,
  /// in a pair that never touches (PairKind::kInert), so that the sparse phase skips them
  /// while their spheres overlap.
  bool Engages(std::uint32_t i, std::uint32_t j) const {
    return IsPolyhedron(i) || IsPolyhedron(j) || HasEnvelope(i) || HasEnvelope(j) ||
           (IsGod(i) && IsGod(j));
  }
  /// Body i's inertia per unit mass in its body frame (a solid sphere: 2/5 r^2).
  Eigen::Matrix3d UnitInertia(std::uint32_t i) const {
    if (IsPolyhedron(i)) return rigid.ShapeOf(i).unit_inertia;
    const double r = materials.Radius(i);
    return Eigen::Matrix3d((0.4 * r * r) * Eigen::Matrix3d::Identity());
  }
  /// Inverse inertia of body i in the world frame at orientation q.
  Eigen::Matrix3d InvInertiaWorld(std::uint32_t i, const Eigen::Quaterniond& q) const {
    if (!IsPolyhedron(i)) {
      const double r = materials.Radius(i);
      return Eigen::Matrix3d((materials.InvMass(i) / (0.4 * r * r)) * Eigen::Matrix3d::Identity());
    }
    const Eigen::Matrix3d r = q.toRotationMatrix();
    return materials.InvMass(i) * r * rigid.ShapeOf(i).unit_inv_inertia * r.transpose();
  }
  /// narrow::SpinRadius of body i's current segment.
  double SpinRadiusOf(std::uint32_t i) const;
  /// The largest acceleration of any surface point of the first `count` bodies on their free
  /// paths (m/s^2): the free acceleration plus the turning's centripetal |omega|^2 r. What
  /// presses bodies back into a contact they touch, without gravity too.
  double MaxSurfaceAcceleration(std::uint32_t count) const;

  /// Renumbers the elements: new element e is old element old_of_new[e].
  void Permute(const std::vector<std::uint32_t>& old_of_new);
  std::size_t MemoryBytes() const;

  ElementPaths paths;
  BodyMaterials materials;
  RigidBodies rigid;
  Envelopes envelopes;
  ThrustSchedules thrusts;
  GodBodies gods;
  BodyIds ids;
  StaticBodies statics;  // not elements: no path, no queue entry
};

/// Reorders `values` so that new entry e is old entry old_of_new[e], with the exact capacity
/// (a run's memory is part of its cost).
template <typename Vector>
void PermuteVector(Vector& values, const std::vector<std::uint32_t>& old_of_new) {
  Vector permuted;
  permuted.reserve(values.size());
  for (const std::uint32_t old : old_of_new) permuted.push_back(values[old]);
  values.swap(permuted);
}

}  // namespace sparsedyn
