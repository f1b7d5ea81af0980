// SPDX-License-Identifier: MIT
#pragma once

// The example polyhedra shipped in data/ and the generator that writes them. A test
// (example_data_test.cpp) regenerates them into a temporary folder and compares byte for
// byte, so data/ cannot drift from this code; SPARSEDYN_REGENERATE_DATA=1 rewrites data/.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "sparsedyn/geometry/polygon_mesh.hpp"
#include "sparsedyn/io/mesh_io.hpp"

namespace sparsedyn::testing {

/// The faces of the convex hull of `points` (all of which must be hull vertices, in general
/// position apart from coplanar faces), found by brute force over vertex triples: each
/// supporting plane becomes one polygon, counter-clockwise seen from outside and starting at
/// its smallest vertex index. Faces come in the order their first triple is met, so the
/// output is deterministic. Only for the small solids below.
inline PolygonMesh HullOfVertices(std::vector<Eigen::Vector3d> points) {
  constexpr double kPlaneTolerance = 1e-9;  // the solids have unit-scale, exact-ish coordinates
  PolygonMesh mesh;
  const int n = static_cast<int>(points.size());
  std::set<std::vector<int>> seen;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      for (int k = j + 1; k < n; ++k) {
        Eigen::Vector3d normal = (points[j] - points[i]).cross(points[k] - points[i]);
        if (normal.norm() < kPlaneTolerance) continue;
        normal.normalize();
        // Supporting plane: all points on one side; flip so that the normal points outward.
        double most = -1e300, least = 1e300;
        for (const Eigen::Vector3d& p : points) {
          most = std::max(most, normal.dot(p - points[i]));
          least = std::min(least, normal.dot(p - points[i]));
        }
        if (most > kPlaneTolerance && least < -kPlaneTolerance) continue;
        if (most > kPlaneTolerance) normal = -normal;
        std::vector<int> on_plane;
        for (int m = 0; m < n; ++m) {
          if (std::abs(normal.dot(points[m] - points[i])) <= kPlaneTolerance) on_plane.push_back(m);
        }
        if (!seen.insert(on_plane).second) continue;

        // Counter-clockwise about the outward normal, by angle around the centroid.
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for (const int m : on_plane) centroid += points[m];
        centroid /= static_cast<double>(on_plane.size());
        const Eigen::Vector3d u = (points[on_plane[0]] - centroid).normalized();
        const Eigen::Vector3d w = normal.cross(u);
        std::vector<std::pair<double, int>> by_angle;
        for (const int m : on_plane) {
          const Eigen::Vector3d d = points[m] - centroid;
          by_angle.emplace_back(std::atan2(d.dot(w), d.dot(u)), m);
        }
        std::sort(by_angle.begin(), by_angle.end());
        std::vector<std::int32_t> face;
        for (const auto& [angle, m] : by_angle) face.push_back(m);
        std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
        mesh.faces.push_back(std::move(face));
      }
    }
  }
  mesh.vertices = std::move(points);
  return mesh;
}

/// One shipped example: a file stem and its polyhedron.
struct NamedPolyhedron {
  std::string name;
  PolygonMesh mesh;
};

/// Every sign combination of (a, b, c), in the order (+,+,+), (+,+,-), ... ; a zero entry is
/// not doubled.
inline std::vector<Eigen::Vector3d> SignedPoints(double a, double b, double c) {
  std::vector<Eigen::Vector3d> out;
  for (const double sa : {1.0, -1.0}) {
    for (const double sb : {1.0, -1.0}) {
      for (const double sc : {1.0, -1.0}) {
        const Eigen::Vector3d p(sa * a, sb * b, sc * c);
        if (std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
      }
    }
  }
  return out;
}

/// Appends the cyclic permutations (a,b,c), (b,c,a), (c,a,b) of SignedPoints(a, b, c).
inline void AppendCyclic(std::vector<Eigen::Vector3d>& out, double a, double b, double c) {
  for (const std::array<double, 3>& abc :
       {std::array{a, b, c}, std::array{b, c, a}, std::array{c, a, b}}) {
    for (const Eigen::Vector3d& p : SignedPoints(abc[0], abc[1], abc[2])) out.push_back(p);
  }
}

/// The shipped solids with their standard coordinates: cube (+-1)^3; tetrahedron on
/// alternate cube corners; octahedron (+-1,0,0) cyclic; icosahedron (0,+-1,+-phi) cyclic;
/// dodecahedron (+-1)^3 and (0,+-1/phi,+-phi) cyclic (pentagons); a 3:1:1 box (+-1.5,+-.5,+-.5).
inline std::vector<NamedPolyhedron> ExamplePolyhedra() {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  const double inv_phi = phi - 1.0;  // exact in floating point (Sterbenz), equals 1/phi
  std::vector<NamedPolyhedron> out;
  out.push_back({"cube", HullOfVertices(SignedPoints(1, 1, 1))});
  out.push_back(
      {"tetrahedron", HullOfVertices({{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}})});
  std::vector<Eigen::Vector3d> octahedron;
  AppendCyclic(octahedron, 1, 0, 0);
  out.push_back({"octahedron", HullOfVertices(octahedron)});
  std::vector<Eigen::Vector3d> icosahedron;
  AppendCyclic(icosahedron, 0, 1, phi);
  out.push_back({"icosahedron", HullOfVertices(icosahedron)});
  std::vector<Eigen::Vector3d> dodecahedron = SignedPoints(1, 1, 1);
  AppendCyclic(dodecahedron, 0, inv_phi, phi);
  out.push_back({"dodecahedron", HullOfVertices(dodecahedron)});
  out.push_back({"box_3x1x1", HullOfVertices(SignedPoints(1.5, 0.5, 0.5))});
  return out;
}

/// One shipped file: path relative to data/, and how it is written.
struct ExampleFile {
  std::string relative_path;
  MeshFormat format;
  MeshEncoding encoding;
};

/// The files shipped for the solid `name`: every format, STL and PLY in both encodings
/// (binary ones under data/binary/).
inline std::vector<ExampleFile> ExampleFilesFor(const std::string& name) {
  return {
      {name + ".off", MeshFormat::kOff, MeshEncoding::kAscii},
      {name + ".ohio", MeshFormat::kOhio, MeshEncoding::kAscii},
      {name + ".obj", MeshFormat::kObj, MeshEncoding::kAscii},
      {name + ".stl", MeshFormat::kStl, MeshEncoding::kAscii},
      {name + ".ply", MeshFormat::kPly, MeshEncoding::kAscii},
      {"binary/" + name + ".stl", MeshFormat::kStl, MeshEncoding::kBinary},
      {"binary/" + name + ".ply", MeshFormat::kPly, MeshEncoding::kBinary},
  };
}

/// Writes every example file under `dir` (creating dir/binary); the first error, if any.
inline Status WriteExampleData(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir / "binary");
  for (const NamedPolyhedron& solid : ExamplePolyhedra()) {
    for (const ExampleFile& file : ExampleFilesFor(solid.name)) {
      Status written = WriteMesh(solid.mesh, dir / file.relative_path, file.encoding);
      if (!written) return written;
    }
  }
  return Status::Ok();
}

}  // namespace sparsedyn::testing
