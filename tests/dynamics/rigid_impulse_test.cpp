// SPDX-License-Identifier: MIT
// ApplyRigidImpulse against independent oracles: SphereImpulse on the line of centres, the
// textbook rod struck at its end, conservation laws on random cases, the Coulomb cone of a
// block landing on a floor, and regions that must stop approaching everywhere.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>

#include "dynamics/rigid_collision.hpp"
#include "dynamics/sphere_collision.hpp"
#include "rigid_test_bodies.hpp"

namespace sparsedyn {
namespace {

using namespace test;  // NOLINT(google-build-using-namespace): test helpers

// Round-off of a few 3x3 products on O(1) data, with room for mass ratios up to ~100.
constexpr double kConservationTolerance = 1e-12;
// Round-off of a point's velocity, absolute: the random velocities and spins are O(1), so a
// tiny approach speed still carries O(1e-16) error from its O(1) terms.
constexpr double kSpeedRoundOff = 1e-12;

Body Wall() { return Body{}; }

// Box with half extents (a, b, c): I = m/3 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2).
Eigen::Matrix3d BoxInertia(double mass, const Vec3& h) {
  return (mass / 3.0) * Vec3(h.y() * h.y() + h.z() * h.z(), h.x() * h.x() + h.z() * h.z(),
                             h.x() * h.x() + h.y() * h.y())
                            .asDiagonal();
}

ContactGeometry PointContact(const Vec3& p, const Vec3& n) {
  ContactGeometry c;
  c.normal = n;
  c.points = {p};
  return c;
}

TEST(RigidImpulse, CentreLineCollisionEqualsSphereImpulse) {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const Vec3 n = Vec3(u(rng), u(rng), u(rng)).normalized();
    const Eigen::Matrix3d r = RandomRotation(rng).toRotationMatrix();
    Body a = MakeBody(1.0 + u(rng) + 1.0, r * Vec3(1, 2, 3).asDiagonal() * r.transpose(),
                      Vec3(u(rng), u(rng), u(rng)));
    Body b = MakeBody(2.0 + u(rng), Vec3(2, 1, 1.5).asDiagonal(), a.state.centre + 3.0 * n);
    a.state.velocity = Vec3(u(rng), u(rng), u(rng)) + 3.0 * n;
    b.state.velocity = Vec3(u(rng), u(rng), u(rng)) - 3.0 * n;
    const double e = 0.5 + 0.5 * u(rng);
    const ImpulseResult expected = SphereImpulse(a.state.velocity, b.state.velocity,
                                                 a.state.inv_mass, b.state.inv_mass, n, e, 0.0);
    const RigidImpulseResult got = ApplyRigidImpulse(
        a.state, b.state, PointContact(a.state.centre + 1.2 * n, n), {.restitution = e});
    EXPECT_EQ(got.rounds, 1);
    EXPECT_LT((a.state.velocity - expected.v_a).norm(), 1e-14);
    EXPECT_LT((b.state.velocity - expected.v_b).norm(), 1e-14);
    EXPECT_LT(a.state.angular_velocity.norm() + b.state.angular_velocity.norm(), 1e-14);
    EXPECT_NEAR(got.normal_impulse, expected.impulse, 1e-14);
  }
}

// A slender rod (length L, mass m) falls flat onto a peg under its end (Beer & Johnston, Vector
// Mechanics, sample problem on eccentric impact): j = m (1 + e) v / 4, v' = -v + j / m,
// omega = 3 (1 + e) v / (2 L).
TEST(RigidImpulse, ThinRodStruckAtItsEndMatchesTextbook) {
  const double m = 2.0, length = 3.0, v = 1.5, thickness = 1e-5 * length;
  for (const double e : {0.0, 0.5, 1.0}) {
    Body peg = Wall();
    Body rod = MakeBody(m, BoxInertia(m, Vec3(length / 2, thickness, thickness)), Vec3(0, 0, 0));
    rod.state.velocity = Vec3(0, -v, 0);
    const RigidImpulseResult result =
        ApplyRigidImpulse(peg.state, rod.state, PointContact(Vec3(length / 2, 0, 0), Vec3::UnitY()),
                          {.restitution = e});
    EXPECT_EQ(result.rounds, 1);
    EXPECT_NEAR(result.normal_impulse, m * (1 + e) * v / 4, 1e-9);
    EXPECT_NEAR(rod.state.velocity.y(), -v + (1 + e) * v / 4, 1e-9);
    EXPECT_NEAR(rod.state.angular_velocity.z(), 3 * (1 + e) * v / (2 * length), 1e-9);
    EXPECT_NEAR(rod.state.velocity.x(), 0.0, 1e-15);
    EXPECT_EQ(peg.state.velocity, Vec3::Zero());
  }
}

// Random bodies, contact point and normal (a point or a polygon region in the contact plane).
struct RandomCase {
  Body a, b;
  ContactGeometry contact;
};

RandomCase MakeRandomCase(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto vec = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  auto inertia = [&](double mass) {
    const Eigen::Matrix3d r = RandomRotation(rng).toRotationMatrix();
    return Eigen::Matrix3d(r * (mass * (vec().cwiseAbs() + Vec3::Constant(0.1))).asDiagonal() *
                           r.transpose());
  };
  RandomCase c;
  const double ma = std::exp(2.0 * u(rng)), mb = std::exp(2.0 * u(rng));
  c.a = MakeBody(ma, inertia(ma), vec());
  c.b = MakeBody(mb, inertia(mb), vec());
  c.contact.normal = vec().normalized();
  const Vec3 p = vec();
  c.contact.points = {p};
  if (rng() % 2 == 0) {
    // A triangle or quadrilateral around p in the contact plane (convex, counter-clockwise).
    const Vec3 t1 = c.contact.normal.unitOrthogonal();
    const Vec3 t2 = c.contact.normal.cross(t1);
    const int corners = 3 + static_cast<int>(rng() % 2);
    c.contact.points.clear();
    for (int k = 0; k < corners; ++k) {
      const double angle = 2 * M_PI * (k + 0.3 * u(rng)) / corners;
      c.contact.points.push_back(p + 0.5 * (std::cos(angle) * t1 + std::sin(angle) * t2));
    }
  }
  c.a.state.velocity = vec();
  c.b.state.velocity = vec();
  c.a.state.angular_velocity = vec();
  c.b.state.angular_velocity = vec();
  return c;
}

double MinNormalVelocity(const RandomCase& c) {
  double lowest = kInfinity;
  for (const Vec3& p : c.contact.points) {
    lowest = std::min(lowest, NormalVelocity(c.a, c.b, p, c.contact.normal));
  }
  return lowest;
}

TEST(RigidImpulse, FrictionlessElasticConservesEnergyAndMomenta) {
  std::mt19937_64 rng(424242);
  int applied = 0, multi_round = 0;
  double worst_energy = 0, worst_momentum = 0, worst_angular = 0;
  for (int trial = 0; trial < 10000; ++trial) {
    RandomCase c = MakeRandomCase(rng);
    const double e0 = Energy(c.a) + Energy(c.b);
    const Vec3 p0 = Momentum(c.a) + Momentum(c.b);
    const Vec3 l0 = AngularMomentum(c.a) + AngularMomentum(c.b);
    const double p_scale = Momentum(c.a).norm() + Momentum(c.b).norm();
    const double l_scale = AngularMomentum(c.a).norm() + AngularMomentum(c.b).norm();
    const double pre = NormalVelocity(c.a, c.b, c.contact.points[0], c.contact.normal);
    const RigidImpulseResult r =
        ApplyRigidImpulse(c.a.state, c.b.state, c.contact, {.elastic_below_speed = 0.0});
    if (r.rounds == 0) {
      EXPECT_GE(MinNormalVelocity(c), 0.0);
      continue;
    }
    ++applied;
    multi_round += r.rounds > 1;
    worst_energy = std::max(worst_energy, std::abs(Energy(c.a) + Energy(c.b) - e0) / e0);
    worst_momentum =
        std::max(worst_momentum, (Momentum(c.a) + Momentum(c.b) - p0).norm() / p_scale);
    worst_angular = std::max(worst_angular,
                             (AngularMomentum(c.a) + AngularMomentum(c.b) - l0).norm() / l_scale);
    if (c.contact.points.size() == 1) {
      EXPECT_NEAR(NormalVelocity(c.a, c.b, c.contact.points[0], c.contact.normal), -pre,
                  kSpeedRoundOff);
    }
    EXPECT_GE(MinNormalVelocity(c), -1e-9) << "trial " << trial;
  }
  std::printf(
      "frictionless e=1: %d impulses (%d regions needing several rounds); max relative "
      "errors: energy %.3g, momentum %.3g, angular momentum %.3g\n",
      applied, multi_round, worst_energy, worst_momentum, worst_angular);
  EXPECT_GT(applied, 4000);
  EXPECT_GT(multi_round, 100);
  EXPECT_LT(worst_energy, kConservationTolerance);
  EXPECT_LT(worst_momentum, kConservationTolerance);
  EXPECT_LT(worst_angular, kConservationTolerance);
}

TEST(RigidImpulse, InelasticOrFrictionalNeverGainsEnergy) {
  std::mt19937_64 rng(777);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int applied = 0, sliding = 0;
  for (int trial = 0; trial < 10000; ++trial) {
    RandomCase c = MakeRandomCase(rng);
    const double e0 = Energy(c.a) + Energy(c.b);
    const Vec3 p0 = Momentum(c.a) + Momentum(c.b);
    const double e = trial % 3 == 0 ? 1.0 : unit(rng);
    const double mu = trial % 3 == 1 ? 0.0 : 1.5 * unit(rng);
    const double pre = NormalVelocity(c.a, c.b, c.contact.points[0], c.contact.normal);
    const RigidImpulseResult r =
        ApplyRigidImpulse(c.a.state, c.b.state, c.contact, {.restitution = e, .friction = mu});
    applied += r.rounds > 0;
    // Friction (and the energy limit on it) leaves Newton's law along the normal intact.
    if (c.contact.points.size() == 1 && r.rounds > 0 && !r.guarded) {
      EXPECT_NEAR(NormalVelocity(c.a, c.b, c.contact.points[0], c.contact.normal), -e * pre,
                  kSpeedRoundOff);
    }
    sliding += r.sliding;
    EXPECT_LE(Energy(c.a) + Energy(c.b), e0 * (1 + 1e-12)) << "trial " << trial;
    EXPECT_LT((Momentum(c.a) + Momentum(c.b) - p0).norm(), 1e-12 * (1 + p0.norm()));
    EXPECT_GE(MinNormalVelocity(c), -1e-9) << "trial " << trial;
    // The total impulse on B lies in the friction cone about the normal.
    const double jn = r.impulse.dot(c.contact.normal);
    EXPECT_LE((r.impulse - jn * c.contact.normal).norm(), mu * jn + 1e-12 * (1 + jn));
  }
  EXPECT_GT(applied, 4000);
  EXPECT_GT(sliding, 500);
}

// A box (half extents h) lands flat on a floor with speed vz and sideways speed vx, struck at the
// centre of its bottom face (r = (0, 0, -c)): K_xx = 1/m + c^2 / I_yy, K_zz = 1/m, no coupling.
// It sticks iff |vx| / K_xx <= mu m (1 + e) vz.
struct BlockLanding {
  double m = 2.0, e = 0.5, mu = 0.4, vz = 1.0;
  Vec3 h = Vec3(0.5, 0.7, 0.3);
  double Kxx() const { return 1 / m + h.z() * h.z() / BoxInertia(m, h)(1, 1); }
  double Threshold() const { return mu * m * (1 + e) * vz * Kxx(); }
};

TEST(RigidImpulse, BlockOnFloorSticksOrSlidesAtTheCoulombThreshold) {
  const BlockLanding s;
  const double iyy = BoxInertia(s.m, s.h)(1, 1);
  for (const double factor : {0.0, 0.5, 0.999, 1.001, 2.0, -1.5}) {
    const double vx = factor * s.Threshold();
    Body floor = Wall();
    Body block = MakeBody(s.m, BoxInertia(s.m, s.h), Vec3(0, 0, s.h.z()));
    block.state.velocity = Vec3(vx, 0, -s.vz);
    const RigidImpulseResult r =
        ApplyRigidImpulse(floor.state, block.state, PointContact(Vec3::Zero(), Vec3::UnitZ()),
                          {.restitution = s.e, .friction = s.mu});
    const bool sticks = std::abs(factor) <= 1.0;
    const double jz = s.m * (1 + s.e) * s.vz;
    const double jx = sticks ? -vx / s.Kxx() : -s.mu * jz * (vx > 0 ? 1.0 : -1.0);
    SCOPED_TRACE(factor);
    EXPECT_EQ(r.sliding, !sticks);
    EXPECT_NEAR(block.state.velocity.z(), s.e * s.vz, 1e-13);
    EXPECT_NEAR(block.state.velocity.x(), vx + jx / s.m, 1e-13);
    EXPECT_NEAR(block.state.angular_velocity.y(), -s.h.z() * jx / iyy, 1e-13);
    if (sticks) {
      EXPECT_NEAR(PointVelocity(block, Vec3::Zero()).x(), 0.0, 1e-13);
    }
  }
}

ContactGeometry BottomFace(const Vec3& h) {
  ContactGeometry c;
  c.normal = Vec3::UnitZ();
  c.points = {Vec3(-h.x(), -h.y(), 0), Vec3(h.x(), -h.y(), 0), Vec3(h.x(), h.y(), 0),
              Vec3(-h.x(), h.y(), 0)};
  return c;
}

TEST(RigidImpulse, FlatFlushImpactGivesNoSpin) {
  const Vec3 h(0.5, 0.7, 0.3);
  for (const double e : {0.0, 0.6, 1.0}) {
    Body floor = Wall();
    Body block = MakeBody(2.0, BoxInertia(2.0, h), Vec3(0, 0, h.z()));
    block.state.velocity = Vec3(0, 0, -1.3);
    const RigidImpulseResult r =
        ApplyRigidImpulse(floor.state, block.state, BottomFace(h), {.restitution = e});
    EXPECT_EQ(r.rounds, 1);
    EXPECT_EQ(block.state.angular_velocity, Vec3::Zero());
    EXPECT_NEAR(block.state.velocity.z(), 1.3 * e, 1e-15);
    EXPECT_NEAR(r.point.norm(), 0.0, 1e-15);
  }
}

TEST(RigidImpulse, SpinningBlockLandingFlatStopsApproachingEverywhere) {
  const Vec3 h(0.5, 0.7, 0.3);
  for (const double e : {0.0, 0.5, 1.0}) {
    Body floor = Wall();
    Body block = MakeBody(2.0, BoxInertia(2.0, h), Vec3(0, 0, h.z()));
    block.state.velocity = Vec3(0.2, 0, -1.0);
    block.state.angular_velocity = Vec3(3.0, -2.0, 0.5);
    const double energy = Energy(block);
    const ContactGeometry c = BottomFace(h);
    const RigidImpulseResult r = ApplyRigidImpulse(floor.state, block.state, c, {.restitution = e});
    SCOPED_TRACE(e);
    EXPECT_GT(r.rounds, 1);
    EXPECT_LT(r.rounds, 16);
    for (const Vec3& p : c.points) EXPECT_GE(PointVelocity(block, p).z(), -1e-9);
    if (e == 1.0) {
      EXPECT_NEAR(Energy(block), energy, 1e-12 * energy);
    } else {
      EXPECT_LT(Energy(block), energy);
    }
  }
}

TEST(RigidImpulse, SeparatingContactDoesNothing) {
  Body floor = Wall();
  Body block = MakeBody(1.0, Eigen::Matrix3d::Identity(), Vec3(0, 0, 1));
  block.state.velocity = Vec3(1, 0, 0.5);
  const RigidImpulseResult r =
      ApplyRigidImpulse(floor.state, block.state, PointContact(Vec3::Zero(), Vec3::UnitZ()), {});
  EXPECT_EQ(r.rounds, 0);
  EXPECT_EQ(block.state.velocity, Vec3(1, 0, 0.5));
}

TEST(RigidImpulse, SlowApproachIsMadeElastic) {
  Body floor = Wall();
  Body block = MakeBody(1.0, Eigen::Matrix3d::Identity(), Vec3(0, 0, 1));
  block.state.velocity = Vec3(0, 0, -1e-8);
  const RigidImpulseResult r = ApplyRigidImpulse(
      floor.state, block.state, PointContact(Vec3::Zero(), Vec3::UnitZ()), {.restitution = 0.0});
  EXPECT_TRUE(r.guarded);
  EXPECT_DOUBLE_EQ(block.state.velocity.z(), 1e-8);
}

}  // namespace
}  // namespace sparsedyn
