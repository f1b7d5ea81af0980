// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "sparsedyn/geometry/polygon_mesh.hpp"
#include "sparsedyn/result.hpp"

namespace sparsedyn {

/// The kind of a polyhedron feature. kNone marks "no feature": the polyhedron's interior, which
/// lies behind a face plane (see VoronoiPlane::neighbor).
enum class FeatureType : std::uint8_t { kVertex, kEdge, kFace, kNone };

/// A vertex, edge or face of one ConvexPolyhedron, by type and index into that polyhedron's
/// vertex, edge or face arrays. Passed by value.
struct FeatureId {
  /// Vertex, edge, face, or kNone for the interior.
  FeatureType type = FeatureType::kNone;
  /// Index into the polyhedron's vertices, edges or faces (-1 for the interior).
  std::int32_t index = -1;

  /// Vertex v.
  static constexpr FeatureId Vertex(std::int32_t v) { return {FeatureType::kVertex, v}; }
  /// Edge e.
  static constexpr FeatureId Edge(std::int32_t e) { return {FeatureType::kEdge, e}; }
  /// Face f.
  static constexpr FeatureId Face(std::int32_t f) { return {FeatureType::kFace, f}; }
  /// The interior of the polyhedron (the "neighbour" across a face plane).
  static constexpr FeatureId Interior() { return {FeatureType::kNone, -1}; }

  /// Features are equal when type and index are.
  friend bool operator==(FeatureId, FeatureId) = default;
};

/// "vertex 3", "edge 7", "face 2" or "interior" (the spelling of the CLI's JSON output).
std::string ToString(FeatureId feature);

/// A plane {p : normal.dot(p) == offset} with a unit normal, in the polyhedron's frame.
struct Plane {
  /// Unit normal.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  /// normal.dot(p) for every point p of the plane, m.
  double offset = 0.0;

  /// Signed distance of p from the plane, positive on the side the normal points to.
  double SignedDistance(const Eigen::Vector3d& p) const { return normal.dot(p) - offset; }
};

/// One bounding plane of a feature's Voronoi region ("zone"), as in Lin & Canny 1991 and
/// Mirtich's V-Clip 1998. The normal points INTO the region: a point p satisfies the plane when
/// plane.SignedDistance(p) >= 0 and lies in the (closed) region when it satisfies all of the
/// region's planes. A point that violates the plane (SignedDistance < 0) lies on the side of
/// `neighbor`, the adjacent feature a closest-feature walk steps to.
struct VoronoiPlane {
  /// The bounding plane, its normal pointing into the region.
  Plane plane;
  /// The adjacent feature on the other side of the plane.
  FeatureId neighbor;
};

/// One edge: two vertices and the two faces that share it. faces[0] traverses the edge from
/// vertices[0] to vertices[1] in its counter-clockwise loop, faces[1] from vertices[1] to
/// vertices[0]. Edge e owns half-edges 2e (vertices[0] -> vertices[1], in faces[0]) and 2e+1.
struct Edge {
  /// The two end vertices.
  std::array<std::int32_t, 2> vertices{-1, -1};
  /// The two faces that share the edge (see above for their order).
  std::array<std::int32_t, 2> faces{-1, -1};
};

/// A directed edge inside one face's counter-clockwise boundary loop. Its twin (the same edge
/// in the neighbouring face, opposite direction) is `h ^ 1` and its edge is `h >> 1`.
struct HalfEdge {
  std::int32_t origin = -1;  ///< vertex the half-edge starts at
  std::int32_t face = -1;    ///< face whose boundary loop contains it
  std::int32_t next = -1;    ///< next half-edge of the loop (starts where this one ends)
  std::int32_t prev = -1;    ///< previous half-edge of the loop
};

/// One face: a planar convex polygon with an outward unit normal.
struct Face {
  Plane plane;             ///< outward normal; offset = normal . (any vertex of the face)
  std::int32_t first = 0;  ///< index of its first half-edge in the face loop arrays
  std::int32_t count = 0;  ///< number of vertices (= edges) of the face
};

/// How ConvexPolyhedron::FromMesh validates and repairs its input.
struct MeshValidation {
  /// Geometric tolerance relative to the polyhedron's scale() (the diagonal of the bounding box
  /// of its vertices): a vertex within tolerance * scale() of a plane counts as on it. It bounds
  /// the non-planarity of a face, the "dent" allowed by the convexity test and decides which
  /// adjacent faces are coplanar. 1e-9 leaves ~6 decimal digits of room above double round-off
  /// on scenes of size 1e3, yet is far below any feature a simulation resolves; loosen it (e.g.
  /// 1e-6) for meshes written with few digits.
  double tolerance = 1e-9;
  /// Merge adjacent faces whose planes agree within tolerance into one polygon (and remove the
  /// vertices that this leaves in the middle of a straight edge). If false, such faces are an
  /// error ("faces 3 and 4 are coplanar").
  bool merge_coplanar_faces = true;
  /// Flip a mesh whose faces are all wound clockwise (seen from outside) and record a warning.
  /// If false, such a mesh is an error.
  bool flip_inward_winding = true;
};

/// An immutable convex polyhedron: vertices, edges, faces with half-edge adjacency, outward face
/// planes, the Voronoi region of every feature as planes (for Lin-Canny / V-Clip closest-feature
/// walks) and uniform-density mass properties.
///
/// Frame: the polyhedron keeps the coordinates it was built from (its body frame B); nothing is
/// re-centred. centroid() is the centre of mass in B, inertia() is taken about the centroid with
/// B's axes, bounding_radius() is measured from the centroid. Use Recentered() for a copy whose
/// centroid is the origin of its frame.
///
/// Invariants (checked at construction): closed 2-manifold of genus 0 (V - E + F = 2), faces
/// wound counter-clockwise seen from outside, each face a convex polygon whose vertices lie within
/// tolerance() * scale() of its plane, no two adjacent faces coplanar, every vertex shared by
/// at least 3 faces, and every vertex at most tolerance() * scale() above every face plane.
///
/// Share one instance between bodies through std::shared_ptr<const ConvexPolyhedron>.
class ConvexPolyhedron {
 public:
  /// Convex hull of points (at least 4, not all coplanar, all finite), computed by Qhull with its
  /// default facet merging ("C-0": facets that are coplanar or concave within round-off are
  /// merged into polygons), then validated like FromMesh with `options` (which merges any
  /// adjacent faces still coplanar within the tolerance). Vertices are the hull vertices in
  /// increasing order of their index in `points`; interior points and points on faces or edges
  /// are not vertices.
  [[nodiscard]] static Result<ConvexPolyhedron> FromPoints(std::span<const Eigen::Vector3d> points,
                                                           MeshValidation options = {});

  /// Builds a polyhedron from a face list, validating that it is a closed, consistently wound,
  /// genus-0 2-manifold that is convex within options.tolerance; coplanar adjacent faces are
  /// merged and a uniformly inward-wound mesh is flipped (each with a message in warnings()).
  /// Anything else is refused with an Error that names the offending face, edge or vertex (by its
  /// index in `mesh`) and by how much it fails. Vertices that no face uses, or that merging leaves
  /// inside a face or in the middle of an edge, are dropped; the remaining vertices keep their
  /// relative order. Faces are numbered in order of the first input face that forms them.
  [[nodiscard]] static Result<ConvexPolyhedron> FromMesh(const PolygonMesh& mesh,
                                                         MeshValidation options = {});

  /// @name Features and adjacency
  /// @{

  /// Number of vertices V.
  int vertex_count() const { return static_cast<int>(vertices_.size()); }
  /// Number of edges E.
  int edge_count() const { return static_cast<int>(edges_.size()); }
  /// Number of faces F (V - E + F = 2).
  int face_count() const { return static_cast<int>(faces_.size()); }
  /// Number of half-edges (2E).
  int half_edge_count() const { return static_cast<int>(half_edges_.size()); }

  /// Position of vertex v in the body frame.
  const Eigen::Vector3d& vertex(int v) const { return vertices_[Index(v)]; }
  /// All vertex positions in the body frame, by index.
  std::span<const Eigen::Vector3d> vertices() const { return vertices_; }
  /// Edge e.
  const Edge& edge(int e) const { return edges_[Index(e)]; }
  /// All edges, by index.
  std::span<const Edge> edges() const { return edges_; }
  /// Face f.
  const Face& face(int f) const { return faces_[Index(f)]; }
  /// All faces, by index.
  std::span<const Face> faces() const { return faces_; }
  /// Half-edge h (edge e owns 2e and 2e + 1).
  const HalfEdge& half_edge(int h) const { return half_edges_[Index(h)]; }
  /// All half-edges, by index.
  std::span<const HalfEdge> half_edges() const { return half_edges_; }

  /// Boundary half-edges of face f in counter-clockwise order seen from outside.
  std::span<const std::int32_t> FaceHalfEdges(int f) const;
  /// Boundary edges of face f, in the same order as FaceHalfEdges(f).
  std::span<const std::int32_t> FaceEdges(int f) const;
  /// Vertex loop of face f (counter-clockwise seen from outside): FaceVertices(f)[i] is the
  /// origin of FaceHalfEdges(f)[i].
  std::span<const std::int32_t> FaceVertices(int f) const;

  /// Outgoing half-edges of vertex v in counter-clockwise order seen from outside. Between
  /// consecutive outgoing half-edges h_i and h_{i+1} lies the face half_edge(h_i).face, and
  /// h_{i+1} == twin(prev(h_i)).
  std::span<const std::int32_t> VertexHalfEdges(int v) const;
  /// Edges incident to vertex v, in the same order as VertexHalfEdges(v).
  std::span<const std::int32_t> VertexEdges(int v) const;
  /// Faces around vertex v: VertexFaces(v)[i] is the face of VertexHalfEdges(v)[i].
  std::span<const std::int32_t> VertexFaces(int v) const;

  /// The end of edge e that is not vertex v (v must be an endpoint of e).
  int OtherVertex(int e, int v) const;
  /// @}

  /// @name Voronoi regions (zones)
  /// @{

  /// The planes bounding the Voronoi region of a feature; a point is in the (closed) region iff
  /// every plane's SignedDistance is >= 0. The order is fixed so a walk can index it:
  /// - vertex v: one plane per incident edge, in VertexEdges(v) order; the plane passes through
  ///   v perpendicular to the edge, its neighbour is that edge.
  /// - edge e: [0] the plane through vertices[0] perpendicular to e (neighbour: vertex
  ///   vertices[0]), [1] the same at vertices[1] (neighbour: vertex vertices[1]), [2] the plane
  ///   through e perpendicular to faces[0] (neighbour: faces[0]), [3] the same for faces[1].
  /// - face f: [0] the face plane itself (normal outward, neighbour Interior()), then one plane
  ///   per boundary edge in FaceEdges(f) order, through the edge and perpendicular to the face
  ///   (normal pointing into the face; neighbour: that edge).
  /// Planes shared by two regions appear in both with opposite normals.
  std::span<const VoronoiPlane> VoronoiPlanes(FeatureId feature) const;
  /// VoronoiPlanes of vertex v, edge e or face f: inline, for the walk's inner loop.
  std::span<const VoronoiPlane> VertexPlanes(int v) const {
    return PlanesFrom(vertex_plane_first_[Index(v)], vertex_plane_first_[Index(v) + 1]);
  }
  /// The Voronoi planes of edge e (four).
  std::span<const VoronoiPlane> EdgePlanes(int e) const {
    return PlanesFrom(edge_plane_first_ + 4 * e, edge_plane_first_ + 4 * e + 4);
  }
  /// The Voronoi planes of face f (its plane, then one per boundary edge).
  std::span<const VoronoiPlane> FacePlanes(int f) const {
    return PlanesFrom(face_plane_first_[Index(f)], face_plane_first_[Index(f) + 1]);
  }
  /// @}

  /// @name Geometry and mass properties (uniform density 1; scale by the density)
  /// @{

  /// Enclosed volume (> 0).
  double volume() const { return volume_; }
  /// Centre of mass for uniform density, in the body frame.
  const Eigen::Vector3d& centroid() const { return centroid_; }
  /// Inertia tensor about the centroid, body axes, for density 1 (so mass = volume()).
  const Eigen::Matrix3d& inertia() const { return inertia_; }
  /// Largest distance from the centroid to a vertex: the radius of the element's sphere.
  double bounding_radius() const { return bounding_radius_; }
  /// Length scale that relative tolerances multiply: diagonal of the vertices' bounding box
  /// (between the diameter and sqrt(3) times the diameter).
  double scale() const { return scale_; }
  /// The relative tolerance the polyhedron was validated with (MeshValidation::tolerance).
  double tolerance() const { return tolerance_; }
  /// Messages about repairs made while building (a flipped winding, merged faces, dropped
  /// vertices); empty when the input was used as given.
  const std::vector<std::string>& warnings() const { return warnings_; }
  /// @}

  /// @name Queries
  /// @{

  /// The point of a feature closest to p (body frame); for a face, the closest point of the
  /// (filled) polygon. Brute force over the feature's boundary: O(size of the feature).
  Eigen::Vector3d ClosestPointOnFeature(FeatureId feature, const Eigen::Vector3d& p) const;
  /// The vertex that maximises direction.dot(vertex) (lowest index on ties). O(V).
  int SupportVertex(const Eigen::Vector3d& direction) const;
  /// The same maximum, found by climbing from vertex `start` to a strictly higher neighbour
  /// until none is higher: on a convex polyhedron a vertex that no neighbour exceeds is a
  /// maximum, so this is exact up to round-off in near-ties (where the value found is below
  /// the maximum by at most a few ulps x scale() per vertex of the tie). O(path x degree).
  int SupportVertexFrom(const Eigen::Vector3d& direction, int start) const;
  /// @}

  /// @name Copies and export
  /// @{

  /// A copy translated so that its centroid is the origin (feature indices unchanged).
  ConvexPolyhedron Recentered() const;
  /// A copy scaled uniformly about the origin of its frame by factor > 0 (indices unchanged).
  ConvexPolyhedron Scaled(double factor) const;
  /// The faces as a PolygonMesh (vertex loops counter-clockwise from outside), e.g. for io/.
  PolygonMesh ToMesh() const;
  /// @}

 private:
  ConvexPolyhedron() = default;

  static std::size_t Index(int i) { return static_cast<std::size_t>(i); }
  std::span<const VoronoiPlane> PlanesFrom(std::int32_t first, std::int32_t end) const {
    return {voronoi_planes_.data() + first, Index(end - first)};
  }
  // Fills planes, Voronoi regions and mass properties from vertices_ and the topology.
  void ComputeDerivedData();

  std::vector<Eigen::Vector3d> vertices_;
  std::vector<Edge> edges_;
  std::vector<HalfEdge> half_edges_;
  std::vector<Face> faces_;
  // Face loops in CSR form (ranges given by Face::first/count).
  std::vector<std::int32_t> face_half_edges_, face_edges_, face_vertices_;
  // Vertex rings in CSR form: vertex v's ring is [vertex_first_[v], vertex_first_[v + 1]).
  std::vector<std::int32_t> vertex_first_, vertex_half_edges_, vertex_edges_, vertex_faces_;
  // Voronoi planes of all features, CSR: vertices, then edges (4 each), then faces.
  std::vector<VoronoiPlane> voronoi_planes_;
  std::vector<std::int32_t> vertex_plane_first_, face_plane_first_;
  std::int32_t edge_plane_first_ = 0;

  double volume_ = 0.0;
  Eigen::Vector3d centroid_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia_ = Eigen::Matrix3d::Zero();
  double bounding_radius_ = 0.0;
  double scale_ = 0.0;
  double tolerance_ = 0.0;
  std::vector<std::string> warnings_;
};

}  // namespace sparsedyn
