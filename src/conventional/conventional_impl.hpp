// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "conventional/sweep_and_prune.hpp"
#include "motion/rigid_path.hpp"
#include "sparsedyn/conventional.hpp"
#include "sparsedyn/narrow/closest_features.hpp"
#include "world/box_walls.hpp"

namespace sparsedyn {

/// A collision detected in the current step and located in time.
struct ConventionalCandidate {
  double time = 0;
  std::uint32_t a = 0;
  std::uint32_t b = kNoIndex;  // kNoIndex: the wall `wall`
  int wall = -1;
};

/// The state of a ConventionalWorld. Split over conventional_world.cpp (API, input checks,
/// energy), conventional_step.cpp (a step: detect, locate, resolve in time order) and
/// conventional_contacts.cpp (distances, walls and the impulse).
class ConventionalWorld::Impl {
 public:
  Impl(const WorldSettings& settings, const ConventionalSettings& conventional)
      : settings_(settings), conventional_(conventional) {}

  // --- API and checks (conventional_world.cpp) ---
  Result<BodyId> AddBody(const BodyDef& def);
  Status AdvanceTo(double t);
  double KineticEnergy() const;
  Vec3 Momentum() const;

  struct Shape {                                         // shared by every body of that shape
    std::shared_ptr<const ConvexPolyhedron> polyhedron;  // centroid at the body-frame origin
    std::shared_ptr<const TrackedPolyhedron> tracked;
    Eigen::Matrix3d unit_inertia;  // per unit mass, body frame (RotationModel)
    Eigen::Matrix3d unit_inv_inertia;
  };
  struct Body {
    RigidPath path;  // the current segment; a collision starts a new one
    std::uint32_t shape = 0;
    double radius = 0;  // bounding radius about the centroid
    double inv_mass = 0;
    double restitution = 1;
    double friction = 0;
    std::uint32_t version = 0;  // path changes (collisions) so far
  };
  using Candidate = ConventionalCandidate;

  WorldSettings settings_;
  ConventionalSettings conventional_;
  ConventionalStatistics stats_;
  std::function<void(const CollisionEvent&)> on_collision_;
  double now_ = 0;
  bool started_ = false;
  std::vector<Shape> shapes_;
  std::map<const ConvexPolyhedron*, std::uint32_t> shape_index_;  // as given in BodyDef::shape
  std::vector<Body> bodies_;
  SweepAndPrune sweep_;
  std::unordered_map<std::uint64_t, FeaturePair> feature_cache_;  // warm starts per pair

  const Shape& ShapeOf(std::uint32_t i) const { return shapes_[bodies_[i].shape]; }
  Eigen::Matrix3d InvInertiaWorld(std::uint32_t i, const Eigen::Quaterniond& q) const {
    const Eigen::Matrix3d r = q.toRotationMatrix();
    return bodies_[i].inv_mass * r * ShapeOf(i).unit_inv_inertia * r.transpose();
  }
  double PairTolerance(std::uint32_t a, std::uint32_t b) const {
    return settings_.contact_tolerance * (bodies_[a].radius + bodies_[b].radius);
  }
  double WallTolerance(std::uint32_t i) const {
    return settings_.contact_tolerance * bodies_[i].radius;
  }
  bool Walled() const { return settings_.container.kind == Container::Kind::kWalledBox; }

  // --- a step (conventional_step.cpp) ---
  Status Step(double t0, double t1);
  void DetectAtStepEnd(double t0, double t1, std::vector<Candidate>& found);
  void RecheckBody(std::uint32_t i, std::uint32_t other, double t0, double t1,
                   std::vector<Candidate>& found);
  std::optional<Candidate> LocatePair(std::uint32_t a, std::uint32_t b, double t0, double t1);
  std::optional<Candidate> LocateWall(std::uint32_t i, int wall, double t0, double t1);

  // --- geometry and response (conventional_contacts.cpp) ---
  ClosestFeatures PairFeatures(std::uint32_t a, std::uint32_t b, double t);
  double WallGap(std::uint32_t i, int wall, double t) const;
  bool ResolvePair(std::uint32_t a, std::uint32_t b, double t);
  bool ResolveWall(std::uint32_t i, int wall, double t);
  void SetMotion(std::uint32_t i, double t, const Vec3& v, const Vec3& omega);
  void NotePenetration(double gap) {
    stats_.max_penetration = std::max(stats_.max_penetration, -gap);
  }
};

}  // namespace sparsedyn
