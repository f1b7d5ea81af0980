// SPDX-License-Identifier: MIT
// Small scenes of rotating convex polyhedra for the World's tests: a pool of random shapes
// scaled to bounding radius 1, placed on a jittered lattice without touching, random
// orientations, velocities and spins. Independent of the `thesis` preset so that the World is
// tested on its own.
#pragma once

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "scenes/random.hpp"
#include "sparsedyn/geometry/generators.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn::testing {

struct PolyhedraSceneOptions {
  int n = 50;
  double spacing = 2.5;   // lattice spacing (bounding radius 1: > 2 keeps spheres apart)
  std::uint64_t seed = 1;
  double speed = 1.0;     // velocity components uniform in [-speed, speed]
  double spin = 1.0;      // angular velocity components uniform in [-spin, spin]
  bool walls = true;      // a walled box around the lattice, else open space
  double restitution = 1.0;
  double friction = 0.0;
  RotationModel rotation_model = RotationModel::kSphericalTop;
  Broadphase broadphase = Broadphase::kGrid;
  int sphere_every = 0;   // > 0: bodies 0, k, 2k, ... are spheres (a mixed world)
};

/// The radius of body i's sphere in a mixed scene (IsSphere), drawn from nothing random so that
/// the references know it.
inline bool IsSphere(const PolyhedraSceneOptions& o, int i) {
  return o.sphere_every > 0 && i % o.sphere_every == 0;
}
inline double SphereRadius(int i) { return 0.55 + 0.4 * ((i * 7) % 10) / 10.0; }

inline std::vector<std::shared_ptr<const ConvexPolyhedron>> ShapePool(std::uint64_t seed) {
  std::vector<std::shared_ptr<const ConvexPolyhedron>> pool;
  const int faces[] = {24, 40, 60, 100};
  for (int k = 0; k < 4; ++k) {
    ConvexPolyhedron p = RandomConvexPolyhedron(faces[k], seed * 31 + k).value().Recentered();
    pool.push_back(std::make_shared<const ConvexPolyhedron>(p.Scaled(1.0 / p.bounding_radius())));
  }
  pool.push_back(std::make_shared<const ConvexPolyhedron>(
      MakeBox(Eigen::Vector3d(0.9, 0.35, 0.2)).value()));  // a flat box: faces meet flush
  return pool;
}

inline World MakePolyhedraWorld(const PolyhedraSceneOptions& o) {
  const int side = static_cast<int>(std::ceil(std::cbrt(static_cast<double>(o.n))));
  const double extent = side * o.spacing;
  WorldSettings settings;
  settings.broadphase = o.broadphase;
  settings.rotation_model = o.rotation_model;
  if (o.walls) settings.container = Container::WalledBox(Vec3::Zero(), Vec3::Constant(extent));
  World world(settings);
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto pool = ShapePool(o.seed);
  const double jitter = 0.5 * (o.spacing - 2.0) * 0.9;
  for (int i = 0; i < o.n; ++i) {
    BodyDef def;
    def.shape = pool[static_cast<std::size_t>(i) % pool.size()];
    const Vec3 cell(i % side, (i / side) % side, i / (side * side));
    def.position = (cell + Vec3::Constant(0.5)) * o.spacing +
                   jitter * scenes::DrawVector([&] { return unit(rng); });
    def.orientation = scenes::DrawQuaternion([&] { return unit(rng); }).normalized();
    def.velocity = o.speed * scenes::DrawVector([&] { return unit(rng); });
    def.angular_velocity = o.spin * scenes::DrawVector([&] { return unit(rng); });
    def.mass = 0.5 + 0.5 * (unit(rng) + 1.0);
    def.restitution = o.restitution;
    def.friction = o.friction;
    if (IsSphere(o, i)) {
      def.shape = nullptr;
      def.radius = SphereRadius(i);
    }
    world.AddBody(def).value();
  }
  return world;
}

}  // namespace sparsedyn::testing
