// SPDX-License-Identifier: MIT
#include "scenes/thesis.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "scenes/presets.hpp"

namespace sparsedyn::scenes {
namespace {

// Radii, packing and mean speed are computed by a few double operations: far below this.
constexpr double kRoundOff = 1e-12;
// Kolmogorov-Smirnov critical value at the 1% level: D_K < 1.63 / sqrt(K).
constexpr double kKs1Percent = 1.63;

// Built once and shared: 1000 bodies from the default pool of 128 hulls.
const SceneDescription& Scene() {
  static const SceneDescription scene = [] {
    Result<SceneDescription> made = MakeThesisScene({.n = 1000, .seed = 20261122});
    EXPECT_TRUE(made) << made.error().message;
    return made ? std::move(*made) : SceneDescription{};
  }();
  return scene;
}

TEST(Thesis, PoolFaceCountsLieIn24To600AndAreUniform) {
  const SceneDescription& scene = Scene();
  ASSERT_GT(scene.shapes.size(), 120u);
  std::vector<int> faces;
  for (const SceneShape& shape : scene.shapes) {
    ASSERT_EQ(shape.kind, SceneShape::Kind::kPolyhedron);
    faces.push_back(shape.polyhedron->face_count());
    EXPECT_GE(faces.back(), 24);
    EXPECT_LE(faces.back(), 600);
  }
  // Kolmogorov-Smirnov distance to the discrete uniform law on 24..600.
  std::sort(faces.begin(), faces.end());
  double ks = 0;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const double cdf = (faces[i] - 23) / 577.0;
    const double below = static_cast<double>(i) / faces.size();
    const double above = static_cast<double>(i + 1) / faces.size();
    ks = std::max({ks, std::abs(cdf - below), std::abs(cdf - above)});
  }
  EXPECT_LT(ks, kKs1Percent / std::sqrt(static_cast<double>(faces.size())));
}

TEST(Thesis, BodiesDrawThePoolShapesUniformlyAndSpecsNameTheFaceCount) {
  const SceneDescription& scene = Scene();
  std::map<std::uint32_t, int> uses;
  for (const SceneBody& body : scene.bodies) ++uses[body.shape];
  // Chi-square over the 128 pool entries (an unused entry is not in the scene: count 0);
  // 127 degrees of freedom, 1% critical value 170.
  const double expected = 1000.0 / 128;
  double chi2 = (128.0 - static_cast<double>(uses.size())) * expected;
  for (const auto& [shape, count] : uses) chi2 += std::pow(count - expected, 2) / expected;
  EXPECT_LT(chi2, 170.0);
  for (const SceneShape& shape : scene.shapes) {
    const std::string faces = "\"faces\":" + std::to_string(shape.polyhedron->face_count());
    EXPECT_NE(shape.spec.find(faces), std::string::npos) << shape.spec;
  }
}

TEST(Thesis, ShapesHaveBoundingRadiusOneAboutTheirCentroid) {
  for (const SceneShape& shape : Scene().shapes) {
    const ConvexPolyhedron& p = *shape.polyhedron;
    double farthest = 0;
    for (const Eigen::Vector3d& v : p.vertices()) {
      farthest = std::max(farthest, (v - p.centroid()).norm());
    }
    EXPECT_NEAR(farthest, 1.0, kRoundOff);
    EXPECT_NEAR(shape.radius, 1.0, kRoundOff);
    EXPECT_LT(p.centroid().norm(), kRoundOff);
  }
}

TEST(Thesis, BoundingSpheresFillThePackingFractionOfAWalledBox) {
  const SceneDescription& scene = Scene();
  const Container& box = scene.settings.container;
  ASSERT_EQ(box.kind, Container::Kind::kWalledBox);
  const Vec3 size = box.hi - box.lo;
  const double filled = 1000 * 4.0 / 3.0 * M_PI / (size[0] * size[1] * size[2]);
  EXPECT_NEAR(filled, 0.05, kRoundOff);
  EXPECT_EQ(scene.settings.gravity, Vec3::Zero());
}

TEST(Thesis, BoundingSpheresDoNotOverlapAndLieInsideTheWalls) {
  const SceneDescription& scene = Scene();
  const Container& box = scene.settings.container;
  const auto& bodies = scene.bodies;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const Vec3& p = bodies[i].position;
    EXPECT_TRUE(((p.array() - 1.0) >= box.lo.array()).all()) << i;
    EXPECT_TRUE(((p.array() + 1.0) <= box.hi.array()).all()) << i;
    for (std::size_t j = i + 1; j < bodies.size(); ++j) {
      EXPECT_GE((bodies[j].position - p).norm(), 2.0) << i << " " << j;
    }
  }
}

TEST(Thesis, MassIsVolumeAtDensityOneAndCollisionsAreElasticFrictionless) {
  for (const SceneBody& body : Scene().bodies) {
    const ConvexPolyhedron& p = *Scene().shapes[body.shape].polyhedron;
    EXPECT_DOUBLE_EQ(body.mass, p.volume());
    EXPECT_EQ(body.restitution, 1.0);
    EXPECT_EQ(body.friction, 0.0);
    EXPECT_EQ(body.orientation.norm(), 1.0);
  }
}

TEST(Thesis, VelocitiesHaveMeanSpeedOneZeroMomentumAndAMaxwellShape) {
  double speed = 0, speed2 = 0, scale = 0;
  Vec3 momentum = Vec3::Zero();
  for (const SceneBody& body : Scene().bodies) {
    speed += body.velocity.norm();
    speed2 += body.velocity.squaredNorm();
    momentum += body.mass * body.velocity;
    scale += body.mass * body.velocity.norm();
  }
  const double n = 1000;
  EXPECT_NEAR(speed / n, 1.0, kRoundOff);
  EXPECT_LT(momentum.norm(), kRoundOff * scale);
  // Maxwell: <v^2> / <v>^2 = 3 pi / 8 = 1.178; its sampling error at N = 1000 is ~0.01.
  EXPECT_NEAR((speed2 / n) / std::pow(speed / n, 2), 3 * M_PI / 8, 0.04);
}

TEST(Thesis, SpinsAreAtMostOneRadianPerSecondWithUniformMagnitudeAndAxis) {
  double sum = 0, largest = 0;
  Vec3 axes = Vec3::Zero();
  for (const SceneBody& body : Scene().bodies) {
    const double w = body.angular_velocity.norm();
    EXPECT_LE(w, 1.0);
    sum += w;
    largest = std::max(largest, w);
    if (w > 0) axes += body.angular_velocity / w;
  }
  EXPECT_NEAR(sum / 1000, 0.5, 0.03);  // uniform on [0, 1]: sd of the mean 0.009
  EXPECT_GT(largest, 0.99);
  EXPECT_LT(axes.norm() / 1000, 0.1);  // isotropic: each component's mean has sd 0.018
}

TEST(Thesis, OrientationsAreUniformSoTheMeanRotationVanishes) {
  Eigen::Matrix3d mean = Eigen::Matrix3d::Zero();
  for (const SceneBody& body : Scene().bodies) mean += body.orientation.toRotationMatrix();
  // Haar measure: E[R] = 0; each entry of one R has variance 1/3, so the mean's sd is 0.018.
  EXPECT_LT((mean / 1000).cwiseAbs().maxCoeff(), 0.1);
}

TEST(Thesis, SameSeedSameSceneOtherSeedOtherScene) {
  Result<SceneDescription> a = MakeThesisScene({.n = 50, .seed = 3});
  Result<SceneDescription> b = MakeThesisScene({.n = 50, .seed = 3});
  Result<SceneDescription> c = MakeThesisScene({.n = 50, .seed = 4});
  ASSERT_TRUE(a && b && c);
  EXPECT_EQ(FormatScene(*a), FormatScene(*b));
  EXPECT_NE(FormatScene(*a), FormatScene(*c));
}

TEST(Thesis, WrittenSceneParsesBackToTheSameBodiesAndShapes) {
  const SceneDescription& scene = Scene();
  const std::string text = FormatScene(scene);
  Result<SceneDescription> read = ParseScene(text, "thesis.json", ".");
  ASSERT_TRUE(read) << read.error().message;
  ASSERT_EQ(read->bodies.size(), scene.bodies.size());
  ASSERT_EQ(read->shapes.size(), scene.shapes.size());
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const SceneBody& x = scene.bodies[i];
    const SceneBody& y = read->bodies[i];
    EXPECT_EQ(x.position, y.position) << i;
    EXPECT_EQ(x.velocity, y.velocity) << i;
    EXPECT_EQ(x.angular_velocity, y.angular_velocity) << i;
    EXPECT_EQ(x.orientation.coeffs(), y.orientation.coeffs()) << i;
    EXPECT_EQ(x.mass, y.mass) << i;
    EXPECT_EQ(scene.shapes[x.shape].spec, read->shapes[y.shape].spec) << i;
  }
  for (std::size_t s = 0; s < scene.shapes.size(); ++s) {
    EXPECT_EQ(scene.shapes[s].spec, read->shapes[s].spec);
    const ConvexPolyhedron& p = *scene.shapes[s].polyhedron;
    const ConvexPolyhedron& q = *read->shapes[s].polyhedron;
    ASSERT_EQ(p.vertex_count(), q.vertex_count());
    for (int v = 0; v < p.vertex_count(); ++v) EXPECT_EQ(p.vertex(v), q.vertex(v));
  }
  EXPECT_EQ(FormatScene(*read), text);
}

TEST(Thesis, OutOfRangeOptionsAreRefused) {
  EXPECT_FALSE(MakeThesisScene({.n = 0}));
  EXPECT_FALSE(MakeThesisScene({.packing = 0.6}));
  EXPECT_FALSE(MakeThesisScene({.min_faces = 600, .max_faces = 24}));
}

TEST(Thesis, PresetIsRegisteredAndUsesTheRequest) {
  const std::vector<std::string> names = PresetNames();
  EXPECT_NE(std::find(names.begin(), names.end(), "thesis"), names.end());
  Result<Preset> preset = MakePreset({.name = "thesis", .n = 20, .density = 0.1, .seed = 5});
  ASSERT_TRUE(preset) << preset.error().message;
  EXPECT_EQ(preset->world.BodyCount(), 20u);
  Result<SceneDescription> scene = MakeThesisScene({.n = 20, .packing = 0.1, .seed = 5});
  ASSERT_TRUE(scene);
  EXPECT_EQ(FormatScene(preset->scene), FormatScene(*scene));
}

TEST(Thesis, TenThousandBodiesAreSetUpQuickly) {
  const auto start = std::chrono::steady_clock::now();
  Result<SceneDescription> scene = MakeThesisScene({.n = 10000, .seed = 7});
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(scene->bodies.size(), 10000u);
  EXPECT_EQ(scene->shapes.size(), 128u);
  RecordProperty("setup_seconds", std::to_string(took.count()));
  std::printf("thesis N = 10^4 set up in %.3f s\n", took.count());
}

}  // namespace
}  // namespace sparsedyn::scenes
