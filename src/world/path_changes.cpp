// SPDX-License-Identifier: MIT
#include "world/path_changes.hpp"

namespace sparsedyn {

void PathChanges::StartDragSegment(std::uint32_t i) { core_.bodies.StartDragSegment(i); }

void PathChanges::AnnounceSegment(std::uint32_t i, std::uint32_t version) {
  const ElementPaths& paths = core_.bodies.paths;
  const PathStart& s = paths.Start(i);
  MotionSegment segment{paths.Now(), core_.bodies.ids.IdOf(i), s.p0, s.v0, paths.PathOf(i).a,
                        version};
  if (core_.bodies.rigid.Tracked()) {
    segment.orientation = core_.bodies.rigid.Orientation0(i);
    segment.angular_velocity = core_.bodies.rigid.Omega(i);
  }
  core_.observers.Segment(segment);
}

void PathChanges::SetHeld(std::uint32_t i, const Hold& hold, Vec3 v,
                          const std::optional<Vec3>& omega) {
  BodyStore& bodies = core_.bodies;
  ElementPaths& paths = bodies.paths;
  const Vec3 p = paths.PositionNow(i);  // on the path so far
  if (omega) {
    bodies.rigid.SetRotation(i, bodies.RigidPathOf(i).OrientationAt(paths.Now()).normalized(),
                             *omega);
    bodies.rigid.SetSpinRadius(i, bodies.SpinRadiusOf(i));
  } else {
    RebaseRotation(i);
  }
  paths.accelerations().SetHeld(i, hold, paths.Size());
  // The velocity into what holds it goes, as the acceleration's (walls: exact zeros).
  paths.SetStart(i, PathStart{p, Accelerations::HeldAcceleration(v, hold), paths.Now()});
  ReportSegment(i);
}

void PathChanges::SetMotion(std::uint32_t i, const Vec3& v, const Vec3& omega) {
  BodyStore& bodies = core_.bodies;
  const double now = bodies.paths.Now();
  const RigidPath path = bodies.RigidPathOf(i);
  bodies.rigid.SetRotation(i, path.OrientationAt(now).normalized(), omega);
  bodies.rigid.SetSpinRadius(i, bodies.SpinRadiusOf(i));
  bodies.paths.SetStart(i, PathStart{bodies.paths.TruePositionAt(i, now), v, now});
  ReportSegment(i);
}

void PathChanges::RebaseRotation(std::uint32_t i) {
  BodyStore& bodies = core_.bodies;
  if (!bodies.rigid.Tracked()) return;
  bodies.rigid.SetOrientation0(i, bodies.RigidPathOf(i).OrientationAt(bodies.paths.Now()).normalized());
}

void PathChanges::SetAcceleration(std::uint32_t i, const Vec3& free_acceleration) {
  const ElementPaths& paths = core_.bodies.paths;
  SetPiece(i, GodState{paths.PositionNow(i), paths.VelocityNow(i), free_acceleration});
}

void PathChanges::SetPiece(std::uint32_t i, const GodState& state) {
  ElementPaths& paths = core_.bodies.paths;
  RebaseRotation(i);
  paths.accelerations().SetFree(i, state.acceleration, paths.Size());
  paths.SetStart(i, PathStart{state.position, state.velocity, paths.Now()});
  ReportSegment(i);
}

void PathChanges::SetPose(std::uint32_t i, const Vec3& position,
                          const Eigen::Quaterniond& orientation) {
  BodyStore& bodies = core_.bodies;
  const Vec3 v = bodies.paths.VelocityNow(i);
  if (bodies.rigid.Tracked()) bodies.rigid.SetOrientation0(i, orientation);
  bodies.paths.SetStart(i, PathStart{position, v, bodies.paths.Now()});
  if (bodies.rigid.Tracked()) bodies.rigid.SetSpinRadius(i, bodies.SpinRadiusOf(i));
  ReportSegment(i);
}

}  // namespace sparsedyn
