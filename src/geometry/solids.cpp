// SPDX-License-Identifier: MIT
// Platonic and Archimedean solids from their standard Cartesian coordinates (sign changes and
// permutations of a few base points; see each solid's Wikipedia page), boxes, prisms, needles
// and slabs.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "sparsedyn/assert.hpp"
#include "sparsedyn/geometry/generators.hpp"

namespace sparsedyn {

namespace {

using Points = std::vector<Eigen::Vector3d>;

constexpr double kPhi = std::numbers::phi;

// Which sign patterns of (+-x, +-y, +-z) to take.
enum class Signs { kAll, kEvenMinus, kOddMinus };

// Sign changes of p (a zero coordinate gives one point, not two) filtered by `signs`.
Points SignChanges(const Eigen::Vector3d& p, Signs signs) {
  Points out;
  for (int mask = 0; mask < 8; ++mask) {
    int minus_count = 0;
    Eigen::Vector3d q = p;
    bool duplicate = false;
    for (int i = 0; i < 3; ++i) {
      if ((mask >> i) & 1) {
        if (p[i] == 0.0) duplicate = true;
        q[i] = -q[i];
        ++minus_count;
      }
    }
    if (duplicate) continue;
    if (signs == Signs::kEvenMinus && minus_count % 2 != 0) continue;
    if (signs == Signs::kOddMinus && minus_count % 2 == 0) continue;
    out.push_back(q);
  }
  return out;
}

// The three cyclic (even) permutations of p, and the three odd ones.
Points EvenPermutations(const Eigen::Vector3d& p) {
  return {p, {p.y(), p.z(), p.x()}, {p.z(), p.x(), p.y()}};
}
Points OddPermutations(const Eigen::Vector3d& p) {
  return {{p.y(), p.x(), p.z()}, {p.x(), p.z(), p.y()}, {p.z(), p.y(), p.x()}};
}
Points AllPermutations(const Eigen::Vector3d& p) {
  Points out = EvenPermutations(p);
  const Points odd = OddPermutations(p);
  out.insert(out.end(), odd.begin(), odd.end());
  return out;
}

// Union over base points of permutations x sign changes, without exact duplicates.
Points Orbit(std::initializer_list<Eigen::Vector3d> bases,
             Points (*permute)(const Eigen::Vector3d&), Signs signs = Signs::kAll) {
  Points out;
  for (const Eigen::Vector3d& base : bases) {
    for (const Eigen::Vector3d& permuted : permute(base)) {
      for (const Eigen::Vector3d& q : SignChanges(permuted, signs)) {
        if (std::find(out.begin(), out.end(), q) == out.end()) out.push_back(q);
      }
    }
  }
  return out;
}

Points Concat(Points a, const Points& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// Snub cube: even permutations of (+-1, +-1/t, +-t) with an odd number of plus signs (an even
// number of minus signs) and odd permutations with an even number of plus signs (odd minus
// signs); t is the tribonacci constant, the real root of t^3 = t^2 + t + 1.
Points SnubCube() {
  const double t =
      (1.0 + std::cbrt(19.0 + 3.0 * std::sqrt(33.0)) + std::cbrt(19.0 - 3.0 * std::sqrt(33.0))) /
      3.0;
  const Eigen::Vector3d base(1.0, 1.0 / t, t);
  return Concat(Orbit({base}, EvenPermutations, Signs::kEvenMinus),
                Orbit({base}, OddPermutations, Signs::kOddMinus));
}

// Snub dodecahedron: even permutations of five base points with an even number of plus signs
// (an odd number of minus signs, since there are three coordinates), where alpha = xi - 1/xi,
// beta = xi phi + phi^2 + phi / xi and xi is the real root of xi^3 - 2 xi = phi.
Points SnubDodecahedron() {
  const double root = std::sqrt(kPhi - 5.0 / 27.0);
  const double xi = std::cbrt(kPhi / 2.0 + root / 2.0) + std::cbrt(kPhi / 2.0 - root / 2.0);
  const double a = xi - 1.0 / xi;
  const double b = xi * kPhi + kPhi * kPhi + kPhi / xi;
  const double p = kPhi;
  return Orbit({Eigen::Vector3d(2 * a, 2, 2 * b),
                Eigen::Vector3d(a + b / p + p, -a * p + b + 1 / p, a / p + b * p - 1),
                Eigen::Vector3d(-a / p + b * p + 1, -a + b / p - p, a * p + b - 1 / p),
                Eigen::Vector3d(-a / p + b * p - 1, a - b / p - p, a * p + b + 1 / p),
                Eigen::Vector3d(a + b / p - p, a * p - b + 1 / p, a / p + b * p + 1)},
               EvenPermutations, Signs::kOddMinus);
}

ConvexPolyhedron HullOf(const Points& points, std::string_view name) {
  Result<ConvexPolyhedron> hull = ConvexPolyhedron::FromPoints(points);
  SPARSEDYN_ASSERT(hull.ok(),
                   std::string(name) + ": " + (hull.ok() ? std::string() : hull.error().message));
  return std::move(hull).value();
}

}  // namespace

std::string_view ToString(PlatonicSolid solid) {
  static constexpr std::array<std::string_view, kPlatonicSolidCount> kNames = {
      "tetrahedron", "cube", "octahedron", "dodecahedron", "icosahedron"};
  return kNames[static_cast<std::size_t>(solid)];
}

std::string_view ToString(ArchimedeanSolid solid) {
  static constexpr std::array<std::string_view, kArchimedeanSolidCount> kNames = {
      "truncated tetrahedron",
      "cuboctahedron",
      "truncated cube",
      "truncated octahedron",
      "rhombicuboctahedron",
      "truncated cuboctahedron",
      "snub cube",
      "icosidodecahedron",
      "truncated dodecahedron",
      "truncated icosahedron",
      "rhombicosidodecahedron",
      "truncated icosidodecahedron",
      "snub dodecahedron"};
  return kNames[static_cast<std::size_t>(solid)];
}

int FaceCount(PlatonicSolid solid) {
  static constexpr std::array<int, kPlatonicSolidCount> kFaces = {4, 6, 8, 12, 20};
  return kFaces[static_cast<std::size_t>(solid)];
}

int FaceCount(ArchimedeanSolid solid) {
  static constexpr std::array<int, kArchimedeanSolidCount> kFaces = {8,  14, 14, 14, 26, 26, 38,
                                                                     32, 32, 32, 62, 62, 92};
  return kFaces[static_cast<std::size_t>(solid)];
}

std::vector<Eigen::Vector3d> SolidVertices(PlatonicSolid solid) {
  switch (solid) {
    case PlatonicSolid::kTetrahedron:
      return Orbit({Eigen::Vector3d(1, 1, 1)}, EvenPermutations, Signs::kEvenMinus);
    case PlatonicSolid::kCube:
      return Orbit({Eigen::Vector3d(1, 1, 1)}, EvenPermutations);
    case PlatonicSolid::kOctahedron:
      return Orbit({Eigen::Vector3d(1, 0, 0)}, EvenPermutations);
    case PlatonicSolid::kDodecahedron:
      return Orbit({Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(0, 1 / kPhi, kPhi)},
                   EvenPermutations);
    case PlatonicSolid::kIcosahedron:
      return Orbit({Eigen::Vector3d(0, 1, kPhi)}, EvenPermutations);
  }
  return {};
}

std::vector<Eigen::Vector3d> SolidVertices(ArchimedeanSolid solid) {
  const double s2 = std::numbers::sqrt2;
  const double p = kPhi;
  switch (solid) {
    case ArchimedeanSolid::kTruncatedTetrahedron:
      return Orbit({Eigen::Vector3d(3, 1, 1)}, AllPermutations, Signs::kEvenMinus);
    case ArchimedeanSolid::kCuboctahedron:
      return Orbit({Eigen::Vector3d(1, 1, 0)}, AllPermutations);
    case ArchimedeanSolid::kTruncatedCube:
      return Orbit({Eigen::Vector3d(s2 - 1, 1, 1)}, AllPermutations);
    case ArchimedeanSolid::kTruncatedOctahedron:
      return Orbit({Eigen::Vector3d(0, 1, 2)}, AllPermutations);
    case ArchimedeanSolid::kRhombicuboctahedron:
      return Orbit({Eigen::Vector3d(1, 1, 1 + s2)}, AllPermutations);
    case ArchimedeanSolid::kTruncatedCuboctahedron:
      return Orbit({Eigen::Vector3d(1, 1 + s2, 1 + 2 * s2)}, AllPermutations);
    case ArchimedeanSolid::kSnubCube:
      return SnubCube();
    case ArchimedeanSolid::kIcosidodecahedron:
      return Concat(Orbit({Eigen::Vector3d(0, 0, p)}, AllPermutations),
                    Orbit({Eigen::Vector3d(0.5, p / 2, p * p / 2)}, EvenPermutations));
    case ArchimedeanSolid::kTruncatedDodecahedron:
      return Orbit({Eigen::Vector3d(0, 1 / p, 2 + p), Eigen::Vector3d(1 / p, p, 2 * p),
                    Eigen::Vector3d(p, 2, p + 1)},
                   EvenPermutations);
    case ArchimedeanSolid::kTruncatedIcosahedron:
      return Orbit({Eigen::Vector3d(0, 1, 3 * p), Eigen::Vector3d(1, 2 + p, 2 * p),
                    Eigen::Vector3d(p, 2, 2 * p + 1)},
                   EvenPermutations);
    case ArchimedeanSolid::kRhombicosidodecahedron:
      return Orbit({Eigen::Vector3d(1, 1, p * p * p), Eigen::Vector3d(p * p, p, 2 * p),
                    Eigen::Vector3d(2 + p, 0, p * p)},
                   EvenPermutations);
    case ArchimedeanSolid::kTruncatedIcosidodecahedron:
      return Orbit({Eigen::Vector3d(1 / p, 1 / p, 3 + p), Eigen::Vector3d(2 / p, p, 1 + 2 * p),
                    Eigen::Vector3d(1 / p, p * p, -1 + 3 * p), Eigen::Vector3d(2 * p - 1, 2, 2 + p),
                    Eigen::Vector3d(p, 3, 2 * p)},
                   EvenPermutations);
    case ArchimedeanSolid::kSnubDodecahedron:
      return SnubDodecahedron();
  }
  return {};
}

ConvexPolyhedron MakeSolid(PlatonicSolid solid) {
  return HullOf(SolidVertices(solid), ToString(solid));
}

ConvexPolyhedron MakeSolid(ArchimedeanSolid solid) {
  return HullOf(SolidVertices(solid), ToString(solid));
}

Result<ConvexPolyhedron> MakeBox(const Eigen::Vector3d& half_extents) {
  if (!(half_extents.allFinite() && half_extents.minCoeff() > 0.0)) {
    return Error{"box half extents must be finite and > 0, got (" +
                 std::to_string(half_extents.x()) + ", " + std::to_string(half_extents.y()) + ", " +
                 std::to_string(half_extents.z()) + ")"};
  }
  PolygonMesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.emplace_back((i & 1) ? half_extents.x() : -half_extents.x(),
                               (i & 2) ? half_extents.y() : -half_extents.y(),
                               (i & 4) ? half_extents.z() : -half_extents.z());
  }
  // Vertex i has bit k set when its coordinate k is positive; loops ccw seen from outside.
  mesh.faces = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  return ConvexPolyhedron::FromMesh(mesh);
}

Result<ConvexPolyhedron> MakePrism(int sides, double radius, double half_height) {
  if (sides < 3 || sides > 100000) {
    return Error{"a prism needs 3 to 100000 sides, got " + std::to_string(sides)};
  }
  if (!(std::isfinite(radius) && radius > 0.0 && std::isfinite(half_height) && half_height > 0.0)) {
    return Error{"prism radius and half height must be finite and > 0, got " +
                 std::to_string(radius) + " and " + std::to_string(half_height)};
  }
  // Bottom ring is vertices [0, n), top ring [n, 2n).
  PolygonMesh mesh;
  const auto n = static_cast<std::int32_t>(sides);
  for (const double z : {-half_height, half_height}) {
    for (std::int32_t i = 0; i < n; ++i) {
      const double angle = 2.0 * std::numbers::pi * i / n;
      mesh.vertices.emplace_back(radius * std::cos(angle), radius * std::sin(angle), z);
    }
  }
  std::vector<std::int32_t> bottom, top;
  for (std::int32_t i = 0; i < n; ++i) {
    bottom.push_back(n - 1 - i);
    top.push_back(n + i);
    const std::int32_t j = (i + 1) % n;
    mesh.faces.push_back({i, j, n + j, n + i});
  }
  mesh.faces.push_back(bottom);
  mesh.faces.push_back(top);
  return ConvexPolyhedron::FromMesh(mesh);
}

Result<ConvexPolyhedron> MakeNeedle(double length, double aspect_ratio, int sides) {
  if (!(std::isfinite(length) && length > 0.0 && std::isfinite(aspect_ratio) &&
        aspect_ratio > 0.0)) {
    return Error{"needle length and aspect ratio must be finite and > 0"};
  }
  return MakePrism(sides, 0.5 * length / aspect_ratio, 0.5 * length);
}

Result<ConvexPolyhedron> MakeSlab(double width, double aspect_ratio) {
  if (!(std::isfinite(width) && width > 0.0 && std::isfinite(aspect_ratio) && aspect_ratio > 0.0)) {
    return Error{"slab width and aspect ratio must be finite and > 0"};
  }
  return MakeBox(Eigen::Vector3d(0.5 * width, 0.5 * width, 0.5 * width / aspect_ratio));
}

}  // namespace sparsedyn
