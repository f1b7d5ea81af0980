// SPDX-License-Identifier: MIT
#include "world/static_leave.hpp"

#include <algorithm>
#include <vector>

#include "math/event_time.hpp"
#include "math/polynomial.hpp"
#include "math/roots.hpp"

namespace sparsedyn {

double FaceLeaveTime(std::span<const Vec3> loop, const Vec3& n, const Path& centre, double now) {
  const Vec3 p = centre.PositionAt(now);
  const Vec3 v = centre.VelocityAt(now);
  double leave = kInfinity;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Vec3& q = loop[k];
    // Counter-clockwise about n: the inside is to the left of each edge, where m points.
    const Vec3 m = n.cross(loop[(k + 1) % loop.size()] - q);
    const double inside = m.dot(p - q);
    if (!(inside > 0.0)) return now;
    const std::optional<double> dt =
        EarliestRoot(Polynomial{inside, m.dot(v), 0.5 * m.dot(centre.a)}, 0.0, 1e30);
    if (dt) leave = std::min(leave, EventTime(now, *dt));
  }
  return leave;
}

std::vector<Vec3> StaticFaceLoop(const BodyStore& bodies, std::uint32_t s, std::int32_t face) {
  const StaticBodies::Static& st = bodies.statics[s];
  const ConvexPolyhedron& polyhedron = *bodies.rigid.shapes()[st.shape].polyhedron;
  std::vector<Vec3> loop;
  for (const std::int32_t vertex : polyhedron.FaceVertices(face)) {
    loop.push_back(st.pose.ToWorld(polyhedron.vertex(vertex)));
  }
  return loop;
}

double StaticLeaveTime(const BodyStore& bodies, std::uint32_t i) {
  const Hold hold = bodies.paths.accelerations().HoldOf(i);
  if (hold.on_static == kNoIndex) return kInfinity;
  return FaceLeaveTime(StaticFaceLoop(bodies, hold.on_static, hold.face), hold.normal,
                       bodies.paths.PathOf(i), bodies.paths.Now());
}

}  // namespace sparsedyn
