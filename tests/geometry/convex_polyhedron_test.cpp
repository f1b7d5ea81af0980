// SPDX-License-Identifier: MIT
#include "sparsedyn/geometry/convex_polyhedron.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "geometry/polyhedron_checks.hpp"
#include "sparsedyn/geometry/generators.hpp"
#include "support/fp_traps.hpp"

namespace sparsedyn {
namespace {

using ::sparsedyn::testing::Describe;
using ::sparsedyn::testing::IsConsistent;
using ::sparsedyn::testing::VoronoiPlanesAreReciprocal;
using ::sparsedyn::testing::VoronoiRegionsAgreeWithBruteForce;

// Analytic mass properties hold to round-off: a few ulps of sums of O(10) terms.
constexpr double kExact = 1e-12;

// The cube [-1, 1]^3 with vertex i at (+-1, +-1, +-1) by the bits of i, faces ccw from outside.
PolygonMesh HandCube() {
  PolygonMesh mesh;
  for (int i = 0; i < 8; ++i)
    mesh.vertices.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  mesh.faces = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  return mesh;
}

PolygonMesh Tetrahedron(int offset = 0) {
  PolygonMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (auto& face : mesh.faces) {
    for (auto& v : face) v += offset;
  }
  return mesh;
}

// Expects FromMesh to fail with a message containing every fragment.
void ExpectRefused(const PolygonMesh& mesh, std::initializer_list<std::string> fragments,
                   MeshValidation options = {}) {
  SCOPED_TRACE(Describe(mesh));
  const Result<ConvexPolyhedron> result = ConvexPolyhedron::FromMesh(mesh, options);
  ASSERT_FALSE(result.ok()) << "accepted";
  for (const std::string& fragment : fragments) {
    EXPECT_NE(result.error().message.find(fragment), std::string::npos)
        << "message: " << result.error().message << "\nmissing: " << fragment;
  }
}

TEST(ConvexPolyhedron, HandWrittenCubeIsAcceptedAsGiven) {
  const Result<ConvexPolyhedron> cube = ConvexPolyhedron::FromMesh(HandCube());
  ASSERT_TRUE(cube.ok()) << cube.error().message;
  EXPECT_TRUE(cube->warnings().empty());
  EXPECT_EQ(cube->vertex_count(), 8);
  EXPECT_EQ(cube->edge_count(), 12);
  EXPECT_EQ(cube->face_count(), 6);
  EXPECT_TRUE(IsConsistent(*cube));
  EXPECT_TRUE(VoronoiPlanesAreReciprocal(*cube));
  // Face 0 is the -x face with its loop as given.
  EXPECT_TRUE(cube->face(0).plane.normal.isApprox(-Eigen::Vector3d::UnitX()));
  EXPECT_NEAR(cube->face(0).plane.offset, 1.0, kExact);
  const auto loop = cube->FaceVertices(0);
  EXPECT_EQ(std::vector<std::int32_t>(loop.begin(), loop.end()),
            (std::vector<std::int32_t>{0, 4, 6, 2}));
}

TEST(ConvexPolyhedron, VoronoiPlaneLayoutFollowsTheDocumentedOrder) {
  const ConvexPolyhedron cube = *ConvexPolyhedron::FromMesh(HandCube());
  // Vertex: one plane per incident edge, through the vertex, normal away from the edge.
  for (int v = 0; v < cube.vertex_count(); ++v) {
    const auto planes = cube.VoronoiPlanes(FeatureId::Vertex(v));
    ASSERT_EQ(planes.size(), cube.VertexEdges(v).size());
    for (std::size_t i = 0; i < planes.size(); ++i) {
      const int e = cube.VertexEdges(v)[i];
      EXPECT_EQ(planes[i].neighbor, FeatureId::Edge(e));
      const Eigen::Vector3d away = cube.vertex(v) - cube.vertex(cube.OtherVertex(e, v));
      EXPECT_TRUE(planes[i].plane.normal.isApprox(away.normalized()));
      EXPECT_NEAR(planes[i].plane.SignedDistance(cube.vertex(v)), 0.0, kExact);
    }
  }
  // Edge: tail, head, faces[0], faces[1].
  for (int e = 0; e < cube.edge_count(); ++e) {
    const Edge& edge = cube.edge(e);
    const auto planes = cube.VoronoiPlanes(FeatureId::Edge(e));
    ASSERT_EQ(planes.size(), 4u);
    EXPECT_EQ(planes[0].neighbor, FeatureId::Vertex(edge.vertices[0]));
    EXPECT_EQ(planes[1].neighbor, FeatureId::Vertex(edge.vertices[1]));
    EXPECT_EQ(planes[2].neighbor, FeatureId::Face(edge.faces[0]));
    EXPECT_EQ(planes[3].neighbor, FeatureId::Face(edge.faces[1]));
    const Eigen::Vector3d mid =
        0.5 * (cube.vertex(edge.vertices[0]) + cube.vertex(edge.vertices[1]));
    const Eigen::Vector3d out =
        (cube.face(edge.faces[0]).plane.normal + cube.face(edge.faces[1]).plane.normal);
    for (const VoronoiPlane& vp : planes) EXPECT_GT(vp.plane.SignedDistance(mid + out), 0.0);
  }
  // Face: the face plane first (neighbour: interior), then one plane per boundary edge.
  for (int f = 0; f < cube.face_count(); ++f) {
    const auto planes = cube.VoronoiPlanes(FeatureId::Face(f));
    ASSERT_EQ(planes.size(), 1 + cube.FaceEdges(f).size());
    EXPECT_EQ(planes[0].neighbor, FeatureId::Interior());
    EXPECT_TRUE(planes[0].plane.normal.isApprox(cube.face(f).plane.normal));
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    for (const int v : cube.FaceVertices(f)) center += cube.vertex(v) / 4.0;
    for (std::size_t i = 0; i < cube.FaceEdges(f).size(); ++i) {
      EXPECT_EQ(planes[i + 1].neighbor, FeatureId::Edge(cube.FaceEdges(f)[i]));
      EXPECT_NEAR(planes[i + 1].plane.SignedDistance(center), 1.0, kExact);
    }
  }
}

TEST(ConvexPolyhedron, ToStringNamesFeatures) {
  EXPECT_EQ(ToString(FeatureId::Vertex(3)), "vertex 3");
  EXPECT_EQ(ToString(FeatureId::Edge(7)), "edge 7");
  EXPECT_EQ(ToString(FeatureId::Face(2)), "face 2");
  EXPECT_EQ(ToString(FeatureId::Interior()), "interior");
}

// ---- Validation: one fixture per error class, each with its named error. ----

TEST(MeshValidation, RefusesNanCoordinate) {
  PolygonMesh mesh = HandCube();
  mesh.vertices[3].y() = std::nan("");
  ExpectRefused(mesh, {"vertex 3", "non-finite"});
}

TEST(MeshValidation, RefusesIndexOutOfRange) {
  PolygonMesh mesh = HandCube();
  mesh.faces[2][1] = 8;
  ExpectRefused(mesh, {"face 2 refers to vertex 8", "8 vertices"});
  mesh.faces[2][1] = -1;
  ExpectRefused(mesh, {"face 2 refers to vertex -1"});
}

TEST(MeshValidation, RefusesFaceWithFewerThanThreeVertices) {
  PolygonMesh mesh = HandCube();
  mesh.faces[4] = {0, 2};
  ExpectRefused(mesh, {"face 4 has 2 vertices"});
}

TEST(MeshValidation, RefusesRepeatedVertexInFace) {
  PolygonMesh mesh = HandCube();
  mesh.faces[1] = {1, 3, 7, 3};
  ExpectRefused(mesh, {"face 1 uses vertex 3 more than once"});
}

TEST(MeshValidation, RefusesNonManifoldEdge) {
  PolygonMesh mesh = Tetrahedron();
  mesh.vertices.emplace_back(1, -1, -1);
  mesh.faces.push_back({0, 1, 4});  // a fin on edge (0,1)
  ExpectRefused(mesh, {"edge (0,1) is used by 3 faces", "face 0", "face 1", "face 4"});
}

TEST(MeshValidation, RefusesOpenBoundary) {
  PolygonMesh mesh = HandCube();
  mesh.faces.pop_back();  // no top
  ExpectRefused(mesh, {"edge (4,5) is used only by face 2", "open"});
}

TEST(MeshValidation, RefusesInconsistentWinding) {
  PolygonMesh mesh = HandCube();
  std::reverse(mesh.faces[3].begin(), mesh.faces[3].end());
  ExpectRefused(mesh, {"inconsistent winding", "face 3"});
}

TEST(MeshValidation, RefusesNonManifoldVertex) {
  // Two tetrahedra touching at one vertex: every edge is fine, vertex 0 is a pinch.
  PolygonMesh mesh = Tetrahedron();
  PolygonMesh other = Tetrahedron();
  for (Eigen::Vector3d& p : other.vertices) p = -p;
  mesh.vertices.insert(mesh.vertices.end(), other.vertices.begin() + 1, other.vertices.end());
  for (auto face : other.faces) {
    for (auto& v : face) v = v == 0 ? 0 : v + 3;
    mesh.faces.push_back(face);
  }
  ExpectRefused(mesh, {"vertex 0 is not manifold"});
}

TEST(MeshValidation, RefusesWrongEulerCharacteristic) {
  PolygonMesh mesh = Tetrahedron();
  const PolygonMesh other = Tetrahedron(4);
  for (Eigen::Vector3d p : Tetrahedron().vertices)
    mesh.vertices.push_back(p + Eigen::Vector3d(3, 0, 0));
  mesh.faces.insert(mesh.faces.end(), other.faces.begin(), other.faces.end());
  ExpectRefused(mesh, {"Euler characteristic V - E + F = 8 - 12 + 8 = 4, expected 2"});
}

TEST(MeshValidation, RefusesNonConvexDent) {
  // The cube's top face replaced by a pyramid pushed 0.5 into the cube.
  PolygonMesh mesh = HandCube();
  mesh.vertices.emplace_back(0, 0, 0.5);
  mesh.faces.pop_back();
  mesh.faces.push_back({4, 5, 8});
  mesh.faces.push_back({5, 7, 8});
  mesh.faces.push_back({7, 6, 8});
  mesh.faces.push_back({6, 4, 8});
  ExpectRefused(mesh, {"not convex", "lies 0.", "above the plane of face", "tolerance 1e-09"});
}

TEST(MeshValidation, RefusesNonPlanarFace) {
  PolygonMesh mesh = HandCube();
  mesh.vertices[7].z() += 1e-3;
  ExpectRefused(mesh, {"face 5 is not planar", "off its best-fit plane"});
}

TEST(MeshValidation, RefusesDegenerateFace) {
  // A triangular prism whose cap triangles are squashed onto a line.
  PolygonMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 1}, {1, 0, 1}, {2, 0, 1}};
  mesh.faces = {{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}};
  ExpectRefused(mesh, {"face 0 is degenerate"});
}

TEST(MeshValidation, RefusesFlatMesh) {
  // A "tetrahedron" with all four points in a plane but non-degenerate faces.
  PolygonMesh mesh = Tetrahedron();
  mesh.vertices[3] = Eigen::Vector3d(1, 1, 0);
  ExpectRefused(mesh, {"encloses no volume"});
}

TEST(MeshValidation, RefusesInwardWindingWhenFlippingIsDisabled) {
  PolygonMesh mesh = HandCube();
  for (auto& face : mesh.faces) std::reverse(face.begin(), face.end());
  MeshValidation options;
  options.flip_inward_winding = false;
  ExpectRefused(mesh, {"clockwise", "flipping is disabled"}, options);
}

TEST(MeshValidation, RefusesCoplanarFacesWhenMergingIsDisabled) {
  PolygonMesh mesh = HandCube();
  mesh.faces[5] = {4, 5, 7};
  mesh.faces.push_back({4, 7, 6});
  MeshValidation options;
  options.merge_coplanar_faces = false;
  ExpectRefused(mesh, {"face 5 and face 6 are coplanar"}, options);
}

TEST(MeshValidation, FlipsUniformlyInwardMeshWithWarning) {
  PolygonMesh mesh = HandCube();
  for (auto& face : mesh.faces) std::reverse(face.begin(), face.end());
  const Result<ConvexPolyhedron> cube = ConvexPolyhedron::FromMesh(mesh);
  ASSERT_TRUE(cube.ok()) << cube.error().message;
  ASSERT_EQ(cube->warnings().size(), 1u);
  EXPECT_NE(cube->warnings()[0].find("flipped"), std::string::npos) << cube->warnings()[0];
  EXPECT_TRUE(IsConsistent(*cube));
  EXPECT_NEAR(cube->volume(), 8.0, kExact);
}

TEST(MeshValidation, MergesTwelveTrianglesOfACubeIntoSixSquares) {
  PolygonMesh triangles = HandCube();
  triangles.faces.clear();
  for (const auto& quad : HandCube().faces) {
    triangles.faces.push_back({quad[0], quad[1], quad[2]});
    triangles.faces.push_back({quad[0], quad[2], quad[3]});
  }
  const Result<ConvexPolyhedron> cube = ConvexPolyhedron::FromMesh(triangles);
  ASSERT_TRUE(cube.ok()) << cube.error().message;
  EXPECT_EQ(cube->face_count(), 6);
  EXPECT_EQ(cube->edge_count(), 12);
  EXPECT_EQ(cube->vertex_count(), 8);
  EXPECT_TRUE(IsConsistent(*cube));
  ASSERT_EQ(cube->warnings().size(), 1u);
  EXPECT_NE(cube->warnings()[0].find("merged 12 input faces into 6"), std::string::npos);
}

TEST(MeshValidation, DropsVerticesInsideMergedFacesAndOnStraightEdges) {
  // The cube's top face as a fan around its centre, and its front face split into two
  // rectangles, which leaves vertices 9 and 10 in the middle of straight edges.
  PolygonMesh mesh = HandCube();
  mesh.vertices.emplace_back(0, 0, 1);    // 8: centre of the top
  mesh.vertices.emplace_back(0, -1, -1);  // 9: middle of bottom front edge
  mesh.vertices.emplace_back(0, -1, 1);   // 10: middle of top front edge
  mesh.faces = {{0, 4, 6, 2}, {1, 3, 7, 5},    {0, 9, 10, 4}, {9, 1, 5, 10},
                {2, 6, 7, 3}, {0, 2, 3, 1, 9}, {4, 10, 8},    {10, 5, 8},
                {5, 7, 8},    {7, 6, 8},       {6, 4, 8}};
  const Result<ConvexPolyhedron> cube = ConvexPolyhedron::FromMesh(mesh);
  ASSERT_TRUE(cube.ok()) << cube.error().message;
  EXPECT_EQ(cube->vertex_count(), 8);
  EXPECT_EQ(cube->face_count(), 6);
  EXPECT_TRUE(IsConsistent(*cube));
  EXPECT_NEAR(cube->volume(), 8.0, kExact);
}

TEST(MeshValidation, RespectsTheRelativeTolerance) {
  // The top face as a fan around a centre sunk by 1e-7 relative to the scale: a dent refused at
  // the default tolerance 1e-9, merged into one flat face at 1e-6.
  PolygonMesh mesh = HandCube();
  mesh.vertices.emplace_back(0, 0, 1 - 1e-7 * 2 * std::sqrt(3.0));
  mesh.faces.pop_back();
  for (const auto& [a, b] : {std::pair{4, 5}, {5, 7}, {7, 6}, {6, 4}})
    mesh.faces.push_back({a, b, 8});
  ExpectRefused(mesh, {"not convex", "above the plane of face"});
  MeshValidation loose;
  loose.tolerance = 1e-6;
  const Result<ConvexPolyhedron> cube = ConvexPolyhedron::FromMesh(mesh, loose);
  ASSERT_TRUE(cube.ok()) << cube.error().message;
  EXPECT_EQ(cube->face_count(), 6);
  EXPECT_EQ(cube->vertex_count(), 8);
}

// ---- Qhull ----

TEST(FromPoints, RefusesTooFewCoplanarAndNonFinitePoints) {
  // Floating-point traps paused (docs/reliability.md): Eigen's
  // allFinite() computes x - x, which is invalid for an infinite x.
  const sparsedyn::testing::FloatingPointTrapsPaused traps_paused;
  std::vector<Eigen::Vector3d> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_FALSE(ConvexPolyhedron::FromPoints(points).ok());
  points.emplace_back(1, 1, 0);
  const Result<ConvexPolyhedron> flat = ConvexPolyhedron::FromPoints(points);
  ASSERT_FALSE(flat.ok());
  // Refused before Qhull sees it (shape_checks.hpp), no longer by Qhull.
  EXPECT_NE(flat.error().message.find("coplanar"), std::string::npos) << flat.error().message;
  points.emplace_back(0, 0, std::numeric_limits<double>::infinity());
  const Result<ConvexPolyhedron> bad = ConvexPolyhedron::FromPoints(points);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("point 4"), std::string::npos) << bad.error().message;
}

TEST(FromPoints, IgnoresInteriorPointsAndPointsOnFacesAndEdges) {
  std::vector<Eigen::Vector3d> points = {{0.1, 0.2, 0.3}, {1, 0, 0}, {1, 1, 0}};
  for (const Eigen::Vector3d& p : SolidVertices(PlatonicSolid::kCube)) points.push_back(p);
  const Result<ConvexPolyhedron> cube = ConvexPolyhedron::FromPoints(points);
  ASSERT_TRUE(cube.ok()) << cube.error().message;
  EXPECT_EQ(cube->vertex_count(), 8);
  EXPECT_EQ(cube->face_count(), 6);
  EXPECT_TRUE(cube->warnings().empty());
  // Hull vertices keep the input order.
  for (int v = 0; v < 8; ++v) EXPECT_EQ(cube->vertex(v), points[static_cast<std::size_t>(v + 3)]);
}

TEST(FromPoints, LatticeWithManyCoplanarPointsGivesTheCube) {
  // 5^3 lattice points, most of them on faces and edges, some jittered by round-off sized
  // amounts: Qhull's merging plus ours must still give the 8-corner cube.
  std::vector<Eigen::Vector3d> points;
  std::mt19937_64 rng(3);
  for (int i = 0; i < 125; ++i) {
    Eigen::Vector3d p(i % 5 - 2, (i / 5) % 5 - 2, i / 25 - 2);
    if (i % 3 == 0) p += 1e-14 * testing::RandomUnitVector(rng);
    points.push_back(p);
  }
  const Result<ConvexPolyhedron> cube = ConvexPolyhedron::FromPoints(points);
  ASSERT_TRUE(cube.ok()) << cube.error().message;
  EXPECT_EQ(cube->face_count(), 6);
  EXPECT_TRUE(IsConsistent(*cube));
  EXPECT_NEAR(cube->volume(), 64.0, 1e-11);
}

TEST(FromPoints, AgreesWithFaceListConstructionOnPlatonicSolids) {
  for (int s = 0; s < kPlatonicSolidCount; ++s) {
    const auto solid = static_cast<PlatonicSolid>(s);
    SCOPED_TRACE(std::string(ToString(solid)));
    const std::vector<Eigen::Vector3d> points = SolidVertices(solid);
    const Result<ConvexPolyhedron> hull = ConvexPolyhedron::FromPoints(points);
    const PolygonMesh reference_mesh = testing::ReferenceHull(points);
    const Result<ConvexPolyhedron> from_faces = ConvexPolyhedron::FromMesh(reference_mesh);
    ASSERT_TRUE(hull.ok()) << hull.error().message;
    ASSERT_TRUE(from_faces.ok()) << from_faces.error().message;
    EXPECT_EQ(hull->face_count(), FaceCount(solid));
    EXPECT_EQ(from_faces->face_count(), FaceCount(solid));
    EXPECT_EQ(hull->vertex_count(), from_faces->vertex_count());
    EXPECT_EQ(hull->edge_count(), from_faces->edge_count());
    EXPECT_NEAR(hull->volume(), from_faces->volume(), kExact * hull->volume());
    // The same faces: as sets of vertex indices (both keep the input's vertex order).
    const auto face_sets = [](const ConvexPolyhedron& p) {
      std::set<std::set<std::int32_t>> sets;
      for (int f = 0; f < p.face_count(); ++f) {
        sets.emplace(p.FaceVertices(f).begin(), p.FaceVertices(f).end());
      }
      return sets;
    };
    EXPECT_EQ(face_sets(*hull), face_sets(*from_faces));
  }
}

// ---- Mass properties ----

TEST(MassProperties, BoxMatchesAnalyticValues) {
  const Eigen::Vector3d h(0.5, 1.5, 2.0);
  const ConvexPolyhedron box = MakeBox(h)->Scaled(1.0);
  const double mass = 8 * h.prod();
  EXPECT_NEAR(box.volume(), mass, kExact * mass);
  EXPECT_LT(box.centroid().norm(), kExact);
  const Eigen::Vector3d expected(mass * (h.y() * h.y() + h.z() * h.z()) / 3,
                                 mass * (h.x() * h.x() + h.z() * h.z()) / 3,
                                 mass * (h.x() * h.x() + h.y() * h.y()) / 3);
  EXPECT_LT((box.inertia() - Eigen::Matrix3d(expected.asDiagonal())).norm(), kExact * mass * 10);
  EXPECT_NEAR(box.bounding_radius(), h.norm(), kExact);
}

TEST(MassProperties, OffsetBoxHasShiftedCentroidAndSameInertia) {
  PolygonMesh mesh = MakeBox(Eigen::Vector3d(1, 2, 3))->ToMesh();
  const Eigen::Vector3d shift(100, -50, 7);
  for (Eigen::Vector3d& p : mesh.vertices) p += shift;
  const ConvexPolyhedron box = *ConvexPolyhedron::FromMesh(mesh);
  EXPECT_LT((box.centroid() - shift).norm(), 1e-12 * shift.norm());
  EXPECT_LT((box.inertia() - MakeBox(Eigen::Vector3d(1, 2, 3))->inertia()).norm(), 1e-10);
  const ConvexPolyhedron centred = box.Recentered();
  EXPECT_LT(centred.centroid().norm(), 1e-12);
  EXPECT_EQ(centred.face_count(), box.face_count());
  EXPECT_LT((centred.inertia() - box.inertia()).norm(), 1e-10);
}

TEST(MassProperties, RegularTetrahedronAndOctahedronMatchAnalyticValues) {
  // Tetrahedron on alternate cube corners: edge a = 2 sqrt 2, V = a^3 / (6 sqrt 2) = 8/3,
  // isotropic I = m a^2 / 20.
  const ConvexPolyhedron tetra = MakeSolid(PlatonicSolid::kTetrahedron);
  EXPECT_NEAR(tetra.volume(), 8.0 / 3.0, kExact);
  EXPECT_LT(tetra.centroid().norm(), kExact);
  EXPECT_LT((tetra.inertia() - (8.0 / 3.0) * 8.0 / 20.0 * Eigen::Matrix3d::Identity()).norm(),
            kExact);
  // Octahedron |x| + |y| + |z| <= 1: V = 4/3, integral of x^2 = 8/60, I = 4/15 * identity.
  const ConvexPolyhedron octa = MakeSolid(PlatonicSolid::kOctahedron);
  EXPECT_NEAR(octa.volume(), 4.0 / 3.0, kExact);
  EXPECT_LT((octa.inertia() - 4.0 / 15.0 * Eigen::Matrix3d::Identity()).norm(), kExact);
  EXPECT_NEAR(octa.bounding_radius(), 1.0, kExact);
}

TEST(MassProperties, ScalingScalesVolumeAndInertia) {
  const ConvexPolyhedron p = *RandomConvexPolyhedron(30, /*seed=*/7);
  const ConvexPolyhedron q = p.Scaled(2.5);
  EXPECT_NEAR(q.volume(), std::pow(2.5, 3) * p.volume(), 1e-12 * q.volume());
  EXPECT_LT((q.inertia() - std::pow(2.5, 5) * p.inertia()).norm(), 1e-12 * q.inertia().norm());
  EXPECT_NEAR(q.bounding_radius(), 2.5 * p.bounding_radius(), 1e-12);
}

TEST(MassProperties, SphereHullApproachesTheBall) {
  // A hull inscribed in the unit sphere with n = 1002 vertices. Each face of area A cuts off a
  // cap of volume ~A^2 / (4 pi), so the relative deficit is ~ (4 pi / F) * 3 / (4 pi) ~ 2 / n
  // times a shape factor of a few: ~1% here; 2% bounds it. The slow tests repeat this with
  // 6000 faces and 5e-3.
  const ConvexPolyhedron ball = *RandomConvexPolyhedron(2000, /*seed=*/11);
  const double volume = 4.0 / 3.0 * std::numbers::pi;
  EXPECT_NEAR(ball.volume(), volume, 2e-2 * volume);
  EXPECT_LT(ball.centroid().norm(), 1e-2);
  const Eigen::Matrix3d expected = 0.4 * ball.volume() * Eigen::Matrix3d::Identity();
  EXPECT_LT((ball.inertia() - expected).norm(), 2e-2 * expected.norm());
  EXPECT_LE(ball.bounding_radius(), 1.0 + 1e-2);
}

TEST(MassProperties, AgreesWithMonteCarloOnARandomHull) {
  const std::uint64_t seed = 20260611;
  RandomPolyhedronOptions options;
  options.radii = Eigen::Vector3d(1.0, 0.6, 1.7);
  const ConvexPolyhedron p = *RandomConvexPolyhedron(40, seed, options);
  SCOPED_TRACE("seed " + std::to_string(seed) + ": " + Describe(p));
  std::mt19937_64 rng(seed);
  const int samples = 100000;
  const Eigen::Vector3d lo = options.radii * -1.0, box = 2.0 * options.radii;
  int inside = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (int i = 0; i < samples; ++i) {
    const Eigen::Vector3d q = lo + Eigen::Vector3d(testing::Uniform01(rng), testing::Uniform01(rng),
                                                   testing::Uniform01(rng))
                                       .cwiseProduct(box);
    bool in = true;
    for (int f = 0; f < p.face_count() && in; ++f) in = p.face(f).plane.SignedDistance(q) <= 0;
    if (!in) continue;
    ++inside;
    first += q;
    second += q * q.transpose();
  }
  const double cell = box.prod() / samples;
  const double volume = inside * cell;
  const Eigen::Vector3d centroid = first / inside;
  const Eigen::Matrix3d about = second * cell - volume * centroid * centroid.transpose();
  const Eigen::Matrix3d inertia = about.trace() * Eigen::Matrix3d::Identity() - about;
  // 100000 samples with a hit rate ~0.4: ~0.4% standard error; 2% is ~5 sigma.
  EXPECT_NEAR(p.volume(), volume, 0.02 * volume);
  EXPECT_LT((p.centroid() - centroid).norm(), 0.02);
  EXPECT_LT((p.inertia() - inertia).norm(), 0.02 * inertia.norm());
}

// ---- Voronoi regions against brute force ----

TEST(VoronoiRegions, AgreeWithBruteForceOnSolidsAndRandomHulls) {
  const std::uint64_t seed = 20260611;
  std::vector<ConvexPolyhedron> shapes;
  for (int s = 0; s < kPlatonicSolidCount; ++s)
    shapes.push_back(MakeSolid(static_cast<PlatonicSolid>(s)));
  shapes.push_back(*MakeNeedle(1.0));
  shapes.push_back(*MakeSlab(1.0));
  for (int f : {4, 5, 9, 24, 61}) shapes.push_back(*RandomConvexPolyhedron(f, seed + f));
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    SCOPED_TRACE("shape " + std::to_string(i) + ", seed " + std::to_string(seed + i) + ": " +
                 Describe(shapes[i]));
    EXPECT_TRUE(VoronoiPlanesAreReciprocal(shapes[i]));
    EXPECT_TRUE(VoronoiRegionsAgreeWithBruteForce(shapes[i], seed + i, 200));
  }
}

}  // namespace
}  // namespace sparsedyn
