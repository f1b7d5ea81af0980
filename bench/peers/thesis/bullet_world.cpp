// SPDX-License-Identifier: MIT
#include "bench/peers/thesis/bullet_world.hpp"

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btStaticPlaneShape.h>
#include <btBulletDynamicsCommon.h>

#include <Eigen/Eigenvalues>

namespace sparsedyn::bench {
namespace {

btVector3 ToBullet(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
Eigen::Vector3d FromBullet(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

// A scene shape in its principal frame P: R_BP (columns = principal axes, det +1) and the
// principal moments at density 1.
struct PrincipalShape {
  std::unique_ptr<btConvexHullShape> hull;
  Eigen::Quaterniond q_BP;
  Eigen::Vector3d p_BP;     // origin of P (the centroid) in B
  Eigen::Vector3d moments;  // per unit density
  double volume = 0;
};

PrincipalShape MakePrincipalShape(const ConvexPolyhedron& polyhedron) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(polyhedron.inertia());
  Eigen::Matrix3d R_BP = solver.eigenvectors();
  if (R_BP.determinant() < 0) R_BP.col(2) = -R_BP.col(2);
  PrincipalShape shape;
  shape.q_BP = Eigen::Quaterniond(R_BP).normalized();
  shape.moments = solver.eigenvalues();
  shape.p_BP = polyhedron.centroid();
  shape.volume = polyhedron.volume();
  shape.hull = std::make_unique<btConvexHullShape>();
  for (const Eigen::Vector3d& p_B : polyhedron.vertices()) {
    shape.hull->addPoint(ToBullet(R_BP.transpose() * (p_B - polyhedron.centroid())), false);
  }
  shape.hull->recalcLocalAabb();
  // Margin 0: Bullet's hull is then exactly our polyhedron (the default 0.04 would inflate it and
  // keep the true shapes apart by up to 0.08, hiding the penetrations we measure).
  shape.hull->setMargin(0);
  return shape;
}

}  // namespace

struct BulletThesisWorld::Impl {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  std::vector<PrincipalShape> shapes;
  std::vector<std::unique_ptr<btStaticPlaneShape>> wall_shapes;
  std::vector<std::unique_ptr<btDefaultMotionState>> motion_states;
  std::vector<std::unique_ptr<btRigidBody>> bodies;  // scene bodies first, then the six walls
  std::vector<std::uint32_t> shape_of;
  std::size_t body_count = 0;

  void AddWalls(const Container& box);
  void AddBody(const SceneBody& body);
  ~Impl() {
    for (auto& body : bodies) world.removeRigidBody(body.get());
  }
};

void BulletThesisWorld::Impl::AddWalls(const Container& box) {
  // Plane n.x = c with n pointing into the box.
  for (int axis = 0; axis < 3; ++axis) {
    for (const int side : {-1, 1}) {
      btVector3 normal(0, 0, 0);
      normal[axis] = -side;
      const double c = side < 0 ? box.lo[axis] : -box.hi[axis];
      wall_shapes.push_back(std::make_unique<btStaticPlaneShape>(normal, c));
      btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, wall_shapes.back().get());
      info.m_restitution = 1;
      info.m_friction = 0;
      bodies.push_back(std::make_unique<btRigidBody>(info));
      world.addRigidBody(bodies.back().get());
    }
  }
}

void BulletThesisWorld::Impl::AddBody(const SceneBody& body) {
  const PrincipalShape& shape = shapes[body.shape];
  const double density = body.mass / shape.volume;
  const Eigen::Quaterniond q_WP = body.orientation * shape.q_BP;
  const Eigen::Vector3d p_WP = body.position + body.orientation * shape.p_BP;
  const btTransform X_WP(btQuaternion(q_WP.x(), q_WP.y(), q_WP.z(), q_WP.w()), ToBullet(p_WP));
  motion_states.push_back(std::make_unique<btDefaultMotionState>(X_WP));

  // Mass and inertia are the scene's, not Bullet's calculateLocalInertia (a box estimate).
  btRigidBody::btRigidBodyConstructionInfo info(
      body.mass, motion_states.back().get(), shape.hull.get(), ToBullet(density * shape.moments));
  info.m_restitution = body.restitution;
  info.m_friction = body.friction;
  info.m_rollingFriction = 0;
  info.m_spinningFriction = 0;
  info.m_linearDamping = 0;
  info.m_angularDamping = 0;
  bodies.push_back(std::make_unique<btRigidBody>(info));
  btRigidBody& rigid = *bodies.back();
  rigid.setLinearVelocity(ToBullet(body.velocity));
  rigid.setAngularVelocity(ToBullet(body.angular_velocity));
  rigid.setActivationState(DISABLE_DEACTIVATION);
  world.addRigidBody(&rigid);
  shape_of.push_back(body.shape);
}

BulletThesisWorld::BulletThesisWorld(const SceneDescription& scene) : impl_(new Impl) {
  impl_->world.setGravity(ToBullet(scene.settings.gravity));
  // Restitution at every approach speed (Bullet's default zeroes it below 0.2 m/s).
  impl_->world.getSolverInfo().m_restitutionVelocityThreshold = 0;
  for (const SceneShape& shape : scene.shapes) {
    impl_->shapes.push_back(MakePrincipalShape(*shape.polyhedron));
  }
  impl_->bodies.reserve(scene.bodies.size() + 6);
  impl_->motion_states.reserve(scene.bodies.size());
  for (const SceneBody& body : scene.bodies) impl_->AddBody(body);
  impl_->body_count = scene.bodies.size();
  impl_->AddWalls(scene.settings.container);
}

BulletThesisWorld::~BulletThesisWorld() = default;

void BulletThesisWorld::Step(double dt) { impl_->world.stepSimulation(dt, 0); }

std::size_t BulletThesisWorld::BodyCount() const { return impl_->body_count; }

Pose BulletThesisWorld::PoseOf(std::size_t i) const {
  const btTransform& X_WP = impl_->bodies[i]->getCenterOfMassTransform();
  const btQuaternion r = X_WP.getRotation();
  const PrincipalShape& shape = impl_->shapes[impl_->shape_of[i]];
  Pose X_WB;
  X_WB.rotation =
      (Eigen::Quaterniond(r.w(), r.x(), r.y(), r.z()) * shape.q_BP.conjugate()).normalized();
  X_WB.translation = FromBullet(X_WP.getOrigin()) - X_WB.rotation * shape.p_BP;
  return X_WB;
}

double BulletThesisWorld::KineticEnergy() const {
  double energy = 0;
  for (std::size_t i = 0; i < impl_->body_count; ++i) {
    const btRigidBody& body = *impl_->bodies[i];
    const double mass = 1.0 / body.getInvMass();
    // 1/2 w_P . I_P w_P in the principal frame, with Bullet's own (diagonal) local inertia.
    const btVector3 w_P =
        body.getCenterOfMassTransform().getBasis().transpose() * body.getAngularVelocity();
    const btVector3 inv = body.getInvInertiaDiagLocal();
    double rotational = 0;
    for (int k = 0; k < 3; ++k) rotational += w_P[k] * w_P[k] / inv[k];
    energy += 0.5 * mass * body.getLinearVelocity().length2() + 0.5 * rotational;
  }
  return energy;
}

}  // namespace sparsedyn::bench
