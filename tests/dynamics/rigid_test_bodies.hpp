// SPDX-License-Identifier: MIT
// Test bodies for the dynamics tests: a RigidBodyState with its mass and inertia kept, so that
// energy and momenta can be measured independently of the code under test.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <random>

#include "dynamics/rigid_collision.hpp"

namespace sparsedyn::test {

struct Body {
  RigidBodyState state;
  double mass = 0.0;                                  // 0 for a static wall
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // world frame, about the centre
};

inline Body MakeBody(double mass, const Eigen::Matrix3d& inertia, const Vec3& centre) {
  Body body;
  body.mass = mass;
  body.inertia = inertia;
  body.state.centre = centre;
  body.state.inv_mass = 1.0 / mass;
  body.state.inv_inertia = inertia.inverse();
  return body;
}

inline double Energy(const Body& b) {
  return 0.5 * b.mass * b.state.velocity.squaredNorm() +
         0.5 * b.state.angular_velocity.dot(b.inertia * b.state.angular_velocity);
}
inline Vec3 Momentum(const Body& b) { return b.mass * b.state.velocity; }
// About the world origin: orbital plus spin.
inline Vec3 AngularMomentum(const Body& b) {
  return b.mass * b.state.centre.cross(b.state.velocity) + b.inertia * b.state.angular_velocity;
}
inline Vec3 PointVelocity(const Body& b, const Vec3& p) {
  return b.state.velocity + b.state.angular_velocity.cross(p - b.state.centre);
}
// Normal velocity of B's material point at p relative to A's (negative: approaching).
inline double NormalVelocity(const Body& a, const Body& b, const Vec3& p, const Vec3& n) {
  return (PointVelocity(b, p) - PointVelocity(a, p)).dot(n);
}

// Uniform random rotation from our own stream (Eigen's UnitRandom uses std::rand, whose state
// other tests share, which would make a test depend on the order of the others).
inline Eigen::Quaterniond RandomRotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized();
}

}  // namespace sparsedyn::test
