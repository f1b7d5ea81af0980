// SPDX-License-Identifier: MIT
// Random pairs of placed convex polyhedra for the closest-feature tests: generic pairs of random
// hulls and solids, and the degenerate classes of issue #3 (parallel faces, parallel edges,
// vertices exactly on zone planes, exact touching, 1e-12 gaps, needles and slabs, scales 1e-3 and
// 1e3, pairs translated by 1e6). Deterministic for a seed; Describe() prints a paste-able case.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "scenes/random.hpp"
#include "sparsedyn/geometry/generators.hpp"
#include "sparsedyn/narrow/closest_features.hpp"

namespace sparsedyn::testing {

struct Shape {
  std::string name;
  std::shared_ptr<const ConvexPolyhedron> polyhedron;
  std::shared_ptr<TrackedPolyhedron> tracked;
};

inline Shape MakeShape(std::string name, ConvexPolyhedron poly) {
  auto shared = std::make_shared<const ConvexPolyhedron>(poly.Recentered());
  return {std::move(name), shared, std::make_shared<TrackedPolyhedron>(shared)};
}

// A pyramid over a regular n-gon: its apex has n edges (a vertex J.1.1 table).
inline ConvexPolyhedron MakePyramid(int sides, double height) {
  std::vector<Eigen::Vector3d> points{{0.0, 0.0, height}};
  for (int i = 0; i < sides; ++i) {
    const double angle = 2.0 * M_PI * i / sides;
    points.emplace_back(std::cos(angle), std::sin(angle), 0.0);
  }
  return *ConvexPolyhedron::FromPoints(points);
}

struct PlacedPair {
  const Shape* a = nullptr;
  const Shape* b = nullptr;
  Pose X_WA, X_WB;
  std::string kind;
  bool degenerate = false;

  // The larger bounding diameter: the scale of the error bound.
  double Diameter() const {
    return 2.0 * std::max(a->polyhedron->bounding_radius(), b->polyhedron->bounding_radius());
  }
  std::string Describe() const {
    std::ostringstream out;
    out.precision(17);
    auto pose = [&](const Pose& X) {
      out << "{t = (" << X.translation.transpose() << "), q = (" << X.rotation.w() << " "
          << X.rotation.x() << " " << X.rotation.y() << " " << X.rotation.z() << ")}";
    };
    out << kind << ": " << a->name << " at ";
    pose(X_WA);
    out << ", " << b->name << " at ";
    pose(X_WB);
    return out.str();
  }
};

class PairGenerator {
 public:
  explicit PairGenerator(std::uint64_t seed) : rng_(seed) {
    for (int i = 0; i < 16; ++i) {
      const int faces = 4 + static_cast<int>((i * 7) % 45);
      generic_.push_back(
          MakeShape("random hull F=" + std::to_string(faces) + " seed " + std::to_string(100 + i),
                    *RandomConvexPolyhedron(faces, 100 + static_cast<std::uint64_t>(i))));
    }
    generic_.push_back(MakeShape("cigar", *RandomEllipsoidalPolyhedron(30, {1, 1, 3}, 7)));
    generic_.push_back(MakeShape("disc", *RandomEllipsoidalPolyhedron(24, {2, 2, 0.4}, 8)));
    for (int s = 0; s < kPlatonicSolidCount; ++s) {
      const auto solid = static_cast<PlatonicSolid>(s);
      generic_.push_back(MakeShape(std::string(ToString(solid)), MakeSolid(solid)));
    }
    for (const ArchimedeanSolid solid :
         {ArchimedeanSolid::kCuboctahedron, ArchimedeanSolid::kTruncatedOctahedron,
          ArchimedeanSolid::kRhombicuboctahedron, ArchimedeanSolid::kTruncatedIcosahedron}) {
      generic_.push_back(MakeShape(std::string(ToString(solid)), MakeSolid(solid)));
    }
    for (const int sides : {3, 8, 12, 24}) {
      generic_.push_back(MakeShape("prism " + std::to_string(sides), *MakePrism(sides, 1.0, 0.6)));
    }
    generic_.push_back(MakeShape("pyramid 12", MakePyramid(12, 1.5)));
    generic_.push_back(MakeShape("pyramid 20", MakePyramid(20, 0.7)));
    boxes_.push_back(MakeShape("cube", *MakeBox({1, 1, 1})));
    boxes_.push_back(MakeShape("box 3x1x1", *MakeBox({1.5, 0.5, 0.5})));
    boxes_.push_back(MakeShape("prism 8", *MakePrism(8, 1.0, 1.0)));
    thin_.push_back(MakeShape("needle", *MakeNeedle(2.0)));
    thin_.push_back(MakeShape("slab", *MakeSlab(2.0)));
    for (const double scale : {1e-3, 1e3}) {
      for (int i = 0; i < 3; ++i) {
        scaled_.push_back(
            MakeShape("random hull F=" + std::to_string(8 + 10 * i) + " x" + std::to_string(scale),
                      RandomConvexPolyhedron(8 + 10 * i, 300 + static_cast<std::uint64_t>(i))
                          ->Scaled(scale)));
      }
    }
  }

  // One pair; about 40% from the degenerate classes. Every draw is sequenced, in the order
  // GCC on x86-64 took them as function arguments and operands (b before a, z before x; see
  // scenes::DrawVector), so that every compiler makes the same pairs from a seed.
  PlacedPair Next() {
    const int kind = static_cast<int>(rng_() % 20);
    if (kind < 12) {
      const Shape* b = Pick(generic_);
      return Generic(Pick(generic_), b, "generic");
    }
    switch (kind) {
      case 12:
        return ParallelFaces();
      case 13:
        return ParallelEdges();
      case 14:
        return OnZonePlanes();
      case 15:
        return Touching(0.0, "exact touching");
      case 16:
        return Touching(1e-12, "1e-12 gap");
      case 17: {
        const Shape* b = Pick(rng_() % 2 ? thin_ : generic_);
        return Generic(Pick(thin_), b, "needle/slab", true);
      }
      case 18: {
        const std::vector<Shape>& pool = scaled_;
        const std::size_t half = pool.size() / 2;
        const std::size_t offset = rng_() % 2 ? half : 0;
        const Shape* b = &pool[offset + rng_() % half];
        return Generic(&pool[offset + rng_() % half], b, "scaled", true);
      }
      default: {
        const Shape* b = Pick(generic_);
        PlacedPair pair = Generic(Pick(generic_), b, "translated by 1e6", true);
        const Eigen::Vector3d far = 1e6 * Eigen::Vector3d(1.0, -0.7, 0.3) + RandomUnit() * 1e5;
        pair.X_WA.translation += far;
        pair.X_WB.translation += far;
        return pair;
      }
    }
  }

  double Uniform() { return static_cast<double>(rng_() >> 11) * 0x1.0p-53; }
  Eigen::Vector3d RandomUnit() {
    while (true) {
      const Eigen::Vector3d p = scenes::DrawVector([&] { return 2 * Uniform() - 1; });
      if (p.squaredNorm() > 1e-4 && p.squaredNorm() <= 1.0) return p.normalized();
    }
  }
  Eigen::Quaterniond RandomRotation() {
    return scenes::DrawQuaternion([&] { return 2 * Uniform() - 1; }).normalized();
  }
  std::mt19937_64& rng() { return rng_; }
  const std::vector<Shape>& generic_shapes() const { return generic_; }

 private:
  const Shape* Pick(const std::vector<Shape>& pool) { return &pool[rng_() % pool.size()]; }

  // Random orientations; B's centroid at ratio * (r_A + r_B) from A's in a random direction,
  // the ratio uniform in [0.35, 1.25] so that roughly half the pairs overlap.
  PlacedPair Generic(const Shape* a, const Shape* b, std::string kind, bool degenerate = false) {
    PlacedPair pair{a, b, {}, {}, std::move(kind), degenerate};
    pair.X_WA.rotation = RandomRotation();
    pair.X_WA.translation =
        scenes::DrawVector([&] { return Uniform(); }) * a->polyhedron->bounding_radius();
    pair.X_WB.rotation = RandomRotation();
    const double ratio = 0.35 + 0.9 * Uniform();
    pair.X_WB.translation =
        pair.X_WA.translation +
        ratio * (a->polyhedron->bounding_radius() + b->polyhedron->bounding_radius()) *
            RandomUnit();
    return pair;
  }

  // Boxes and prisms with a common orientation, stacked along z with a gap from {-0.3, 0, 0.2}
  // and a lateral offset on a 1/4 grid: parallel faces, often partly overlapping.
  PlacedPair ParallelFaces() {
    const Shape* a = Pick(boxes_);
    const Shape* b = Pick(boxes_);
    PlacedPair pair{a, b, {}, {}, "parallel faces", true};
    const Eigen::Quaterniond common =
        rng_() % 2 ? Eigen::Quaterniond::Identity() : RandomRotation();
    pair.X_WA.rotation = pair.X_WB.rotation = common;
    const double gaps[] = {-0.3, 0.0, 0.2, 0.2};
    const double lateral_x = 0.25 * static_cast<double>(static_cast<int>(rng_() % 13) - 6);
    const double lateral_y = 0.25 * static_cast<double>(static_cast<int>(rng_() % 13) - 6);
    const double height = HalfHeight(*a) + HalfHeight(*b) + gaps[rng_() % 4];
    pair.X_WB.translation = common * Eigen::Vector3d(lateral_x, lateral_y, height);
    return pair;
  }

  // Two boxes turned about z by independent multiples of 45 degrees: vertical edges parallel.
  PlacedPair ParallelEdges() {
    const Shape* a = Pick(boxes_);
    const Shape* b = Pick(boxes_);
    PlacedPair pair{a, b, {}, {}, "parallel edges", true};
    pair.X_WA.rotation = Eigen::Quaterniond(
        Eigen::AngleAxisd(M_PI / 4 * static_cast<double>(rng_() % 8), Eigen::Vector3d::UnitZ()));
    pair.X_WB.rotation = Eigen::Quaterniond(
        Eigen::AngleAxisd(M_PI / 4 * static_cast<double>(rng_() % 8), Eigen::Vector3d::UnitZ()));
    const double angle = 2 * M_PI * Uniform();
    const double distance = 1.5 + 2.0 * Uniform();
    pair.X_WB.translation = Eigen::Vector3d(distance * std::cos(angle), distance * std::sin(angle),
                                            0.5 * (Uniform() - 0.5));
    return pair;
  }

  // Axis-aligned boxes offset on a 1/2 grid: B's vertices land exactly on A's zone planes.
  PlacedPair OnZonePlanes() {
    const Shape* a = &boxes_[0];
    const Shape* b = &boxes_[static_cast<std::size_t>(rng_() % 2)];
    PlacedPair pair{a, b, {}, {}, "vertex on a zone plane", true};
    Eigen::Vector3d offset;
    for (int i = 0; i < 3; ++i)
      offset[i] = 0.5 * static_cast<double>(static_cast<int>(rng_() % 11) - 5);
    if (offset.cwiseAbs().maxCoeff() < 2.5) offset[static_cast<int>(rng_() % 3)] = 3.0;
    pair.X_WB.translation = offset;
    return pair;
  }

  // Cube faces (or a cube and a rotated cube's vertex) at exactly `gap` along a random axis.
  PlacedPair Touching(double gap, std::string kind) {
    const Shape* a = &boxes_[0];
    PlacedPair pair{a, a, {}, {}, std::move(kind), true};
    const int axis = static_cast<int>(rng_() % 3);
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    offset[axis] = (rng_() % 2 ? 1.0 : -1.0) * (2.0 + gap);
    offset[(axis + 1) % 3] = 0.125 * static_cast<double>(static_cast<int>(rng_() % 33) - 16);
    if (rng_() % 2) {
      // A vertex of B touches the face: B turned so its corner (1,1,1) points along -axis.
      const Eigen::Vector3d corner = Eigen::Vector3d::Ones().normalized();
      Eigen::Vector3d target = Eigen::Vector3d::Zero();
      target[axis] = offset[axis] > 0 ? -1.0 : 1.0;
      pair.X_WB.rotation = Eigen::Quaterniond::FromTwoVectors(corner, target);
      offset[axis] = (offset[axis] > 0 ? 1.0 : -1.0) * (1.0 + std::sqrt(3.0) + gap);
    }
    pair.X_WB.translation = offset;
    return pair;
  }

  static double HalfHeight(const Shape& shape) {
    double h = 0.0;
    for (const Eigen::Vector3d& p : shape.polyhedron->vertices()) h = std::max(h, p.z());
    return h;
  }

  std::mt19937_64 rng_;
  std::vector<Shape> generic_, boxes_, thin_, scaled_;
};

}  // namespace sparsedyn::testing
