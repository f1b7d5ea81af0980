// SPDX-License-Identifier: MIT
// The ConventionalWorld's API: settings and body checks, the step loop, energy and momentum.
#include <cmath>
#include <string>

#include "base/format.hpp"
#include "conventional/conventional_impl.hpp"
#include "world/body_checks.hpp"

namespace sparsedyn {
namespace {

// A body definition on its own: the World's checks of its values, and what the conventional
// method simulates (polyhedra on exact paths).
Status CheckBody(const BodyDef& def, std::size_t index, const std::string& body) {
  if (def.shape == nullptr) {
    return Error{body + "the conventional method simulates polyhedra only (no shape given)"};
  }
  if (def.is_static) {
    return Error{body + "the conventional method has no static bodies (every body moves)"};
  }
  if (def.god) {
    return Error{body + "the conventional method has no god objects (every body is free)"};
  }
  if (std::optional<Error> error = CheckBodyValues(def, index)) return *error;
  if (!def.envelope.IsZero()) {
    return Error{body + "envelopes are for spheres; a polyhedron's path is exact"};
  }
  return Status::Ok();
}

}  // namespace

Status ConventionalWorld::CheckSettings(const WorldSettings& settings,
                                        const ConventionalSettings& conventional) {
  if (!std::isfinite(conventional.dt) || conventional.dt <= 0) {
    return Error{"the conventional method needs a time step dt > 0, got " +
                 FormatExact(conventional.dt)};
  }
  if (conventional.digits < 0 || conventional.digits > 15) {
    return Error{"digits must be in [0, 15], got " + std::to_string(conventional.digits)};
  }
  if (settings.container.kind == Container::Kind::kPeriodicBox) {
    return Error{
        "the conventional method supports open space and walled boxes, not periodic boxes"};
  }
  return Status::Ok();
}

Result<BodyId> ConventionalWorld::Impl::AddBody(const BodyDef& def) {
  const auto index = static_cast<std::uint32_t>(bodies_.size());
  const std::string body = "body " + std::to_string(index) + ": ";
  if (started_) return Error{body + "bodies are added before the first AdvanceTo"};
  if (Status ok = CheckBody(def, index, body); !ok) return ok.error();

  // The shape, placed by its centroid and shared by the bodies that share the given pointer.
  std::uint32_t shape = 0;
  if (auto found = shape_index_.find(def.shape.get()); found != shape_index_.end()) {
    shape = found->second;
  } else {
    Shape s;
    s.polyhedron = def.shape;
    if (def.shape->centroid().norm() > 1e-12 * def.shape->scale()) {
      s.polyhedron = std::make_shared<const ConvexPolyhedron>(def.shape->Recentered());
    }
    s.tracked = std::make_shared<const TrackedPolyhedron>(s.polyhedron);
    const Eigen::Matrix3d unit = s.polyhedron->inertia() / s.polyhedron->volume();
    s.unit_inertia = settings_.rotation_model == RotationModel::kSphericalTop
                         ? Eigen::Matrix3d((unit.trace() / 3.0) * Eigen::Matrix3d::Identity())
                         : unit;
    s.unit_inv_inertia = s.unit_inertia.inverse();
    if (!s.unit_inv_inertia.allFinite()) return Error{body + "degenerate polyhedron"};
    shape = static_cast<std::uint32_t>(shapes_.size());
    shapes_.push_back(std::move(s));
    shape_index_.emplace(def.shape.get(), shape);
  }

  Body b;
  b.path.centre = Path{def.position, def.velocity, settings_.gravity + def.thrust, now_};
  b.path.q0 = def.orientation.normalized();
  b.path.omega = def.angular_velocity;
  b.shape = shape;
  b.radius = shapes_[shape].polyhedron->bounding_radius();
  b.inv_mass = 1.0 / def.mass;
  b.restitution = def.restitution;
  b.friction = def.friction;

  // Inside the walls and apart from every body already there (O(N) per body: set-up only).
  const Pose pose = b.path.PoseAt(now_);
  const ConvexPolyhedron& polyhedron = *shapes_[shape].polyhedron;
  for (int w = 0; w < 6 && Walled(); ++w) {
    const WallPlane plane = BoxWall(settings_.container, w);
    const Vec3& n = plane.normal;
    const double offset = plane.offset;
    const Vec3 n_B = pose.rotation.conjugate() * n;
    const double gap =
        n.dot(pose.ToWorld(polyhedron.vertex(polyhedron.SupportVertex(-n_B)))) - offset;
    if (gap <= settings_.contact_tolerance * b.radius) {
      return Error{body + "outside the walled box (or touching wall " + std::to_string(w) + ")"};
    }
  }
  for (std::uint32_t j = 0; j < index; ++j) {
    const Pose other = bodies_[j].path.PoseAt(now_);
    const double reach = b.radius + bodies_[j].radius;
    if ((other.translation - pose.translation).squaredNorm() >= reach * reach) continue;
    const ClosestFeatures f = FindClosestFeatures(*shapes_[shape].tracked, pose,
                                                  *shapes_[bodies_[j].shape].tracked, other);
    if (f.distance <= settings_.contact_tolerance * reach) {
      return Error{body + "touches or overlaps body " + std::to_string(j)};
    }
  }
  bodies_.push_back(b);
  return BodyId{index, 0};
}

Status ConventionalWorld::Impl::AdvanceTo(double t) {
  // Checked again here: with asserts off a bad dt would never advance the clock.
  if (Status ok = CheckSettings(settings_, conventional_); !ok) return ok;
  started_ = true;
  const double dt = conventional_.dt;
  while (now_ < t) {
    // Full steps; a sliver shorter than a millionth of a step joins the last one.
    double t1 = now_ + dt;
    if (t1 > t || t - t1 < 1e-6 * dt) t1 = t;
    if (Status ok = Step(now_, t1); !ok) return ok;
    now_ = t1;
    ++stats_.steps;
  }
  return Status::Ok();
}

double ConventionalWorld::Impl::KineticEnergy() const {
  double energy = 0;
  for (std::uint32_t i = 0; i < bodies_.size(); ++i) {
    const Body& b = bodies_[i];
    const Eigen::Matrix3d r = b.path.OrientationAt(now_).toRotationMatrix();
    const Eigen::Matrix3d inertia = r * ShapeOf(i).unit_inertia * r.transpose() / b.inv_mass;
    const Vec3 v = b.path.centre.VelocityAt(now_);
    energy += 0.5 * (v.squaredNorm() / b.inv_mass + b.path.omega.dot(inertia * b.path.omega));
  }
  return energy;
}

Vec3 ConventionalWorld::Impl::Momentum() const {
  Vec3 p = Vec3::Zero();
  for (const Body& b : bodies_) p += b.path.centre.VelocityAt(now_) / b.inv_mass;
  return p;
}

// --- the public class forwards to Impl ---

ConventionalWorld::ConventionalWorld(const WorldSettings& settings,
                                     const ConventionalSettings& conventional)
    : impl_(std::make_unique<Impl>(settings, conventional)) {
  SPARSEDYN_ASSERT(CheckSettings(settings, conventional).ok(),
                   "ConventionalWorld: settings refused by CheckSettings");
}
ConventionalWorld::~ConventionalWorld() = default;
ConventionalWorld::ConventionalWorld(ConventionalWorld&&) noexcept = default;
ConventionalWorld& ConventionalWorld::operator=(ConventionalWorld&&) noexcept = default;

Result<BodyId> ConventionalWorld::AddBody(const BodyDef& def) { return impl_->AddBody(def); }
Status ConventionalWorld::AdvanceTo(double t) { return impl_->AdvanceTo(t); }

BodyState ConventionalWorld::StateAt(BodyId id, double t) const {
  SPARSEDYN_ASSERT(id.index < impl_->bodies_.size(), "StateAt: invalid body");
  const Impl::Body& b = impl_->bodies_[id.index];
  BodyState s;
  s.position = b.path.centre.PositionAt(t);
  s.velocity = b.path.centre.VelocityAt(t);
  s.acceleration = b.path.centre.a;
  s.radius = b.radius;
  s.mass = 1.0 / b.inv_mass;
  s.version = b.version;
  s.orientation = b.path.OrientationAt(t);
  s.angular_velocity = b.path.omega;
  return s;
}

double ConventionalWorld::Time() const { return impl_->now_; }
std::size_t ConventionalWorld::BodyCount() const { return impl_->bodies_.size(); }
const WorldSettings& ConventionalWorld::Settings() const { return impl_->settings_; }
const ConventionalSettings& ConventionalWorld::Conventional() const { return impl_->conventional_; }
void ConventionalWorld::OnCollision(std::function<void(const CollisionEvent&)> callback) {
  impl_->on_collision_ = std::move(callback);
}
const ConventionalStatistics& ConventionalWorld::Stats() const { return impl_->stats_; }
double ConventionalWorld::KineticEnergy() const { return impl_->KineticEnergy(); }
Vec3 ConventionalWorld::Momentum() const { return impl_->Momentum(); }

}  // namespace sparsedyn
