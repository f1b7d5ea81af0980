// SPDX-License-Identifier: MIT
// The impulse of a sphere-polyhedron contact: PredictSphereContact's result, turned into a
// one-point ContactGeometry, through ApplyRigidImpulse. A spinning sphere hitting a static
// (tilted) cube on a face, an edge and a vertex against the closed-form reflection with
// restitution and Coulomb friction; a free, spinning cube and a sphere conserving energy,
// momentum and angular momentum (elastic, frictionless) or losing energy (otherwise).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "dynamics/sphere_polyhedron_contact.hpp"
#include "narrow/sphere_contact.hpp"
#include "pair_generator.hpp"

namespace sparsedyn {
namespace {

using Kind = ContactPrediction::Kind;

// A tolerance small enough that the contact point's offset from the surface (half the gap)
// changes the lever arm only at round-off; the closed form uses the same lever arm anyway.
constexpr double kTolerance = 1e-9;
// Velocities O(1) after a few 3x3 products and one normal's round-off.
constexpr double kVelocityError = 1e-9;

struct Reflection {
  Vec3 v, w;
};

// A solid sphere (mass m, radius r: I = 2/5 m r^2) hitting a static body at the point
// `centre - l n`, n the unit normal from the body to the sphere, with Newton restitution e and
// Coulomb friction mu (e.g. Stronge, "Impact mechanics", 2000, §5 for a sphere on a plane).
// The contact point's velocity is u = v + w x (-l n); the normal impulse
// j_n = -(1 + e) m (v . n) (the spin moves that point only tangentially); tangentially an
// impulse j_t changes u by j_t (1/m + l^2 / I), so sticking needs j_t = -u_t / (1/m + l^2/I),
// accepted when |j_t| <= mu j_n, else sliding: j_t = -mu j_n u_t / |u_t|. The normal and
// tangential parts decouple for a sphere, so no energy correction applies.
Reflection ClosedForm(const Vec3& v, const Vec3& w, const Vec3& n, double m, double r, double l,
                      double e, double mu) {
  const double inertia = 0.4 * m * r * r;
  const Vec3 u = v + w.cross(-l * n);
  const Vec3 u_t = u - u.dot(n) * n;
  const double j_n = -(1.0 + e) * m * v.dot(n);
  Vec3 j_t = -u_t / (1.0 / m + l * l / inertia);
  if (j_t.norm() > mu * j_n)
    j_t = u_t.norm() > 0.0 ? Vec3(-mu * j_n * u_t.normalized()) : Vec3::Zero();
  const Vec3 j = j_n * n + j_t;
  return {v + j / m, w + (-l * n).cross(j) / inertia};
}

// A static cube [-1, 1]^3 at a tilted pose; the sphere approaches the surface point P_B
// (body frame) along the outward direction n_B at the time T = 1 with velocity v, which keeps
// its centre in P's zone all the way (so the first contact is there, at T).
void HitAndReflect(const Vec3& P_B, const Vec3& n_B, const char* what) {
  SCOPED_TRACE(what);
  const testing::Shape cube = testing::MakeShape("cube", *MakeBox({1, 1, 1}));
  RigidPath box;
  box.q0 = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Vec3(1, -2, 0.5).normalized()));
  box.centre.p0 = {0.3, -1.2, 2.0};
  const Vec3 n = box.q0 * n_B.normalized();
  const double m = 2.0, r = 0.3, T = 1.0;
  // Approaching along -n with a small sideways part, spinning.
  const Vec3 sideways = (n.cross(Vec3(0.3, 0.4, 0.5))).normalized();
  const Vec3 v = -2.0 * n + 0.3 * sideways;
  const Vec3 w(1.5, -2.0, 0.7);
  const Vec3 touching = box.PoseAt(0).ToWorld(P_B) + (r + kTolerance) * n;
  const Path centre{touching - T * v, v, Vec3::Zero(), 0.0};
  ContactPredictionOptions options;
  options.tolerance = kTolerance;
  const SphereContactPrediction p =
      PredictSphereContact(*cube.tracked, box, centre, r, 0.0, 3.0, std::nullopt, options);
  ASSERT_EQ(p.kind, Kind::kContact);
  EXPECT_NEAR(p.time, T, 1e-9);
  const ContactGeometry contact = SphereContactGeometry(p.closest, r);
  ASSERT_EQ(contact.points.size(), 1u);
  EXPECT_LT((contact.normal - n).norm(), 1e-8);
  EXPECT_LE(contact.distance, kTolerance);
  const Vec3 c = centre.PositionAt(p.time);
  EXPECT_LT((contact.points[0] - (c - (r + 0.5 * contact.distance) * contact.normal)).norm(),
            1e-14);
  const double l = (c - contact.points[0]).norm();

  for (const auto& [e, mu] : {std::pair{1.0, 0.0}, {0.6, 0.0}, {0.6, 0.05}, {0.6, 2.0}}) {
    SCOPED_TRACE(::testing::Message() << "e " << e << " mu " << mu);
    RigidBodyState wall;  // static: zero inverse mass and inertia
    RigidBodyState ball = SolidSphereState(c, v, w, m, r);
    const RigidImpulseResult result =
        ApplyRigidImpulse(wall, ball, contact, {.restitution = e, .friction = mu});
    EXPECT_EQ(result.rounds, 1);
    const Reflection expected = ClosedForm(v, w, contact.normal, m, r, l, e, mu);
    EXPECT_LT((ball.velocity - expected.v).norm(), kVelocityError);
    EXPECT_LT((ball.angular_velocity - expected.w).norm(), kVelocityError);
    EXPECT_EQ(result.sliding, mu == 0.05);
    EXPECT_EQ(wall.velocity, Vec3::Zero());
  }
}

TEST(SphereImpulse, HittingAStaticCubeOnAFaceReflectsAsTheClosedForm) {
  HitAndReflect({0.2, -0.3, 1.0}, {0, 0, 1}, "face");
}

TEST(SphereImpulse, HittingAStaticCubeOnAnEdgeReflectsAsTheClosedForm) {
  HitAndReflect({0.1, 1.0, 1.0}, {0, 1, 1.6}, "edge");
}

TEST(SphereImpulse, HittingAStaticCubeOnAVertexReflectsAsTheClosedForm) {
  HitAndReflect({1.0, 1.0, 1.0}, {1.3, 1, 0.8}, "vertex");
}

// A free, spinning polyhedron and a sphere: at restitution 1 without friction the impulse
// conserves kinetic energy, momentum and angular momentum (about the origin); otherwise the
// energy never rises and the contact point stops approaching.
TEST(SphereImpulse, FreePolyhedronAndSphereConserveOrLoseEnergy) {
  testing::PairGenerator gen(20261216);
  const testing::Shape hull = testing::MakeShape("hull", *RandomConvexPolyhedron(20, 77));
  const ConvexPolyhedron& poly = *hull.polyhedron;
  int contacts = 0;
  for (int trial = 0; trial < 200; ++trial) {
    RigidPath path;
    path.q0 = gen.RandomRotation();
    path.omega = gen.RandomUnit() * 3.0 * gen.Uniform();
    path.centre.v0 = gen.RandomUnit() * gen.Uniform();
    const double r = 0.2 + 0.6 * gen.Uniform();
    const Vec3 start = 2.5 * gen.RandomUnit();
    const Path centre{start, -start.normalized() * 2.0 + 0.5 * gen.RandomUnit(), Vec3::Zero(), 0.0};
    ContactPredictionOptions options;
    options.tolerance = kTolerance;
    const SphereContactPrediction p =
        PredictSphereContact(*hull.tracked, path, centre, r, 0.0, 5.0, std::nullopt, options);
    if (p.kind != Kind::kContact || p.time == 0.0) continue;
    ++contacts;
    const ContactGeometry contact = SphereContactGeometry(p.closest, r);
    const double m_a = 3.0, m_b = 0.5 + gen.Uniform();
    const Eigen::Matrix3d R = path.OrientationAt(p.time).toRotationMatrix();
    const Eigen::Matrix3d I_a = R * (poly.inertia() * (m_a / poly.volume())) * R.transpose();
    const Eigen::Matrix3d I_b = 0.4 * m_b * r * r * Eigen::Matrix3d::Identity();
    RigidBodyState a{path.centre.PositionAt(p.time), path.centre.VelocityAt(p.time), path.omega,
                     1.0 / m_a, I_a.inverse()};
    RigidBodyState b = SolidSphereState(centre.PositionAt(p.time), centre.VelocityAt(p.time),
                                        gen.RandomUnit(), m_b, r);
    auto energy = [&] {
      return 0.5 * m_a * a.velocity.squaredNorm() +
             0.5 * a.angular_velocity.dot(I_a * a.angular_velocity) +
             0.5 * m_b * b.velocity.squaredNorm() +
             0.5 * b.angular_velocity.dot(I_b * b.angular_velocity);
    };
    auto momentum = [&] { return Vec3(m_a * a.velocity + m_b * b.velocity); };
    auto angular = [&] {
      return Vec3(m_a * a.centre.cross(a.velocity) + I_a * a.angular_velocity +
                  m_b * b.centre.cross(b.velocity) + I_b * b.angular_velocity);
    };
    const RigidBodyState a0 = a, b0 = b;
    const double e0 = energy();
    const Vec3 p0 = momentum(), l0 = angular();
    ApplyRigidImpulse(a, b, contact, {.restitution = 1.0});
    EXPECT_NEAR(energy(), e0, 1e-12 * e0);
    EXPECT_LT((momentum() - p0).norm(), 1e-12 * (1 + p0.norm()));
    EXPECT_LT((angular() - l0).norm(), 1e-12 * (1 + l0.norm()));
    a = a0;
    b = b0;
    ApplyRigidImpulse(a, b, contact, {.restitution = 0.5, .friction = 0.5});
    EXPECT_LE(energy(), e0 * (1 + 1e-12));
    const Vec3& q = contact.points[0];
    const Vec3 u = (b.velocity + b.angular_velocity.cross(q - b.centre)) -
                   (a.velocity + a.angular_velocity.cross(q - a.centre));
    EXPECT_GE(u.dot(contact.normal), -1e-12);
  }
  EXPECT_GE(contacts, 50);
}

}  // namespace
}  // namespace sparsedyn
