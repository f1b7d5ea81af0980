// SPDX-License-Identifier: MIT
// No missed contact (issue #4): a small scene is run, every body's motion is rebuilt from the
// segments the World reports, and a brute-force reference samples every pair's distance over
// time — cold-started closest features at each sample, steps bounded by a global Lipschitz
// constant of the distance so that no dip can hide between samples — and bisects every onset of
// contact. Each onset must be a reported collision of that pair at that time, each reported
// collision must be a touching pair, and no pair may ever interpenetrate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <vector>

#include "motion/rigid_path.hpp"
#include "narrow/point_features.hpp"
#include "sparsedyn/narrow/closest_features.hpp"
#include "sparsedyn/world.hpp"
#include "world/polyhedra_scene.hpp"

namespace sparsedyn {
namespace {

struct Track {
  std::vector<RigidPath> segments;  // in time order
  Pose PoseAt(double t) const {
    auto it = std::upper_bound(segments.begin(), segments.end(), t,
                               [](double time, const RigidPath& p) { return time < p.t0(); });
    return std::prev(it)->PoseAt(t);
  }
};

RigidPath PathOf(const MotionSegment& s) {
  return RigidPath{Path{s.position, s.velocity, s.acceleration, s.t0}, s.orientation,
                   s.angular_velocity};
}

// Runs the scene of `options` and checks every pair against the reference; returns the
// reference's onsets of contact.
int CheckNoMiss(const testing::PolyhedraSceneOptions& options, double duration) {
  World world = testing::MakePolyhedraWorld(options);
  const auto pool = testing::ShapePool(options.seed);
  std::vector<std::unique_ptr<TrackedPolyhedron>> tracked;
  for (const auto& shape : pool) tracked.push_back(std::make_unique<TrackedPolyhedron>(shape));

  const int n = options.n;
  std::vector<Track> tracks(n);
  for (int i = 0; i < n; ++i) {
    const BodyState s = world.StateAt(world.IdOf(i), 0.0);
    MotionSegment first{0.0, world.IdOf(i), s.position, s.velocity, s.acceleration, 0};
    first.orientation = s.orientation;
    first.angular_velocity = s.angular_velocity;
    tracks[i].segments.push_back(PathOf(first));
  }
  world.OnSegment([&](const MotionSegment& s) {
    tracks[s.body.index].segments.push_back(PathOf(s));
  });
  std::map<std::pair<int, int>, std::vector<double>> reported;
  world.OnCollision([&](const CollisionEvent& c) {
    if (c.b.valid()) {
      reported[{std::min(c.a.index, c.b.index), std::max(c.a.index, c.b.index)}].push_back(c.time);
    }
  });
  EXPECT_TRUE(world.AdvanceTo(duration).ok());
  EXPECT_GT(world.Stats().collisions, 15u);

  // A bound on how fast any pair's distance can change: |v_a| + |v_b| + |w_a| r + |w_b| r over
  // every segment (bounding radii are 1).
  double speed = 0;
  for (const Track& track : tracks) {
    for (const RigidPath& p : track.segments) {
      speed = std::max(speed, p.centre.v0.norm() + p.omega.norm());
    }
  }
  const double lipschitz = 2 * speed;
  // Bounding radii are 1, a sphere's its own radius; the pair's tolerance is relative to their sum.
  const auto radius = [&](int i) {
    return testing::IsSphere(options, i) ? testing::SphereRadius(i) : 1.0;
  };
  const auto tolerance_of = [&](int i, int j) {
    return world.Settings().contact_tolerance * (radius(i) + radius(j));
  };
  auto distance = [&](int i, int j, double t) {
    const Pose a = tracks[i].PoseAt(t);
    const Pose b = tracks[j].PoseAt(t);
    const double centres = (a.translation - b.translation).norm();
    const double reach = radius(i) + radius(j);
    const bool sphere_i = testing::IsSphere(options, i), sphere_j = testing::IsSphere(options, j);
    if (centres > reach + 1e-3 || (sphere_i && sphere_j)) {
      return centres - reach;  // spheres apart: a lower bound (two spheres: exact)
    }
    if (sphere_i || sphere_j) {
      const int p = sphere_i ? j : i, s = sphere_i ? i : j;
      const Pose& pose_p = sphere_i ? b : a;
      const Pose& pose_s = sphere_i ? a : b;
      return FindClosestFeatureToPoint(*tracked[p % pool.size()], pose_p, pose_s.translation)
                 .distance -
             radius(s);
    }
    return FindClosestFeatures(*tracked[i % pool.size()], a, *tracked[j % pool.size()], b)
        .distance;
  };

  int onsets = 0, matched = 0, missed = 0;
  double deepest = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const std::vector<double>& times = reported[{i, j}];
      bool touching = false;
      double t = 0, previous = 0;
      while (t < duration) {
        const double d = distance(i, j, t);
        deepest = std::min(deepest, d / tolerance_of(i, j));
        if (d < -tolerance_of(i, j)) {
          ADD_FAILURE() << "bodies " << i << " and " << j << " interpenetrate by " << -d
                        << " at t = " << t;
          break;  // (the steps below would shrink to nothing)
        }
        const double tolerance = tolerance_of(i, j);
        if (d <= tolerance && !touching) {
          // An onset between `previous` and t: bisect it.
          double lo = previous, hi = t;
          for (int k = 0; k < 60 && hi - lo > 1e-13; ++k) {
            const double mid = 0.5 * (lo + hi);
            (distance(i, j, mid) <= tolerance ? hi : lo) = mid;
          }
          ++onsets;
          const bool found = std::any_of(times.begin(), times.end(), [&](double r) {
            return std::abs(r - hi) <= 1e-7;
          });
          if (found) {
            ++matched;
          } else {
            ADD_FAILURE() << "bodies " << i << " and " << j << " touch at t = " << hi
                          << " with no collision reported";

            ++missed;
          }
        }
        touching = d <= tolerance;
        previous = t;
        // No dip below the tolerance can hide in a step of (d - tolerance) / L; near contact
        // the steps shrink to 1e-11 s (a contact dips below the tolerance for ~1e-10 s).
        t += std::max((d - tolerance) / lipschitz, 1e-11);
      }
      for (const double r : times) {
        EXPECT_LE(distance(i, j, r), tolerance_of(i, j) * (1 + 1e-6)) << i << "-" << j << " at "
                                                                      << r;
      }
    }
  }
  EXPECT_EQ(missed, 0);
  EXPECT_GE(deepest, -1.0) << "no pair interpenetrates beyond the tolerance";
  std::printf("reference onsets %d, matched %d, collisions %llu\n", onsets, matched,
              static_cast<unsigned long long>(world.Stats().collisions));
  return onsets;
}

TEST(PolyhedraNoMiss, EveryContactTheReferenceFindsIsAReportedCollision) {
  testing::PolyhedraSceneOptions options;
  options.n = 20;
  options.spacing = 2.3;
  options.seed = 12;
  options.spin = 2.0;
  EXPECT_GE(CheckNoMiss(options, 8.0), 10);
}

// Spheres among the polyhedra (every third body, spinning): the sphere-polyhedron pairs too.
TEST(MixedNoMiss, EveryContactTheReferenceFindsIsAReportedCollision) {
  testing::PolyhedraSceneOptions options;
  options.n = 21;
  options.spacing = 2.3;
  options.seed = 5;
  options.spin = 2.0;
  options.sphere_every = 3;
  EXPECT_GE(CheckNoMiss(options, 8.0), 10);
}

}  // namespace
}  // namespace sparsedyn
