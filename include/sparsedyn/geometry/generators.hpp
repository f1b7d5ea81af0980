// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string_view>
#include <vector>

#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/result.hpp"

namespace sparsedyn {

/// The five Platonic solids.
enum class PlatonicSolid : std::uint8_t {
  kTetrahedron,
  kCube,
  kOctahedron,
  kDodecahedron,
  kIcosahedron,
};
inline constexpr int kPlatonicSolidCount = 5;

/// The thirteen Archimedean solids (the snub solids in one fixed chirality).
enum class ArchimedeanSolid : std::uint8_t {
  kTruncatedTetrahedron,
  kCuboctahedron,
  kTruncatedCube,
  kTruncatedOctahedron,
  kRhombicuboctahedron,
  kTruncatedCuboctahedron,
  kSnubCube,
  kIcosidodecahedron,
  kTruncatedDodecahedron,
  kTruncatedIcosahedron,
  kRhombicosidodecahedron,
  kTruncatedIcosidodecahedron,
  kSnubDodecahedron,
};
inline constexpr int kArchimedeanSolidCount = 13;

/// Lower-case name, e.g. "dodecahedron", "truncated icosahedron".
std::string_view ToString(PlatonicSolid solid);
std::string_view ToString(ArchimedeanSolid solid);

/// Number of faces of the solid (e.g. 12 for the dodecahedron, 92 for the snub dodecahedron).
int FaceCount(PlatonicSolid solid);
int FaceCount(ArchimedeanSolid solid);

/// The vertices of the solid in the standard Cartesian coordinates (centred at the origin; the
/// cube is [-1, 1]^3, the tetrahedron the alternate corners of that cube, the octahedron +-e_i;
/// the others as on Wikipedia's pages for each solid, with unit or small-integer edge lengths).
std::vector<Eigen::Vector3d> SolidVertices(PlatonicSolid solid);
std::vector<Eigen::Vector3d> SolidVertices(ArchimedeanSolid solid);

/// The solid as a polyhedron: the convex hull of SolidVertices(solid), centred at the origin,
/// with its regular polygons as faces.
ConvexPolyhedron MakeSolid(PlatonicSolid solid);
ConvexPolyhedron MakeSolid(ArchimedeanSolid solid);

/// A box [-h, h] (component-wise) for half extents h > 0. Centred at the origin.
[[nodiscard]] Result<ConvexPolyhedron> MakeBox(const Eigen::Vector3d& half_extents);

/// A right prism over a regular n-gon (n >= 3) inscribed in a circle of `radius` in the xy-plane,
/// extending from z = -half_height to z = +half_height. Centred at the origin; n + 2 faces.
[[nodiscard]] Result<ConvexPolyhedron> MakePrism(int sides, double radius, double half_height);

/// A needle for degenerate tests: a prism with `sides` sides, `length` along z and a
/// circumscribed diameter of length / aspect_ratio (1000:1 by default). Centred at the origin.
[[nodiscard]] Result<ConvexPolyhedron> MakeNeedle(double length, double aspect_ratio = 1000.0,
                                                  int sides = 6);

/// A slab for degenerate tests: a square plate of side `width` in the xy-plane and thickness
/// width / aspect_ratio (1000:1 by default) along z. Centred at the origin.
[[nodiscard]] Result<ConvexPolyhedron> MakeSlab(double width, double aspect_ratio = 1000.0);

/// Options of RandomConvexPolyhedron.
struct RandomPolyhedronOptions {
  /// Semi-axes of the ellipsoid the vertices lie on (all 1: a sphere of radius 1). The points
  /// are drawn on the unit sphere and then stretched, so the face count is unaffected.
  Eigen::Vector3d radii = Eigen::Vector3d::Ones();
  /// Minimum distance between two vertices on the unit sphere, as a fraction of the mean spacing
  /// sqrt(4 pi / n) of n points: rejects near-coincident points, which would give needle-thin
  /// triangles. 0 gives plain uniform random points (the thesis's "hull of random points").
  double min_separation = 0.3;
};

/// A random convex polyhedron with exactly `face_count` faces (4 <= face_count <= 100000),
/// deterministic for a given seed on every platform (std::mt19937_64 with our own mapping to
/// [0, 1), rejection sampling in the cube, no transcendental functions).
///
/// Method: n points on the unit sphere are in general position with probability 1, so their hull
/// has only triangles and F = 2n - 4 faces. An even face count takes n = F / 2 + 2 random points;
/// an odd count replaces four of them with a square whose corners lie exactly in the plane
/// z = h (a cap that no other point enters), giving one quadrilateral and F = 2n - 5. If round-off
/// merging ever changes the count, the attempt is redrawn from the same random stream, so the
/// result always has exactly `face_count` faces. Stretched by options.radii afterwards (an
/// affine map keeps the face structure). The polyhedron is centred near, not at, the origin: use
/// Recentered() for a body frame at the centroid.
[[nodiscard]] Result<ConvexPolyhedron> RandomConvexPolyhedron(int face_count, std::uint64_t seed,
                                                              RandomPolyhedronOptions options = {});

/// RandomConvexPolyhedron on an ellipsoid with the given semi-axes (e.g. {1, 1, 3} for a cigar).
[[nodiscard]] Result<ConvexPolyhedron> RandomEllipsoidalPolyhedron(int face_count,
                                                                   const Eigen::Vector3d& radii,
                                                                   std::uint64_t seed);

}  // namespace sparsedyn
