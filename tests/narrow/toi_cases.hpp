// SPDX-License-Identifier: MIT
// Random motion cases for the contact-prediction tests: two polyhedra (random hulls of various
// face counts, boxes, slabs, needles) on rigid paths aimed so that about half of the pairs
// collide, or one polyhedron flying at a wall. Deterministic for a seed; Describe() prints a
// paste-able case.
#pragma once

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "motion/rigid_path.hpp"
#include "pair_generator.hpp"

namespace sparsedyn::testing {

struct MotionCase {
  const Shape* a = nullptr;
  const Shape* b = nullptr;
  RigidPath path_a, path_b;
  double t_begin = 0.0, t_end = 0.0;

  // A bound on how fast the distance can change (m/s) over [t_begin, t_end].
  double Lipschitz() const {
    const double dt = t_end - path_a.t0();
    return (path_b.centre.VelocityAt(path_b.t0()) - path_a.centre.VelocityAt(path_a.t0())).norm() +
           (path_b.centre.a - path_a.centre.a).norm() * std::abs(dt) +
           path_a.omega.norm() * Radius(*a) + (b ? path_b.omega.norm() * Radius(*b) : 0.0);
  }
  static double Radius(const Shape& s) {
    return s.polyhedron->centroid().norm() + s.polyhedron->bounding_radius();
  }
  std::string Describe() const {
    std::ostringstream out;
    out.precision(17);
    auto path = [&](const RigidPath& p) {
      out << "{p0 = (" << p.centre.p0.transpose() << "), v0 = (" << p.centre.v0.transpose()
          << "), a = (" << p.centre.a.transpose() << "), t0 = " << p.t0() << ", q0 = (" << p.q0.w()
          << " " << p.q0.x() << " " << p.q0.y() << " " << p.q0.z() << "), omega = ("
          << p.omega.transpose() << ")}";
    };
    out << a->name << " on ";
    path(path_a);
    if (b) {
      out << ", " << b->name << " on ";
      path(path_b);
    }
    out << ", t in [" << t_begin << ", " << t_end << "]";
    return out.str();
  }
};

class MotionCaseGenerator {
 public:
  explicit MotionCaseGenerator(std::uint64_t seed) : pairs_(seed) {
    for (const int faces : {4, 6, 9, 14, 20, 32, 48, 80, 120}) {
      shapes_.push_back(
          MakeShape("random hull F=" + std::to_string(faces),
                    *RandomConvexPolyhedron(faces, 700 + static_cast<unsigned>(faces))));
    }
    aligned_first_ = shapes_.size();
    shapes_.push_back(MakeShape("cube", *MakeBox({0.5, 0.5, 0.5})));
    shapes_.push_back(MakeShape("box 3x1x1", *MakeBox({0.75, 0.25, 0.25})));
    shapes_.push_back(MakeShape("prism 8", *MakePrism(8, 0.5, 0.4)));
    shapes_.push_back(MakeShape("slab", *MakeSlab(1.5, 200.0)));
    shapes_.push_back(MakeShape("needle", *MakeNeedle(1.5, 200.0)));
    shapes_.push_back(MakeShape("cigar", *RandomEllipsoidalPolyhedron(30, {0.4, 0.4, 1.2}, 7)));
  }

  const std::vector<Shape>& shapes() const { return shapes_; }
  PairGenerator& random() { return pairs_; }

  // A at a random pose and velocity; B at 1.1-2.5 sums of radii, its relative velocity aimed at
  // A's centre with a lateral offset up to 1.5 sums of radii (so about half of them hit).
  // `spin`: angular speeds up to this (rad/s); `accelerate`: random, different accelerations.
  MotionCase Pair(double spin, bool accelerate) {
    MotionCase c;
    c.a = Pick();
    c.b = Pick();
    const double reach = MotionCase::Radius(*c.a) + MotionCase::Radius(*c.b);
    const double t0 = Uniform() - 0.5;
    c.t_begin = t0 + 0.5 * Uniform();
    c.path_a = RandomPath(t0, 0.5 * Uniform(), spin);
    const Vec3 u = pairs_.RandomUnit();
    const Vec3 lateral = (pairs_.RandomUnit().cross(u)).normalized();
    const double distance = reach * (1.1 + 1.4 * Uniform());
    const double speed = 0.5 + 2.0 * Uniform();
    const Vec3 aim = -distance * u + reach * 1.5 * Uniform() * lateral;
    c.path_b = RandomPath(t0, 0.0, spin);
    c.path_b.centre.v0 = c.path_a.centre.v0 + speed * aim.normalized();
    // Place B so that at t_begin it is `distance` from A along u.
    c.path_b.centre.p0 = c.path_a.centre.PositionAt(c.t_begin) + distance * u -
                         (c.t_begin - t0) * c.path_b.centre.v0;
    if (accelerate && Uniform() < 0.5) {
      c.path_a.centre.a = RandomVector(1.0);
      c.path_b.centre.a = Uniform() < 0.3 ? c.path_a.centre.a : RandomVector(2.0);
      c.path_b.centre.p0 -= 0.5 * (c.t_begin - t0) * (c.t_begin - t0) * c.path_b.centre.a -
                            0.5 * (c.t_begin - t0) * (c.t_begin - t0) * c.path_a.centre.a;
    }
    c.t_end = c.t_begin + 2.5 * (distance + reach) / speed;
    return c;
  }

  // Degenerate translating pairs: boxes and prisms with a common orientation, or turned about
  // their common z axis by multiples of 45 degrees (parallel faces and parallel edges), B
  // starting 0.5-2 away along a random axis with a lateral offset on a 1/4 grid and moving
  // straight back along that axis, sometimes with a lateral drift on the same grid.
  MotionCase AlignedPair() {
    MotionCase c;
    c.a = &shapes_[aligned_first_ + pairs_.rng()() % (shapes_.size() - aligned_first_)];
    c.b = &shapes_[aligned_first_ + pairs_.rng()() % (shapes_.size() - aligned_first_)];
    const Eigen::Quaterniond common = pairs_.RandomRotation();
    auto turn = [&] {
      return common * Eigen::Quaterniond(Eigen::AngleAxisd(
                          M_PI / 4 * static_cast<double>(pairs_.rng()() % 8), Vec3::UnitZ()));
    };
    c.path_a.q0 = turn();
    c.path_b.q0 = pairs_.rng()() % 2 ? c.path_a.q0 : turn();
    const int axis = static_cast<int>(pairs_.rng()() % 3);
    auto grid = [&] {
      return 0.25 * static_cast<double>(static_cast<int>(pairs_.rng()() % 9) - 4);
    };
    Vec3 offset = scenes::DrawVector(grid);
    const double sign = pairs_.rng()() % 2 ? 1.0 : -1.0;
    offset[axis] = sign * (MotionCase::Radius(*c.a) + MotionCase::Radius(*c.b) + 0.5 + 1.5 * Uniform());
    Vec3 velocity = Vec3::Zero();
    velocity[axis] = -offset[axis] / (1.0 + Uniform());
    if (pairs_.rng()() % 2) velocity[(axis + 1) % 3] = grid();
    c.path_b.centre.p0 = common * offset;
    c.path_b.centre.v0 = common * velocity;
    c.t_end = 3.0;
    return c;
  }

  // One polyhedron (in `a`) and the wall n.x = 0 with n = `normal`: the body starts 0.1-3 above
  // it, moving towards it (or away, for a third of the cases) at 0.5-2.5 m/s.
  MotionCase Wall(const Vec3& normal, double spin, bool accelerate) {
    MotionCase c;
    c.a = Pick();
    const double r = MotionCase::Radius(*c.a);
    const double t0 = Uniform() - 0.5;
    c.t_begin = t0 + 0.5 * Uniform();
    c.path_a = RandomPath(t0, 0.0, spin);
    const double speed = 0.5 + 2.0 * Uniform();
    const double towards = 1.5 * Uniform() - 0.5;
    c.path_a.centre.v0 = speed * (pairs_.RandomUnit() - towards * normal);
    if (accelerate && Uniform() < 0.5) c.path_a.centre.a = RandomVector(2.0);
    const double height = r + 0.1 + 3.0 * Uniform();
    c.path_a.centre.p0 = Vec3(pairs_.RandomUnit() * 5.0);
    c.path_a.centre.p0 += (height - normal.dot(c.path_a.centre.PositionAt(c.t_begin))) * normal;
    c.t_end = c.t_begin + 3.0 * (height + r) / speed;
    return c;
  }

  double Uniform() { return pairs_.Uniform(); }

 private:
  const Shape* Pick() { return &shapes_[pairs_.rng()() % shapes_.size()]; }

  // A random direction times `scale` times a uniform draw: the draw first, then the direction
  // (the order GCC on x86-64 took for RandomUnit() * Uniform(), so that every compiler makes
  // the same cases; see PairGenerator::Next).
  Vec3 RandomVector(double scale) {
    const double length = Uniform();
    return pairs_.RandomUnit() * scale * length;
  }

  RigidPath RandomPath(double t0, double speed, double spin) {
    RigidPath p;
    p.centre.t0 = t0;
    p.centre.p0 = RandomVector(1.0);
    p.centre.v0 = pairs_.RandomUnit() * speed;
    p.q0 = pairs_.RandomRotation();
    if (spin > 0.0) p.omega = RandomVector(spin);
    return p;
  }

  PairGenerator pairs_;
  std::vector<Shape> shapes_;
  std::size_t aligned_first_ = 0;  // boxes, prisms, slab and needle: the aligned pairs' shapes
};

}  // namespace sparsedyn::testing
