// SPDX-License-Identifier: MIT
#include "scenes/rotating_pair.hpp"

#include <cmath>
#include <string>

#include "scenes/random.hpp"
#include "sparsedyn/geometry/generators.hpp"

namespace sparsedyn::scenes {
namespace {

constexpr long kMaxLoopSteps = 1000000;

// A unit vector in a uniformly random direction (normalised Gaussian triple).
Eigen::Vector3d RandomDirection(Random& random) {
  Eigen::Vector3d d;
  do {
    d = {random.Normal(), random.Normal(), random.Normal()};
  } while (d.norm() < 1e-6);
  return d.normalized();
}

// Whether x is an integer up to round-off in the angle arithmetic.
bool IsWhole(double x) { return std::abs(x - std::round(x)) < 1e-9 * std::max(1.0, x); }

// A recentred random polyhedron scaled to bounding radius 1.
Result<std::shared_ptr<const ConvexPolyhedron>> UnitPolyhedron(int faces, std::uint64_t seed) {
  Result<ConvexPolyhedron> raw = RandomConvexPolyhedron(faces, seed);
  if (!raw) return raw.error();
  const ConvexPolyhedron centred = raw->Recentered();
  return std::make_shared<const ConvexPolyhedron>(centred.Scaled(1.0 / centred.bounding_radius()));
}

}  // namespace

Result<RotatingPair> MakeRotatingPair(const RotatingPairOptions& options) {
  // Validate the motion: separated spheres and a loop that closes within kMaxLoopSteps.
  if (!(options.orbit_radius > 2.0)) {
    return Error{"rotating pair: orbit_radius must be > 2 (bounding radii are 1), got " +
                 std::to_string(options.orbit_radius)};
  }
  if (!(options.degrees_per_step > 0.0) || !(options.orbit_slowdown >= 1.0)) {
    return Error{"rotating pair: degrees_per_step must be > 0 and orbit_slowdown >= 1"};
  }
  long steps = 1;
  while (steps <= kMaxLoopSteps &&
         !(IsWhole(static_cast<double>(steps) * options.degrees_per_step / 360.0) &&
           IsWhole(static_cast<double>(steps) * options.degrees_per_step /
                   (360.0 * options.orbit_slowdown)))) {
    ++steps;
  }
  if (steps > kMaxLoopSteps) {
    return Error{"rotating pair: the loop does not close within 10^6 steps at " +
                 std::to_string(options.degrees_per_step) + " degrees per step"};
  }

  // The shapes depend on the face count and seed only, so every angle sees the same pair.
  RotatingPair pair;
  pair.options = options;
  const auto faces = static_cast<std::uint64_t>(options.faces);
  Result<std::shared_ptr<const ConvexPolyhedron>> a =
      UnitPolyhedron(options.faces, options.seed * 2003 + faces);
  if (!a) return a.error();
  Result<std::shared_ptr<const ConvexPolyhedron>> b =
      UnitPolyhedron(options.faces, options.seed * 2003 + faces + 1000003);
  if (!b) return b.error();
  pair.a = *a;
  pair.b = *b;

  // Fixed random spin axis, orbit axis and starting orientation of A.
  Random random(options.seed);
  const Eigen::Vector3d spin_axis = RandomDirection(random);
  const Eigen::Vector3d orbit_axis = RandomDirection(random);
  const Eigen::Vector3d start_offset =
      orbit_axis.unitOrthogonal() * options.orbit_radius;  // perpendicular to the orbit axis
  const Eigen::Quaterniond R_WA0 =
      DrawQuaternion([&] { return random.Normal(); }).normalized();

  // Angles from the step index (not accumulated), so that the loop closes exactly.
  const double step_radians = options.degrees_per_step * M_PI / 180.0;
  pair.X_WA.reserve(static_cast<std::size_t>(steps));
  for (long k = 0; k < steps; ++k) {
    const double spin = static_cast<double>(k) * step_radians;
    const double orbit = spin / options.orbit_slowdown;
    Pose X_WA;
    X_WA.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(spin, spin_axis)) * R_WA0;
    X_WA.translation = Eigen::AngleAxisd(orbit, orbit_axis) * start_offset;
    pair.X_WA.push_back(X_WA);
  }
  return pair;
}

}  // namespace sparsedyn::scenes
