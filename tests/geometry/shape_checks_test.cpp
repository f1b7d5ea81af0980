// SPDX-License-Identifier: MIT
// The up-front refusals of src/geometry/shape_checks.hpp through FromPoints and FromMesh (issue
// #39 part 1: degenerate point sets crashed Qhull), each with the message naming what is wrong,
// and shapes just inside the limits still accepted.
#include "geometry/shape_checks.hpp"

#include <gtest/gtest.h>

#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

#include "geometry/polyhedron_checks.hpp"
#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/geometry/generators.hpp"

namespace sparsedyn {
namespace {

std::vector<Eigen::Vector3d> Tetrahedron(double size = 1.0,
                                         const Eigen::Vector3d& at = Eigen::Vector3d::Zero()) {
  return {at, at + size * Eigen::Vector3d::UnitX(), at + size * Eigen::Vector3d::UnitY(),
          at + size * Eigen::Vector3d::UnitZ()};
}

// Expects FromPoints to refuse the points with a message containing every fragment.
void ExpectRefused(const std::vector<Eigen::Vector3d>& points,
                   std::initializer_list<std::string> fragments) {
  const Result<ConvexPolyhedron> hull = ConvexPolyhedron::FromPoints(points);
  ASSERT_FALSE(hull.ok()) << "accepted";
  for (const std::string& fragment : fragments) {
    EXPECT_NE(hull.error().message.find(fragment), std::string::npos)
        << "message: " << hull.error().message << "\nmissing: " << fragment;
  }
}

TEST(ShapeChecks, RefusesFewerThanFourPoints) {
  std::vector<Eigen::Vector3d> points = Tetrahedron();
  points.pop_back();
  ExpectRefused(points, {"at least 4 points", "got 3"});
  ExpectRefused({}, {"at least 4 points", "got 0"});
}

TEST(ShapeChecks, RefusesNanAndInfiniteCoordinates) {
  std::vector<Eigen::Vector3d> points = Tetrahedron();
  points[2].y() = std::numeric_limits<double>::quiet_NaN();
  ExpectRefused(points, {"point 2", "non-finite coordinate"});
  points = Tetrahedron();
  points[3].z() = -std::numeric_limits<double>::infinity();
  ExpectRefused(points, {"point 3", "non-finite coordinate", "-inf"});
}

TEST(ShapeChecks, RefusesCoordinatesBeyondKMaxCoordinate) {
  std::vector<Eigen::Vector3d> points = Tetrahedron();
  points[1].x() = 1e60;
  ExpectRefused(points, {"point 1", "magnitude 1e+60", "kMaxCoordinate = 1e+50"});
}

TEST(ShapeChecks, RefusesCoincidentPoints) {
  const std::vector<Eigen::Vector3d> points(5, Eigen::Vector3d(1, 2, 3));
  ExpectRefused(points, {"all 5 points coincide", "(1, 2, 3)"});
}

TEST(ShapeChecks, RefusesAScaleBelowKMinScale) {
  ExpectRefused(Tetrahedron(1e-52), {"span only 1.73e-52", "kMinScale = 1e-50"});
}

TEST(ShapeChecks, RefusesPointsDistinctOnlyAtRoundOff) {
  // 1e-7 apart at 1e6: about 860 ulps of the coordinates, distinct but with no usable plane.
  ExpectRefused(Tetrahedron(1e-7, Eigen::Vector3d::Constant(1e6)),
                {"distinct only at round-off", "kMinRelativeScale = 1e-12"});
}

TEST(ShapeChecks, RefusesCollinearPoints) {
  const std::vector<Eigen::Vector3d> points = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {-3, -3, -3}};
  ExpectRefused(points, {"collinear", "no volume", "points 0 and 3"});
}

TEST(ShapeChecks, RefusesCoplanarPoints) {
  std::vector<Eigen::Vector3d> points = {{0, 0, 5}, {1, 0, 5}, {0, 1, 5}, {1, 1, 5}, {0.5, 2, 5}};
  ExpectRefused(points, {"coplanar", "no volume"});
  // Flat within the tolerance (1e-9 x scale) counts as flat: 1e-12 off the plane.
  points.emplace_back(0.3, 0.3, 5 + 1e-12);
  ExpectRefused(points, {"coplanar", "tolerance"});
}

// The corners of the box [0, size]^3 + at: its face planes are exact far from the origin too.
std::vector<Eigen::Vector3d> Box(double size, const Eigen::Vector3d& at) {
  std::vector<Eigen::Vector3d> corners;
  for (int i = 0; i < 8; ++i) {
    corners.push_back(at + size * Eigen::Vector3d(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  }
  return corners;
}

TEST(ShapeChecks, AcceptsShapesJustInsideTheLimits) {
  for (const auto& points : {Tetrahedron(1e-45), Tetrahedron(1e49), Box(1e-5, {1e6, 0, 0}),
                             Box(1.0, {1e11, -1e11, 1e11})}) {
    SCOPED_TRACE(testing::Describe(PolygonMesh{points, {}}));
    const Result<ConvexPolyhedron> hull = ConvexPolyhedron::FromPoints(points);
    ASSERT_TRUE(hull.ok()) << hull.error().message;
    EXPECT_EQ(hull->vertex_count(), static_cast<int>(points.size()));
    EXPECT_GT(hull->volume(), 0.0);
    EXPECT_TRUE(CheckFinishedPolyhedron(*hull).ok());
  }
}

TEST(ShapeChecks, FinishedSolidsPassTheLastCheck) {
  for (int s = 0; s < kPlatonicSolidCount; ++s) {
    const Result<ConvexPolyhedron> solid =
        ConvexPolyhedron::FromPoints(SolidVertices(static_cast<PlatonicSolid>(s)));
    ASSERT_TRUE(solid.ok()) << solid.error().message;
    const Status finished = CheckFinishedPolyhedron(*solid);
    EXPECT_TRUE(finished.ok()) << finished.error().message;
  }
}

// FromMesh refuses the same coordinates and vertex sets, naming the mesh's vertices.
PolygonMesh TetrahedronMesh(double size) {
  PolygonMesh mesh;
  mesh.vertices = Tetrahedron(size);
  mesh.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return mesh;
}

std::string MeshError(const PolygonMesh& mesh) {
  const Result<ConvexPolyhedron> built = ConvexPolyhedron::FromMesh(mesh);
  return built ? "<accepted>" : built.error().message;
}

TEST(ShapeChecks, FromMeshRefusesTheSameDegenerateVertices) {
  PolygonMesh mesh = TetrahedronMesh(1.0);
  mesh.vertices[0].z() = -2e50;
  EXPECT_NE(MeshError(mesh).find("vertex 0 has a coordinate of magnitude 2e+50"), std::string::npos)
      << MeshError(mesh);
  EXPECT_NE(MeshError(TetrahedronMesh(1e-60)).find("the vertices span only"), std::string::npos)
      << MeshError(TetrahedronMesh(1e-60));
  mesh = TetrahedronMesh(1.0);
  for (Eigen::Vector3d& v : mesh.vertices) v = Eigen::Vector3d(4, 5, 6);
  EXPECT_NE(MeshError(mesh).find("all 4 vertices coincide at (4, 5, 6)"), std::string::npos)
      << MeshError(mesh);
  mesh = TetrahedronMesh(1e-9);
  for (Eigen::Vector3d& v : mesh.vertices) v += Eigen::Vector3d(1e5, 0, 0);
  EXPECT_NE(MeshError(mesh).find("the vertices are distinct only at round-off"), std::string::npos)
      << MeshError(mesh);
}

}  // namespace
}  // namespace sparsedyn
