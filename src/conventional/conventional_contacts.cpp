// SPDX-License-Identifier: MIT
// What the conventional method measures and how it responds: closest features of a pair at a
// time on the bodies' paths, a body's nearest vertex to a wall, and the World's impulse.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "conventional/conventional_impl.hpp"
#include "dynamics/rigid_collision.hpp"

namespace sparsedyn {
namespace {

std::uint64_t PairKey(std::uint32_t a, std::uint32_t b) {
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

}  // namespace

ClosestFeatures ConventionalWorld::Impl::PairFeatures(std::uint32_t a, std::uint32_t b, double t) {
  // Warm-started from the pair's last answer: coherence makes the walk a few steps long.
  std::optional<FeaturePair> warm;
  const auto cached = feature_cache_.find(PairKey(a, b));
  if (cached != feature_cache_.end()) warm = cached->second;
  const ClosestFeatures f =
      FindClosestFeatures(*ShapeOf(a).tracked, bodies_[a].path.PoseAt(t), *ShapeOf(b).tracked,
                          bodies_[b].path.PoseAt(t), warm);
  if (f.status == ClosestFeatures::Status::kIterationCap) ++stats_.walk_cap_hits;
  feature_cache_[PairKey(a, b)] = f.features;
  return f;
}

double ConventionalWorld::Impl::WallGap(std::uint32_t i, int wall, double t) const {
  const WallPlane plane = BoxWall(settings_.container, wall);
  const Vec3& n = plane.normal;
  const double offset = plane.offset;
  const Pose pose = bodies_[i].path.PoseAt(t);
  const ConvexPolyhedron& polyhedron = *ShapeOf(i).polyhedron;
  const Vec3 n_B = pose.rotation.conjugate() * n;
  return n.dot(pose.ToWorld(polyhedron.vertex(polyhedron.SupportVertex(-n_B)))) - offset;
}

void ConventionalWorld::Impl::SetMotion(std::uint32_t i, double t, const Vec3& v,
                                        const Vec3& omega) {
  RigidPath& path = bodies_[i].path;
  path = path.RebasedAt(t);
  path.centre.v0 = v;
  path.omega = omega;
  ++bodies_[i].version;
}

bool ConventionalWorld::Impl::ResolvePair(std::uint32_t a, std::uint32_t b, double t) {
  ++stats_.narrow_queries;
  const ClosestFeatures features = PairFeatures(a, b, t);
  const RigidPath& path_a = bodies_[a].path;
  const RigidPath& path_b = bodies_[b].path;
  const Pose pose_a = path_a.PoseAt(t);
  const Pose pose_b = path_b.PoseAt(t);
  const ContactGeometry contact =
      ContactFromFeatures(*ShapeOf(a).polyhedron, pose_a, *ShapeOf(b).polyhedron, pose_b, features,
                          PairTolerance(a, b));
  RigidBodyState body_a{pose_a.translation, path_a.centre.VelocityAt(t), path_a.omega,
                        bodies_[a].inv_mass, InvInertiaWorld(a, pose_a.rotation)};
  RigidBodyState body_b{pose_b.translation, path_b.centre.VelocityAt(t), path_b.omega,
                        bodies_[b].inv_mass, InvInertiaWorld(b, pose_b.rotation)};
  // The World's response: restitution product, friction sqrt(mu_a mu_b).
  RigidImpulseOptions options;
  options.restitution = bodies_[a].restitution * bodies_[b].restitution;
  options.friction = std::sqrt(bodies_[a].friction * bodies_[b].friction);
  options.elastic_below_speed = settings_.elastic_below_speed;
  const RigidImpulseResult result = ApplyRigidImpulse(body_a, body_b, contact, options);
  if (result.rounds == 0) return false;
  SetMotion(a, t, body_a.velocity, body_a.angular_velocity);
  SetMotion(b, t, body_b.velocity, body_b.angular_velocity);
  ++stats_.collisions;
  if (on_collision_) {
    on_collision_(CollisionEvent{t, BodyId{a, 0}, BodyId{b, 0}, -1, result.point, contact.normal,
                                 result.normal_impulse});
  }
  return true;
}

bool ConventionalWorld::Impl::ResolveWall(std::uint32_t i, int wall, double t) {
  const WallPlane plane = BoxWall(settings_.container, wall);
  const Vec3& n = plane.normal;
  const double offset = plane.offset;
  const RigidPath& path = bodies_[i].path;
  const Pose pose = path.PoseAt(t);
  const ConvexPolyhedron& polyhedron = *ShapeOf(i).polyhedron;
  const double tolerance = WallTolerance(i);

  // The contact: the vertices within the band above the nearest one (a vertex, an edge or a
  // face on the wall), ordered around their mean so that a face's vertices form its polygon.
  std::vector<Vec3> vertices(static_cast<std::size_t>(polyhedron.vertex_count()));
  double nearest = kInfinity;
  for (int v = 0; v < polyhedron.vertex_count(); ++v) {
    vertices[static_cast<std::size_t>(v)] = pose.ToWorld(polyhedron.vertex(v));
    nearest = std::min(nearest, n.dot(vertices[static_cast<std::size_t>(v)]) - offset);
  }
  ContactGeometry contact;
  contact.normal = -n;  // from the body towards the wall
  contact.distance = nearest;
  for (const Vec3& x : vertices) {
    if (n.dot(x) - offset <= nearest + tolerance) contact.points.push_back(x);
  }
  if (contact.points.size() > 2) {
    const Vec3 mean =
        std::accumulate(contact.points.begin(), contact.points.end(), Vec3(Vec3::Zero())) /
        static_cast<double>(contact.points.size());
    const Vec3 u = n.unitOrthogonal();
    const Vec3 w = n.cross(u);
    auto angle = [&](const Vec3& p) { return std::atan2((p - mean).dot(w), (p - mean).dot(u)); };
    std::sort(contact.points.begin(), contact.points.end(),
              [&](const Vec3& p, const Vec3& q) { return angle(p) < angle(q); });
  }

  RigidBodyState body{pose.translation, path.centre.VelocityAt(t), path.omega, bodies_[i].inv_mass,
                      InvInertiaWorld(i, pose.rotation)};
  RigidBodyState static_wall;  // no mass to move
  static_wall.centre = contact.points.front();
  RigidImpulseOptions options;
  options.restitution = bodies_[i].restitution;
  options.friction = bodies_[i].friction;
  options.elastic_below_speed = settings_.elastic_below_speed;
  const RigidImpulseResult result = ApplyRigidImpulse(body, static_wall, contact, options);
  if (result.rounds == 0) return false;
  SetMotion(i, t, body.velocity, body.angular_velocity);
  ++stats_.wall_collisions;
  if (on_collision_) {
    on_collision_(CollisionEvent{t, BodyId{i, 0}, BodyId{}, wall, result.point, contact.normal,
                                 result.normal_impulse});
  }
  return true;
}

}  // namespace sparsedyn
