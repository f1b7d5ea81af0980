// SPDX-License-Identifier: MIT
// The contact probe of thesis_bullet against poses whose penetrations are known in closed form:
// axis-aligned cubes of bounding radius 1 (half side h = 1/sqrt(3)).
#include "bench/peers/thesis/contact_probe.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace sparsedyn::bench {
namespace {

const double kHalfSide = 1 / std::sqrt(3.0);
// Closest-feature distances of the walk are exact to round-off on boxes.
constexpr double kTolerance = 1e-9;

SceneDescription TwoCubes() {
  SceneDescription scene;
  scene.settings.container = Container::WalledBox(Vec3::Zero(), Vec3::Constant(10));
  Result<SceneShape> cube = ParseShapeSpec(R"({"generator":"cube","bounding_radius":1})", {});
  EXPECT_TRUE(cube) << cube.error().message;
  const std::uint32_t shape = scene.AddShape(std::move(*cube));
  scene.bodies = {SceneBody{.shape = shape}, SceneBody{.shape = shape}};
  return scene;
}

std::vector<Pose> At(const Vec3& a, const Vec3& b) {
  Pose X_WA, X_WB;
  X_WA.translation = a;
  X_WB.translation = b;
  return {X_WA, X_WB};
}

TEST(ContactProbe, FaceToFaceOverlapIsItsDepth) {
  const SceneDescription scene = TwoCubes();
  ContactProbe probe(scene);
  probe.Measure(At({5, 5, 5}, {5 + 2 * kHalfSide - 0.1, 5, 5}));
  const ProbeTotals& totals = probe.Finish();
  EXPECT_NEAR(totals.max_penetration, 0.1, kTolerance);
  EXPECT_EQ(totals.contacts, 1u);
  EXPECT_EQ(totals.penetrating, 1u);
  EXPECT_EQ(totals.deep_contacts, 0u);
  EXPECT_EQ(totals.Missed(), 0u);
}

TEST(ContactProbe, ABounceIsOneContactAndNothingMissed) {
  const SceneDescription scene = TwoCubes();
  ContactProbe probe(scene);
  for (const double gap : {0.6, 0.3, 0.02, -0.01, 0.2, 0.5, 3.0}) {
    probe.Measure(At({5, 5, 5}, {5 + 2 * kHalfSide + gap, 5, 5}));
  }
  const ProbeTotals& totals = probe.Finish();
  EXPECT_EQ(totals.contacts, 1u);
  EXPECT_EQ(totals.penetrating, 1u);
  EXPECT_NEAR(totals.max_penetration, 0.01, kTolerance);
  EXPECT_EQ(totals.passed_through, 0u);
}

TEST(ContactProbe, BodiesPassingThroughEachOtherAreMissedAndDeep) {
  const SceneDescription scene = TwoCubes();
  ContactProbe probe(scene);
  for (double x = 1.9; x >= -1.9; x -= 0.2) probe.Measure(At({5, 5, 5}, {5 + x, 5, 5}));
  probe.Measure(At({5, 5, 5}, {1, 5, 5}));  // apart again: the episode ends
  const ProbeTotals& totals = probe.Finish();
  EXPECT_EQ(totals.passed_through, 1u);
  EXPECT_EQ(totals.deep_contacts, 1u);
  EXPECT_EQ(totals.Missed(), 1u);
  EXPECT_GT(totals.max_penetration, 2 * kHalfSide - 0.2);
}

TEST(ContactProbe, WallPenetrationAndEscapeAreMeasured) {
  const SceneDescription scene = TwoCubes();
  ContactProbe probe(scene);
  probe.Measure(At({0.5, 5, 5}, {5, 5, 9.6}));  // into x = 0 by h - 0.5, into z = 10 by h - 0.4
  EXPECT_EQ(probe.Finish().escaped, 0u);
  EXPECT_NEAR(probe.Finish().max_penetration, kHalfSide - 0.4, kTolerance);
  probe.Measure(At({-0.1, 5, 5}, {5, 5, 5}));
  probe.Measure(At({-0.2, 5, 5}, {5, 5, 5}));
  EXPECT_EQ(probe.Finish().escaped, 1u);  // once per body
}

TEST(ContactProbe, FarApartBodiesAreNotQueried) {
  const SceneDescription scene = TwoCubes();
  ContactProbe probe(scene);
  probe.Measure(At({2, 2, 2}, {8, 8, 8}));
  EXPECT_EQ(probe.Finish().queries, 0u);
  EXPECT_EQ(probe.Finish().max_penetration, 0.0);
}

}  // namespace
}  // namespace sparsedyn::bench
