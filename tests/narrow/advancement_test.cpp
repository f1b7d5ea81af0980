// SPDX-License-Identifier: MIT
// The conservative-advancement helpers against independent computations: the closed-form step
// against the certified root finder, the table-started support climb against the O(V) scan.
#include "narrow/advancement.hpp"

#include "narrow/slab_bound.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "math/polynomial.hpp"
#include "math/roots.hpp"
#include "motion/rigid_path.hpp"
#include "sparsedyn/geometry/generators.hpp"
#include "sparsedyn/narrow/closest_features.hpp"

namespace sparsedyn {
namespace {

// The oracle: the earliest root of -closable + speed dt + accel dt^2 / 2 in [0, horizon].
std::optional<double> CertifiedStep(double closable, double speed, double accel, double horizon) {
  if (speed <= 0.0 && accel <= 0.0) return std::nullopt;
  return EarliestRoot(Polynomial{-closable, speed, 0.5 * accel}, 0.0, horizon);
}

TEST(AdvancementStep, SimpleCases) {
  EXPECT_NEAR(*narrow::AdvancementStep(2.0, 4.0, 0.0, 10.0), 0.5, 1e-12);
  // dt^2 / 2 = 2 -> dt = 2.
  EXPECT_NEAR(*narrow::AdvancementStep(2.0, 0.0, 1.0, 10.0), 2.0, 1e-12);
  // dt - dt^2 / 2 reaches at most 1/2: 1 can never be closed; 0.5 exactly at dt = 1 (a touch).
  EXPECT_FALSE(narrow::AdvancementStep(1.0, 1.0, -1.0, 10.0));
  EXPECT_NEAR(*narrow::AdvancementStep(0.5, 1.0, -1.0, 10.0), 1.0, 1e-7);
  EXPECT_FALSE(narrow::AdvancementStep(1.0, -1.0, 0.0, 10.0));
  EXPECT_FALSE(narrow::AdvancementStep(1.0, 0.0, 0.0, 10.0));
  EXPECT_FALSE(narrow::AdvancementStep(20.0, 1.0, 0.0, 10.0));  // beyond the horizon
  EXPECT_EQ(*narrow::AdvancementStep(0.0, 1.0, 0.0, 10.0), 0.0);
}

TEST(AdvancementStep, NeverLaterThanTheCertifiedRootAndAsLong) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int compared = 0;
  for (int i = 0; i < 100000; ++i) {
    const double closable = std::pow(10.0, 6.0 * unit(rng) - 3.0);
    const double speed = unit(rng) * std::pow(10.0, 3.0 * unit(rng));
    const double accel = (i % 5 == 0) ? 0.0 : unit(rng) * std::pow(10.0, 3.0 * unit(rng));
    const double horizon = std::pow(10.0, 4.0 * unit(rng));
    const std::optional<double> step = narrow::AdvancementStep(closable, speed, accel, horizon);
    const std::optional<double> exact = CertifiedStep(closable, speed, accel, horizon);
    ASSERT_EQ(step.has_value(), exact.has_value())
        << "closable " << closable << " speed " << speed << " accel " << accel << " horizon "
        << horizon;
    if (!step) continue;
    ++compared;
    // Conservative (never later) and no shorter than the slack asks.
    EXPECT_LE(*step, *exact) << closable << " " << speed << " " << accel;
    EXPECT_GE(*step, *exact * (1.0 - 1e-9)) << closable << " " << speed << " " << accel;
  }
  EXPECT_GT(compared, 30000);
}

TEST(TrackedSupportVertex, AgreesWithTheScanOnEveryGenerator) {
  std::vector<std::shared_ptr<const ConvexPolyhedron>> shapes;
  for (const int faces : {8, 24, 100, 600}) {
    shapes.push_back(std::make_shared<ConvexPolyhedron>(*RandomConvexPolyhedron(faces, faces)));
  }
  shapes.push_back(std::make_shared<ConvexPolyhedron>(*MakeBox({1.0, 2.0, 3.0})));
  shapes.push_back(std::make_shared<ConvexPolyhedron>(*MakePrism(64, 1.0, 0.5)));
  shapes.push_back(std::make_shared<ConvexPolyhedron>(*MakeNeedle(2.0)));
  shapes.push_back(std::make_shared<ConvexPolyhedron>(*MakeSlab(2.0)));
  std::mt19937_64 rng(3);
  std::normal_distribution<double> gauss;
  for (const auto& shape : shapes) {
    const TrackedPolyhedron tracked(shape);
    for (int i = 0; i < 4000; ++i) {
      Vec3 d(gauss(rng), gauss(rng), gauss(rng));
      if (i % 4 == 0) d = shape->face(i % shape->face_count()).plane.normal;  // a face-tie
      const double best = d.dot(shape->vertex(shape->SupportVertex(d)));
      const double climbed = d.dot(shape->vertex(tracked.SupportVertex(d)));
      EXPECT_NEAR(climbed, best, 1e-13 * shape->scale() * d.norm());
      const int start = i % shape->vertex_count();
      EXPECT_NEAR(d.dot(shape->vertex(shape->SupportVertexFrom(d, start))), best,
                  1e-13 * shape->scale() * d.norm());
    }
  }
}

// The exact separation along n at time t: B's lowest vertex minus A's highest.
double Separation(const ConvexPolyhedron& a, const RigidPath& path_a, const ConvexPolyhedron& b,
                  const RigidPath& path_b, const Vec3& n, double t) {
  const Pose X_WA = path_a.PoseAt(t), X_WB = path_b.PoseAt(t);
  double top = -kInfinity, bottom = kInfinity;
  for (const Vec3& v : a.vertices()) top = std::max(top, n.dot(X_WA.ToWorld(v)));
  for (const Vec3& v : b.vertices()) bottom = std::min(bottom, n.dot(X_WB.ToWorld(v)));
  return bottom - top;
}

TEST(SlabBound, BoundsTheSeparationAndItsStepKeepsTheSlabOpen) {
  auto shape_a = std::make_shared<ConvexPolyhedron>(RandomConvexPolyhedron(60, 1)->Recentered());
  auto shape_b = std::make_shared<ConvexPolyhedron>(RandomConvexPolyhedron(200, 2)->Recentered());
  const TrackedPolyhedron a(shape_a), b(shape_b);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> gauss;
  auto random_vec = [&](double scale) -> Vec3 {
    return Vec3(gauss(rng), gauss(rng), gauss(rng)) * scale;
  };
  int steps = 0, long_steps = 0;
  for (int i = 0; i < 300; ++i) {
    const Vec3 n = random_vec(1.0).normalized();
    const double t = 0.3 * i / 300.0;
    RigidPath path_a{Path{Vec3::Zero(), random_vec(0.5), (i % 3 == 0) ? random_vec(1.0) : Vec3(Vec3::Zero()), 0.0},
                     Eigen::Quaterniond(Eigen::AngleAxisd(gauss(rng), random_vec(1.0).normalized())),
                     random_vec(i % 2 == 0 ? 0.5 : 5.0)};
    const double reach = shape_a->bounding_radius() + shape_b->bounding_radius();
    RigidPath path_b{Path{n * (reach * (0.8 + 0.4 * (i % 7) / 7.0)), random_vec(0.5), Vec3::Zero(), 0.0},
                     Eigen::Quaterniond(Eigen::AngleAxisd(gauss(rng), random_vec(1.0).normalized())),
                     random_vec(1.0)};
    const double r_a = narrow::SpinRadius(*shape_a, path_a);
    const double r_b = narrow::SpinRadius(*shape_b, path_b);
    narrow::SlabBound bound(a, path_a, r_a, b, path_b, r_b, n, t);
    for (int k = 0; k <= 50; ++k) {
      const double dt = 2.0 * k / 50.0;
      EXPECT_LE(bound(dt), Separation(*shape_a, path_a, *shape_b, path_b, n, t + dt))
          << "case " << i << " dt " << dt;
    }
    const double start = Separation(*shape_a, path_a, *shape_b, path_b, n, t);
    if (start <= 1e-3) continue;
    const double level = 1e-3;
    const std::optional<double> step = bound.Step(level, 10.0, 1e-6);
    if (!step) continue;
    ++steps;
    if (*step > 1e-3) ++long_steps;
    for (int k = 0; k <= 200; ++k) {
      const double dt = *step * k / 200.0;
      EXPECT_GE(Separation(*shape_a, path_a, *shape_b, path_b, n, t + dt), level - 1e-12)
          << "case " << i << " dt " << dt << " of step " << *step;
    }
  }
  EXPECT_GT(steps, 100);
  EXPECT_GT(long_steps, steps / 2);
}

}  // namespace
}  // namespace sparsedyn
