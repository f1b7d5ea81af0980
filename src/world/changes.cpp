// SPDX-License-Identifier: MIT
// Changes between AdvanceTo calls, at the current time (App. H.3's manipulations): each is
// checked first and refused with a named error and nothing changed, then made as a new segment
// of the body's path, after which the body predicts again. Removing a body or moving it at once
// (a teleport) restarts the predictions of every body (Start): O(N), as a World built afresh
// from the same state would do.
#include <string>
#include <vector>

#include "base/format.hpp"
#include "world/static_leave.hpp"
#include "world/world_impl.hpp"

namespace sparsedyn {
namespace {

std::string Handle(BodyId id) {
  return "body " + std::to_string(id.index) + " (generation " + std::to_string(id.generation) +
         ")";
}

std::optional<Error> CheckFinite(const Vec3& v, const char* call, const char* what) {
  if (v.allFinite()) return std::nullopt;
  return Error{std::string(call) + ": " + what + " must be finite, got (" + FormatExact(v[0]) +
               ", " + FormatExact(v[1]) + ", " + FormatExact(v[2]) + ")"};
}

}  // namespace

Result<std::uint32_t> World::Impl::ElementOf(BodyId id, const char* call) const {
  if (!core_.bodies.ids.Valid(id)) {
    return Error{std::string(call) + ": " + Handle(id) +
                 " is not in the World (removed, or never added)"};
  }
  if (core_.bodies.ids.IsStaticSlot(id.index)) {
    return Error{std::string(call) + ": " + Handle(id) + " is static (it never moves)"};
  }
  return core_.bodies.ids.InternalOf(id.index);
}

Result<std::uint32_t> World::Impl::MovableOf(BodyId id, const char* call) const {
  Result<std::uint32_t> element = ElementOf(id, call);
  if (element && core_.bodies.IsGod(*element)) {
    return Error{std::string(call) + ": " + Handle(id) +
                 " is a god object (nothing pushes it; SetGodTrack steers it)"};
  }
  return element;
}

void World::Impl::AfterChange(std::uint32_t i) {
  if (!started_) return;  // the start predicts everything
  BodyStore& bodies = core_.bodies;
  if (bodies.paths.StraightLines() && !bodies.AllOnStraightLines()) {
    Start();
    return;
  }
  sparse_.PredictFull(i);
  detailed_.PredictEngagementsOf(i);
}

Status World::Impl::RemoveBody(BodyId id) {
  if (core_.bodies.ids.Valid(id) && core_.bodies.ids.IsStaticSlot(id.index)) {
    // A static: its engagements end with a restart (as a World built without it).
    BodyIds& ids = core_.bodies.ids;
    const std::uint32_t s = StaticBodies::IndexOf(ids.InternalOf(id.index));
    // What rested on it falls (or rests on what else holds it).
    for (std::uint32_t i = 0; i < core_.bodies.Size(); ++i) {
      if (core_.bodies.paths.accelerations().HoldOf(i).on_static == s) changes_.ReleaseStatic(i);
    }
    core_.bodies.statics.Remove(s);
    ids.Remove(id.index);
    if (started_) Start();
    return Status::Ok();
  }
  Result<std::uint32_t> element = ElementOf(id, "RemoveBody");
  if (!element) return element.error();
  BodyStore& bodies = core_.bodies;
  const std::uint32_t e = *element, n = bodies.Size();
  // The last element takes the removed one's place; the versions stay with their bodies.
  std::vector<std::uint32_t> old_of_new(n - 1);
  for (std::uint32_t k = 0; k + 1 < n; ++k) old_of_new[k] = k == e ? n - 1 : k;
  std::vector<std::uint32_t> versions(n - 1);
  for (std::uint32_t k = 0; k + 1 < n; ++k) versions[k] = sparse_.PredictionOf(old_of_new[k]).version;
  bodies.ids.Remove(id.index);
  bodies.Permute(old_of_new);
  ElementQueue& queue = sparse_.queue();
  queue.Clear();
  queue.Truncate(n - 1);
  for (std::uint32_t k = 0; k + 1 < n; ++k) {
    sparse_.PredictionOf(k) = Prediction{};
    sparse_.PredictionOf(k).version = versions[k];
  }
  detailed_.Clear();
  if (started_) {
    Start();
  } else {
    admission_.Rebuild();
  }
  return Status::Ok();
}

Status World::Impl::SetVelocity(BodyId id, const Vec3& velocity) {
  Result<std::uint32_t> element = MovableOf(id, "SetVelocity");
  if (!element) return element.error();
  if (std::optional<Error> error = CheckFinite(velocity, "SetVelocity", "velocity")) return *error;
  changes_.Release(*element);
  changes_.SetVelocity(*element, velocity);
  AfterChange(*element);
  return Status::Ok();
}

Status World::Impl::SetAngularVelocity(BodyId id, const Vec3& angular_velocity) {
  Result<std::uint32_t> element = MovableOf(id, "SetAngularVelocity");
  if (!element) return element.error();
  if (std::optional<Error> error =
          CheckFinite(angular_velocity, "SetAngularVelocity", "angular_velocity")) {
    return *error;
  }
  BodyStore& bodies = core_.bodies;
  const std::uint32_t i = *element;
  bodies.rigid.Track(bodies.Size());  // from now on rotation matters
  changes_.Release(i);
  changes_.SetMotion(i, bodies.paths.VelocityNow(i), angular_velocity);
  AfterChange(i);
  return Status::Ok();
}

Status World::Impl::ApplyImpulse(BodyId id, const Vec3& impulse, const Vec3& point) {
  Result<std::uint32_t> element = MovableOf(id, "ApplyImpulse");
  if (!element) return element.error();
  if (std::optional<Error> error = CheckFinite(impulse, "ApplyImpulse", "impulse")) return *error;
  if (std::optional<Error> error = CheckFinite(point, "ApplyImpulse", "point")) return *error;
  BodyStore& bodies = core_.bodies;
  const std::uint32_t i = *element;
  const double now = core_.Now();
  const Vec3 centre = bodies.paths.PathOf(i).PositionAt(now);
  // In a periodic box the path is not wrapped between restarts while StateAt is: the lever arm
  // is the image of point - centre nearest zero, whichever image either is given in.
  changes_.Release(i);
  const Vec3 torque_impulse = core_.MinimumImage(point - centre).cross(impulse);
  if (!torque_impulse.isZero(0.0)) bodies.rigid.Track(bodies.Size());
  const Vec3 v = bodies.paths.VelocityNow(i) + bodies.materials.InvMass(i) * impulse;
  if (!bodies.rigid.Tracked()) {
    changes_.SetVelocity(i, v);
  } else {
    const Eigen::Quaterniond q = bodies.RigidPathOf(i).OrientationAt(now).normalized();
    const Vec3 omega = bodies.rigid.Omega(i) + bodies.InvInertiaWorld(i, q) * torque_impulse;
    changes_.SetMotion(i, v, omega);
  }
  AfterChange(i);
  return Status::Ok();
}

Status World::Impl::SetPose(BodyId id, const Vec3& position,
                            const Eigen::Quaterniond& orientation) {
  Result<std::uint32_t> element = ElementOf(id, "SetPose");
  if (!element) return element.error();
  const std::uint32_t i = *element;
  if (Status placed = admission_.CheckPose(i, id.index, position, orientation, started_);
      !placed) {
    return Error{"SetPose: " + placed.error().message};
  }
  changes_.SetPose(i, position, orientation.normalized());
  // A god object teleported goes on to the targets it had not reached, from its new place.
  if (core_.bodies.IsGod(i)) Replan(i, core_.bodies.gods.Of(i).Remaining(core_.Now()));
  // The body's former partners predict again and its new place is searched (App. H.3): a
  // restart does both, and engages what overlaps its element there.
  if (started_) {
    Start();
  } else {
    admission_.Rebuild();
  }
  return Status::Ok();
}

Status World::Impl::SetThrust(BodyId id, const Vec3& thrust,
                              const std::vector<ThrustChange>& schedule) {
  Result<std::uint32_t> element = MovableOf(id, "SetThrust");
  if (!element) return element.error();
  if (std::optional<Error> error = CheckFinite(thrust, "SetThrust", "thrust")) return *error;
  if (std::optional<Error> error = CheckSchedule(schedule, core_.Now(), "SetThrust: ")) {
    return *error;
  }
  BodyStore& bodies = core_.bodies;
  const std::uint32_t i = *element;
  if (!schedule.empty() || bodies.thrusts.Any()) bodies.thrusts.Replace(i, schedule, bodies.Size());
  changes_.SetAcceleration(i, core_.settings.gravity + thrust);
  AfterChange(i);
  return Status::Ok();
}

Status World::Impl::SetGodTrack(BodyId id, const GodDef& god) {
  Result<std::uint32_t> element = ElementOf(id, "SetGodTrack");
  if (!element) return element.error();
  const std::uint32_t i = *element;
  if (!core_.bodies.IsGod(i)) {
    return Error{"SetGodTrack: " + Handle(id) + " is not a god object (give it one in AddBody)"};
  }
  if (std::optional<Error> error = admission_.CheckGodTrack(god, "SetGodTrack: ")) return *error;
  Replan(i, god);
  AfterChange(i);
  return Status::Ok();
}

void World::Impl::Replan(std::uint32_t i, const GodDef& god) {
  const double now = core_.Now();
  const Path path = core_.bodies.paths.PathOf(i);
  GodPlan plan(now, path.PositionAt(now), path.VelocityAt(now), god.track, god.max_acceleration);
  GodBodies::God replaced{god, std::move(plan)};
  const Vec3 a = replaced.Follow(now).a;
  core_.bodies.gods.Replace(i, std::move(replaced));
  changes_.SetAcceleration(i, a);
}

void World::Impl::HandleBodyTimer(std::uint32_t i) {
  BodyStore& bodies = core_.bodies;
  if (bodies.IsGod(i)) {
    // The next piece of its plan: the same place and velocity (to round-off), a new
    // acceleration.
    changes_.SetPiece(i, bodies.gods.Follow(i, core_.Now()));
  } else if (bodies.thrusts.NextTime(i) <= core_.Now()) {
    changes_.SetAcceleration(i, core_.settings.gravity + bodies.thrusts.TakeNext(i));
  } else if (bodies.paths.accelerations().OnStatic(i)) {
    // Its leave time, or a little before it (never late): once its centre of mass is at the
    // face's boundary the static's hold ends (it slides off, or tips over the edge); else it
    // predicts again.
    if (StaticLeaveTime(bodies, i) <= core_.Now()) {
      changes_.ReleaseStatic(i);
      ++core_.observers.stats().static_leaves;
    }
  } else {
    // A drag check (App. E.2): the element's envelope holds the true motion up to here; a new
    // segment from the true state (its version up: partners predict against the new one).
    SPARSEDYN_ASSERT(bodies.HasDrag(i), "a body timer that is neither thrust, god nor drag");
    ++core_.observers.stats().drag_checks;
    changes_.SetVelocity(i, bodies.paths.VelocityNow(i));
  }
  sparse_.PredictFull(i);
  detailed_.PredictEngagementsOf(i);
}

}  // namespace sparsedyn
