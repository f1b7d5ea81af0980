// SPDX-License-Identifier: MIT
#include "world/path_changes.hpp"

namespace sparsedyn {

void PathChanges::SetHeld(std::uint32_t i, std::uint8_t walls, Vec3 v) {
  ElementPaths& paths = core_.bodies.paths;
  const Vec3 p = paths.PositionNow(i);  // on the path so far
  paths.accelerations().SetHeld(i, walls, paths.Size());
  for (int w = 0; w < 6; ++w) {
    if ((walls >> w & 1u) != 0) v[w / 2] = 0.0;  // axis-aligned walls: exact zeros
  }
  paths.SetStart(i, PathStart{p, v, paths.Now()});
  ReportSegment(i);
}

void PathChanges::SetMotion(std::uint32_t i, const Vec3& v, const Vec3& omega) {
  BodyStore& bodies = core_.bodies;
  const double now = bodies.paths.Now();
  const RigidPath path = bodies.RigidPathOf(i);
  bodies.rigid.SetRotation(i, path.OrientationAt(now).normalized(), omega);
  bodies.rigid.SetSpinRadius(i, bodies.SpinRadiusOf(i));
  bodies.paths.SetStart(i, PathStart{path.centre.PositionAt(now), v, now});
  const std::uint32_t version = ++sparse_.PredictionOf(i).version;
  if (core_.observers.WantsSegments()) {
    MotionSegment segment{now,         bodies.ids.IdOf(i), bodies.paths.Start(i).p0, v,
                          path.centre.a, version};
    segment.orientation = bodies.rigid.Orientation0(i);
    segment.angular_velocity = omega;
    core_.observers.Segment(segment);
  }
}

}  // namespace sparsedyn
