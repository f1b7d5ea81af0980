// SPDX-License-Identifier: MIT
// Random convex polyhedra with an exact face count: hulls of random points on a sphere,
// stretched to an ellipsoid.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <unordered_map>

#include "sparsedyn/geometry/generators.hpp"

namespace sparsedyn {

namespace {

constexpr int kMaxFaceCount = 100000;
constexpr int kMaxAttempts = 50;

// Uniform in [0, 1) from the top 53 bits: the same on every platform, unlike
// std::uniform_real_distribution whose algorithm is implementation-defined.
double Uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// Uniform on the unit sphere by rejection in the cube [-1, 1]^3 and normalisation: only +, *, /
// and sqrt, which IEEE 754 rounds exactly, so the points are bit-identical everywhere.
Eigen::Vector3d UniformOnSphere(std::mt19937_64& rng) {
  while (true) {
    // Drawn z, y, x in sequence: as constructor arguments the order was the compiler's (GCC
    // on x86-64 right to left, aarch64 and clang left to right; docs/reliability.md).
    const double z = 2.0 * Uniform(rng) - 1.0;
    const double y = 2.0 * Uniform(rng) - 1.0;
    const double x = 2.0 * Uniform(rng) - 1.0;
    const Eigen::Vector3d p(x, y, z);
    const double r2 = p.squaredNorm();
    // The lower bound avoids amplifying the quantisation of tiny vectors.
    if (r2 <= 1.0 && r2 > 1e-4) return p / std::sqrt(r2);
  }
}

// Hash grid of accepted points, to reject candidates closer than `spacing` to any of them.
class SeparationGrid {
 public:
  explicit SeparationGrid(double spacing) : spacing_(spacing) {}

  bool IsFarFromAll(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& points) const {
    if (spacing_ <= 0.0) return true;
    const Eigen::Vector3i c = Cell(p);
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(Key(c + Eigen::Vector3i(dx, dy, dz)));
          if (it == cells_.end()) continue;
          for (const std::size_t i : it->second) {
            if ((points[i] - p).squaredNorm() < spacing_ * spacing_) return false;
          }
        }
      }
    }
    return true;
  }

  void Add(const Eigen::Vector3d& p, std::size_t index) {
    if (spacing_ > 0.0) cells_[Key(Cell(p))].push_back(index);
  }

 private:
  Eigen::Vector3i Cell(const Eigen::Vector3d& p) const {
    return (p / spacing_).array().floor().cast<int>();
  }
  static std::uint64_t Key(const Eigen::Vector3i& c) {
    // Cells of the unit sphere's bounding cube fit in 21 bits per axis for any spacing used.
    const auto part = [](int x) { return static_cast<std::uint64_t>(x + (1 << 20)) & 0x1FFFFF; };
    return part(c.x()) | (part(c.y()) << 21) | (part(c.z()) << 42);
  }

  double spacing_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

// One attempt: the points whose hull should have face_count faces (see the header).
std::vector<Eigen::Vector3d> DrawPoints(int face_count, double min_separation,
                                        std::mt19937_64& rng) {
  const bool odd = face_count % 2 != 0;
  const int point_count = odd ? (face_count + 5) / 2 : face_count / 2 + 2;
  const double mean_spacing = std::sqrt(4.0 * std::numbers::pi / point_count);
  SeparationGrid grid(min_separation * mean_spacing);
  std::vector<Eigen::Vector3d> points;

  // For an odd count, a square in the plane z = cap_height: its corners are exact in binary
  // (coordinates a, 0 and h), so they are coplanar without round-off. The cap above the plane
  // stays empty, and a band below it too, so that no triangle is nearly coplanar with it.
  double max_z = 2.0;
  if (odd) {
    const double a = std::min(0.8, 0.7 * mean_spacing);
    const double h = std::sqrt(1.0 - a * a);
    for (const Eigen::Vector3d& corner : {Eigen::Vector3d(a, 0, h), Eigen::Vector3d(0, a, h),
                                          Eigen::Vector3d(-a, 0, h), Eigen::Vector3d(0, -a, h)}) {
      grid.Add(corner, points.size());
      points.push_back(corner);
    }
    max_z = h - 0.25 * a;
  }

  // Dart throwing: uniform points, rejecting those too close to an accepted one. The separation
  // covers under 10% of the sphere, so rejections stay rare.
  while (static_cast<int>(points.size()) < point_count) {
    const Eigen::Vector3d p = UniformOnSphere(rng);
    if (p.z() > max_z || !grid.IsFarFromAll(p, points)) continue;
    grid.Add(p, points.size());
    points.push_back(p);
  }
  return points;
}

}  // namespace

Result<ConvexPolyhedron> RandomConvexPolyhedron(int face_count, std::uint64_t seed,
                                                RandomPolyhedronOptions options) {
  if (face_count < 4 || face_count > kMaxFaceCount) {
    return Error{"a random polyhedron needs 4 to " + std::to_string(kMaxFaceCount) +
                 " faces, got " + std::to_string(face_count)};
  }
  if (!(options.radii.allFinite() && options.radii.minCoeff() > 0.0)) {
    return Error{"random polyhedron radii must be finite and > 0"};
  }
  if (!(options.min_separation >= 0.0 && options.min_separation <= 0.6)) {
    return Error{"random polyhedron min_separation must be in [0, 0.6], got " +
                 std::to_string(options.min_separation)};
  }
  std::mt19937_64 rng(seed);
  std::string last_problem;
  for (int attempt = 0; attempt < kMaxAttempts; ++attempt) {
    std::vector<Eigen::Vector3d> points = DrawPoints(face_count, options.min_separation, rng);
    for (Eigen::Vector3d& p : points) p = p.cwiseProduct(options.radii);
    Result<ConvexPolyhedron> hull = ConvexPolyhedron::FromPoints(points);
    if (hull && hull->face_count() == face_count) return hull;
    last_problem =
        hull ? "got " + std::to_string(hull->face_count()) + " faces" : hull.error().message;
  }
  return Error{"no random polyhedron with " + std::to_string(face_count) + " faces after " +
               std::to_string(kMaxAttempts) + " attempts (seed " + std::to_string(seed) +
               "; last: " + last_problem + ")"};
}

Result<ConvexPolyhedron> RandomEllipsoidalPolyhedron(int face_count, const Eigen::Vector3d& radii,
                                                     std::uint64_t seed) {
  RandomPolyhedronOptions options;
  options.radii = radii;
  return RandomConvexPolyhedron(face_count, seed, options);
}

}  // namespace sparsedyn
