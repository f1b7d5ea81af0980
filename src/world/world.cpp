// SPDX-License-Identifier: MIT
// The World's API: adding bodies, the start, states, energies and momenta, and the forwarding
// from World to its Impl.
#include <algorithm>
#include <bit>
#include <cmath>

#include "world/body_checks.hpp"
#include "world/world_impl.hpp"

namespace sparsedyn {

const char* EventKindName(int k) { return kEventKindNames.at(static_cast<std::size_t>(k)).data(); }

World::Impl::Impl(const WorldSettings& settings)
    : core_(settings),
      detailed_(core_, sparse_),
      sparse_(core_, detailed_.engagements()),
      changes_(core_, sparse_),
      spheres_(core_, sparse_, detailed_, changes_),
      polyhedra_(core_, sparse_, detailed_, changes_),
      mixed_(core_, sparse_, detailed_, changes_),
      statics_(core_, sparse_, detailed_, changes_),
      walls_(core_, sparse_, detailed_, changes_),
      memory_(core_, sparse_, detailed_),
      look_ahead_(core_.bodies.paths, sparse_),
      admission_(core_) {
  core_.bodies.paths.SetNow(settings.start_time);
  sparse_.SetWalls(&walls_);
  detailed_.SetModels(&spheres_, &polyhedra_, &mixed_, &statics_);
}

Result<BodyId> World::Impl::AddBody(const BodyDef& def) {
  BodyStore& bodies = core_.bodies;
  const std::uint32_t index = bodies.Size();
  Result<Admission::Accepted> accepted = admission_.Check(def, index, started_);
  if (!accepted) return accepted.error();

  // Accepted: from here on nothing can fail.
  if (def.is_static) return AddStatic(def, *accepted);
  const double radius = accepted->radius;
  const double now = core_.Now();
  // Rotation is tracked from the first body whose rotation matters: a polyhedron, or a sphere
  // that spins or rubs (friction). A gas of frictionless spheres keeps no rotation at all.
  if (def.shape != nullptr || !def.angular_velocity.isZero(0.0) || def.friction > 0) {
    bodies.rigid.Track(index);
  }
  // A god object follows its plan from here (not gravity): its path is the plan's piece now,
  // and its mass is infinite to every other body.
  std::optional<GodBodies::God> god;
  if (def.god) {
    god.emplace(GodBodies::God{*def.god, GodPlan(now, def.position, def.velocity, def.god->track,
                                                 def.god->max_acceleration)});
  }
  bodies.paths.Append(PathStart{def.position, def.velocity, now},
                      god ? god->Follow(now).a : core_.settings.gravity + def.thrust);
  if (!started_) admission_.NoteAdded(def.position, radius);
  bodies.materials.Append(
      Material{radius, god ? 0.0 : 1.0 / def.mass, def.restitution, def.friction});
  if (bodies.rigid.Tracked()) {
    std::uint32_t shape = accepted->shape;
    if (accepted->new_shape) shape = bodies.rigid.shapes().Insert(std::move(*accepted->new_shape));
    bodies.rigid.Append(shape, def.orientation.normalized(), def.angular_velocity);
  }
  bodies.envelopes.Append(index, def.envelope);
  // Drag: the body's true motion and the Taylor path of its element from now on, with an
  // envelope that grows to at most a fraction of its radius.
  const Drag drag = DragOf(def, core_.settings.drag);
  const double drag_error = kDragErrorFraction * radius;
  bodies.paths.drags().Append(index, drag, drag_error);
  if (bodies.HasDrag(index)) bodies.StartDragSegment(index);
  // Its spin radius reads its path, which needs every per-body array (drag's included).
  if (bodies.rigid.Tracked()) bodies.rigid.SetSpinRadius(index, bodies.SpinRadiusOf(index));
  bodies.thrusts.Append(index, def.thrust_schedule);
  bodies.gods.Append(index, std::move(god));
  const BodyId id = bodies.ids.Add(index);
  sparse_.queue().Resize(index + 1);  // the element's slot and prediction
  // The element's largest radius: the grid's cells cover it (a drag segment's envelope too).
  const double element_radius = bodies.HasDrag(index) ? radius + drag_error : radius;
  const bool larger = element_radius > max_radius_;
  max_radius_ = std::max(max_radius_, element_radius);
  if (started_) {
    // A bigger body or the first envelope can change the broad phase, the first body off
    // straight lines (a thrust of its own, an envelope, a polyhedron) ends the fast paths that
    // assume them, and a body that engages must be engaged with every element it overlaps:
    // rebuild.
    if (larger || (bodies.envelopes.AnyOwn() && sparse_.grid()) ||
        (bodies.paths.StraightLines() && !bodies.AllOnStraightLines()) ||
        bodies.IsPolyhedron(index) || bodies.HasEnvelope(index) || bodies.IsGod(index)) {
      Start();
    } else {
      sparse_.AddElement(index);
      memory_.SetPeriod();
    }
  }
  return id;
}

BodyId World::Impl::AddStatic(const BodyDef& def, const Admission::Accepted& accepted) {
  BodyStore& bodies = core_.bodies;
  // A moving body's spin matters against a static (friction, an off-centre push).
  bodies.rigid.Track(bodies.Size());
  StaticBodies::Static body;
  body.radius = accepted.radius;
  body.restitution = def.restitution;
  body.friction = def.friction;
  body.pose.translation = def.position;
  Aabb box = BoxOfSphere(def.position, accepted.radius);
  if (def.shape != nullptr) {
    body.shape = accepted.new_shape ? bodies.rigid.shapes().Insert(*accepted.new_shape)
                                    : accepted.shape;
    body.pose.rotation = def.orientation.normalized();
    box = BoxOfPolyhedron(*bodies.rigid.shapes()[body.shape].polyhedron, body.pose);
  }
  const BodyId id = bodies.ids.AddStatic(StaticBodies::KeyOf(bodies.statics.NextIndex()));
  body.slot = id.index;
  bodies.statics.Add(body, box);
  // Every element may reach it: all predict again (as a World built with it would).
  if (started_) Start();
  return id;
}

BodyState World::Impl::StaticStateAt(std::uint32_t s) const {
  const StaticBodies::Static& body = core_.bodies.statics[s];
  BodyState state;
  state.position = body.pose.translation;
  state.radius = body.radius;
  state.mass = kInfinity;
  state.orientation = body.pose.rotation;
  return state;
}

void World::Impl::Start() {
  started_ = true;
  core_.bodies.statics.tree().Build();
  admission_.Clear();
  BodyStore& bodies = core_.bodies;
  const auto n = bodies.Size();
  const double now = core_.Now();
  ElementQueue& queue = sparse_.queue();
  queue.Clear();
  queue.ShrinkToFit();  // one slot per element, grown one by one by AddBody
  detailed_.Clear();
  // A restart (AddBody while running) predicts every element afresh below: the old predictions
  // go with the cleared queue, which holds no times for them (Reorder would carry them over).
  // The versions stay, as they count each body's path changes.
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t version = sparse_.PredictionOf(i).version;
    sparse_.PredictionOf(i) = Prediction{};
    sparse_.PredictionOf(i).version = version;
  }

  // Rebase every path at the current time so that cells and predictions start from now.
  for (std::uint32_t i = 0; i < n; ++i) {
    if (bodies.rigid.Tracked()) {
      bodies.rigid.SetOrientation0(i, bodies.RigidPathOf(i).OrientationAt(now).normalized());
    }
    if (bodies.HasDrag(i)) {
      // A new drag segment from the true state now (the same motion, the same version).
      const Vec3 p = bodies.paths.TruePositionAt(i, now);
      const Vec3 v = bodies.paths.TrueVelocityAt(i, now);
      bodies.paths.SetStart(i, PathStart{core_.WrapIntoBox(p), v, now});
      bodies.StartDragSegment(i);
      continue;
    }
    const Path path = bodies.paths.PathOf(i).RebasedAt(now);
    bodies.paths.SetStart(i, PathStart{core_.WrapIntoBox(path.p0), path.v0, path.t0});
  }

  bodies.paths.SetStraightLines(bodies.AllOnStraightLines());
  sparse_.Build(max_radius_);
  if (sparse_.grid()) memory_.Reorder();  // start in spatial order
  memory_.Restart();
  if (bodies.EngagesOnMeet()) detailed_.EngageOverlapping();
  for (std::uint32_t i = 0; i < n; ++i) sparse_.PredictFull(i);
}

BodyState World::Impl::StateAt(std::uint32_t i, double t) const {
  const BodyStore& bodies = core_.bodies;
  const Path& path = bodies.paths.PathOf(i);
  BodyState state{core_.WrapIntoBox(path.PositionAt(t)),
                  path.VelocityAt(t),
                  path.a,
                  bodies.materials.Radius(i),
                  bodies.IsGod(i) ? kInfinity : 1.0 / bodies.materials.InvMass(i),
                  sparse_.PredictionOf(i).version};
  if (bodies.HasDrag(i)) {
    // The true motion (DragMotion), not the Taylor path its element follows.
    const DragState true_state = bodies.paths.drags().StateAt(i, t);
    state.position = core_.WrapIntoBox(true_state.position);
    state.velocity = true_state.velocity;
    state.acceleration = true_state.acceleration;
  }
  if (bodies.rigid.Tracked()) {
    state.orientation = bodies.RigidPathOf(i).OrientationAt(t).normalized();
    state.angular_velocity = bodies.rigid.Omega(i);
  }
  return state;
}

double World::Impl::KineticEnergy() const {
  // Summed in public order: the result does not depend on the memory order.
  const BodyStore& bodies = core_.bodies;
  const double now = core_.Now();
  double energy = 0;
  for (const std::uint32_t i : bodies.ids.InPublicOrder()) {
    if (bodies.IsGod(i)) continue;  // of infinite mass: left out of the sums
    const double inv_mass = bodies.materials.InvMass(i);
    energy += 0.5 / inv_mass * bodies.paths.TrueVelocityAt(i, now).squaredNorm();
    if (bodies.rigid.Tracked()) {
      const Eigen::Matrix3d r = bodies.RigidPathOf(i).OrientationAt(now).toRotationMatrix();
      const Vec3 w_B = r.transpose() * bodies.rigid.Omega(i);  // 1/2 w.I w in body axes
      energy += 0.5 / inv_mass * w_B.dot(bodies.UnitInertia(i) * w_B);
    }
  }
  return energy;
}

Vec3 World::Impl::AngularMomentum() const {
  const BodyStore& bodies = core_.bodies;
  const double now = core_.Now();
  Vec3 momentum = Vec3::Zero();
  for (const std::uint32_t i : bodies.ids.InPublicOrder()) {
    if (bodies.IsGod(i)) continue;
    const double inv_mass = bodies.materials.InvMass(i);
    momentum += bodies.paths.TruePositionAt(i, now).cross(bodies.paths.TrueVelocityAt(i, now)) /
                inv_mass;
    if (bodies.rigid.Tracked()) {
      const Eigen::Matrix3d r = bodies.RigidPathOf(i).OrientationAt(now).toRotationMatrix();
      momentum += r * (bodies.UnitInertia(i) * (r.transpose() * bodies.rigid.Omega(i))) /
                  inv_mass;
    }
  }
  return momentum;
}

Vec3 World::Impl::Momentum() const {
  const BodyStore& bodies = core_.bodies;
  Vec3 momentum = Vec3::Zero();
  for (const std::uint32_t i : bodies.ids.InPublicOrder()) {
    if (bodies.IsGod(i)) continue;
    momentum += bodies.paths.TrueVelocityAt(i, core_.Now()) / bodies.materials.InvMass(i);
  }
  return momentum;
}

std::size_t World::Impl::MemoryBytes() const {
  return core_.bodies.MemoryBytes() + sparse_.MemoryBytes() + detailed_.MemoryBytes();
}

// --- World: thin forwarding to Impl ---

World::World(const WorldSettings& settings) : impl_(std::make_unique<Impl>(settings)) {
  SPARSEDYN_ASSERT(ValidateSettings(settings), "World: invalid settings (see ValidateSettings)");
}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

Result<BodyId> World::AddBody(const BodyDef& def) { return impl_->AddBody(def); }
Status World::AdvanceTo(double t) { return impl_->AdvanceTo(t); }
Status World::SetGodTrack(BodyId id, const GodDef& god) { return impl_->SetGodTrack(id, god); }
std::optional<GodDef> World::GodTrackOf(BodyId id) const {
  if (!IsGod(id)) return std::nullopt;
  const BodyIds& ids = impl_->core_.bodies.ids;
  return impl_->core_.bodies.gods.Of(ids.InternalOf(id.index)).Remaining(Time());
}
bool World::IsStatic(BodyId id) const {
  return IsValid(id) && impl_->core_.bodies.ids.IsStaticSlot(id.index);
}
bool World::IsGod(BodyId id) const {
  const BodyIds& ids = impl_->core_.bodies.ids;
  return IsValid(id) && !ids.IsStaticSlot(id.index) && impl_->core_.bodies.IsGod(ids.InternalOf(id.index));
}
Status World::RemoveBody(BodyId id) { return impl_->RemoveBody(id); }
Status World::SetVelocity(BodyId id, const Vec3& velocity) {
  return impl_->SetVelocity(id, velocity);
}
Status World::SetAngularVelocity(BodyId id, const Vec3& angular_velocity) {
  return impl_->SetAngularVelocity(id, angular_velocity);
}
Status World::ApplyImpulse(BodyId id, const Vec3& impulse, const Vec3& point) {
  return impl_->ApplyImpulse(id, impulse, point);
}
Status World::SetPose(BodyId id, const Vec3& position, const Eigen::Quaterniond& orientation) {
  return impl_->SetPose(id, position, orientation);
}
Status World::SetThrust(BodyId id, const Vec3& thrust, const std::vector<ThrustChange>& schedule) {
  return impl_->SetThrust(id, thrust, schedule);
}
BodyState World::StateAt(BodyId id, double t) const {
  SPARSEDYN_ASSERT(IsValid(id), "StateAt: invalid BodyId");
  const std::uint32_t internal = impl_->core_.bodies.ids.InternalOf(id.index);
  if (StaticBodies::IsKey(internal)) return impl_->StaticStateAt(StaticBodies::IndexOf(internal));
  return impl_->StateAt(internal, t);
}
double World::Time() const { return impl_->core_.Now(); }
std::size_t World::BodyCount() const {
  return impl_->core_.bodies.Size() + impl_->core_.bodies.statics.Count();
}
bool World::IsValid(BodyId id) const { return impl_->core_.bodies.ids.Valid(id); }
bool World::IsPolyhedron(BodyId id) const {
  if (!IsValid(id)) return false;
  const BodyStore& bodies = impl_->core_.bodies;
  const std::uint32_t internal = bodies.ids.InternalOf(id.index);
  if (StaticBodies::IsKey(internal)) {
    return bodies.statics[StaticBodies::IndexOf(internal)].shape != kNoIndex;
  }
  return bodies.IsPolyhedron(internal);
}
BodyId World::IdOf(std::uint32_t index) const { return impl_->core_.bodies.ids.IdOfSlot(index); }
std::size_t World::SlotCount() const { return impl_->core_.bodies.ids.SlotCount(); }
std::vector<BodyId> World::Bodies() const {
  std::vector<BodyId> ids;
  for (std::uint32_t slot = 0; slot < SlotCount(); ++slot) {
    if (const BodyId id = IdOf(slot); id.valid()) ids.push_back(id);
  }
  return ids;
}
void World::OnCollision(std::function<void(const CollisionEvent&)> callback) {
  impl_->core_.observers.OnCollision(std::move(callback));
}
void World::OnSegment(std::function<void(const MotionSegment&)> callback) {
  impl_->core_.observers.OnSegment(std::move(callback));
}
const Statistics& World::Stats() const { return impl_->core_.observers.stats(); }
const WorldSettings& World::Settings() const { return impl_->core_.settings; }
double World::KineticEnergy() const { return impl_->KineticEnergy(); }
Vec3 World::Momentum() const { return impl_->Momentum(); }
Vec3 World::AngularMomentum() const { return impl_->AngularMomentum(); }
double World::MaxPenetration() const { return impl_->core_.observers.MaxPenetration(); }
Status World::Validate() const { return impl_->Validate(); }
std::size_t World::MemoryBytes() const { return impl_->MemoryBytes(); }

std::uint64_t World::StateHash() const {
  // FNV-1a over the bytes of each value (little-endian integers and IEEE doubles).
  std::uint64_t hash = 0xcbf29ce484222325ull;
  const auto mix = [&hash](std::uint64_t bits) {
    for (int k = 0; k < 8; ++k) {
      hash ^= (bits >> (8 * k)) & 0xffu;
      hash *= 0x100000001b3ull;
    }
  };
  const auto mix_double = [&mix](double x) { mix(std::bit_cast<std::uint64_t>(x)); };
  const auto mix_vector = [&mix_double](const Vec3& v) {
    for (int k = 0; k < 3; ++k) mix_double(v[k]);
  };
  mix_double(Time());
  mix(BodyCount());
  for (const BodyId id : Bodies()) {
    const BodyState s = StateAt(id, Time());
    mix_vector(s.position);
    mix_vector(s.velocity);
    mix_vector(s.acceleration);
    const Eigen::Vector4d q = s.orientation.coeffs();
    for (int k = 0; k < 4; ++k) mix_double(q[k]);
    mix_vector(s.angular_velocity);
    mix(s.version);
  }
  return hash;
}

}  // namespace sparsedyn
