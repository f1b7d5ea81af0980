// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "sparsedyn/geometry/polygon_mesh.hpp"
#include "sparsedyn/result.hpp"

namespace sparsedyn {

/// The mesh file formats read and written by io/ (docs/decisions/0001-mesh-loading.md).
enum class MeshFormat {
  kOff,   ///< Geomview OFF (".off"): "OFF", counts, points, 0-based polygons.
  kOhio,  ///< Ohio State format of the thesis (".ohio"): counts, points, 1-based polygons.
  kObj,   ///< Wavefront OBJ (".obj"): only `v` and `f` statements carry geometry.
  kStl,   ///< STL (".stl"), ASCII or binary: triangles only.
  kPly,   ///< Stanford PLY (".ply"), ASCII, binary little or big endian.
};

/// How FormatMesh/WriteMesh encode a file. Only STL and PLY have a binary encoding.
enum class MeshEncoding { kAscii, kBinary };

/// The format named by the extension of `path`, compared case-insensitively (".OFF" is OFF).
/// An unknown or missing extension is an Error that names the path.
Result<MeshFormat> MeshFormatFromPath(const std::filesystem::path& path);

/// Reads a mesh file, choosing the format by extension (MeshFormatFromPath). Polygons are
/// kept as they are in the file (a quad stays a quad); vertices keep the file's order, and no
/// vertex is merged or dropped, except for STL (see ParseStl). Every malformed file is an
/// Error "<file>:<line>: <what>" (binary data: "<file>: byte <offset>: <what>"). The reader
/// never reserves memory from a declared count that the file size cannot back.
Result<PolygonMesh> ReadMesh(const std::filesystem::path& path);

/// Reads an OFF file; see ParseOff.
Result<PolygonMesh> ReadOff(const std::filesystem::path& path);
/// Reads an Ohio State file; see ParseOhio.
Result<PolygonMesh> ReadOhio(const std::filesystem::path& path);
/// Reads an OBJ file; see ParseObj.
Result<PolygonMesh> ReadObj(const std::filesystem::path& path);
/// Reads an ASCII or binary STL file; see ParseStl.
Result<PolygonMesh> ReadStl(const std::filesystem::path& path);
/// Reads an ASCII or binary PLY file; see ParsePly.
Result<PolygonMesh> ReadPly(const std::filesystem::path& path);

/// Parses the bytes of a mesh file in `format`; `name` is used in error messages in place of
/// a file name (tests pass e.g. "cube.off").
Result<PolygonMesh> ParseMesh(std::string_view content, MeshFormat format, std::string_view name);

/// OFF: an "OFF" line (the counts may follow on the same line), then "nvertices nfaces
/// nedges", nvertices lines "x y z", nfaces lines "n i_1 ... i_n" with 0-based indices,
/// optionally followed by an RGB or RGBA face colour, which is ignored. '#' starts a comment;
/// blank lines are skipped. The edge count is not checked (many writers put 0).
Result<PolygonMesh> ParseOff(std::string_view content, std::string_view name);

/// Ohio State format (DESIGN.md, the thesis's "3D" package [Crow82]): a first line "npoints
/// npolys nedges", then one "x y z" line per point, then one line per polygon: its vertex
/// count followed by 1-based vertex indices. Blank lines are skipped; there are no comments.
/// nedges must be a non-negative integer but is not checked against the polygons.
Result<PolygonMesh> ParseOhio(std::string_view content, std::string_view name);

/// OBJ: `v x y z` (an optional w must be 1; six values are read as a point and an ignored
/// colour) and `f` with `v`, `v/vt`, `v//vn` or `v/vt/vn` corners; indices are 1-based, and
/// negative ones count back from the last vertex read so far. `vt`, `vn`, `vp`, `g`, `o`,
/// `s`, `usemtl`, `mtllib` are ignored; any other statement (lines, curves...) is an Error,
/// so nothing is dropped silently. All groups and objects go into the one mesh.
Result<PolygonMesh> ParseObj(std::string_view content, std::string_view name);

/// STL, binary (80-byte header, uint32 triangle count, 50 bytes per triangle; the size must
/// match exactly) or ASCII ("solid" ... "endsolid", exactly three vertices per facet). STL
/// stores each triangle with its own three positions, so the reader welds positions that are
/// exactly equal (0.0 equals -0.0) into one vertex, numbered in order of first appearance;
/// nothing else is merged. Stored facet normals are ignored: the vertex order gives the
/// orientation. Faces are always triangles.
Result<PolygonMesh> ParseStl(std::string_view content, std::string_view name);

/// PLY 1.0, ascii, binary_little_endian or binary_big_endian: element "vertex" with scalar
/// properties x, y, z (of any PLY type; other properties are skipped) and element "face"
/// with a list property "vertex_indices" (or "vertex_index"). Other elements are skipped.
/// Declared element counts are checked against the bytes left before anything is reserved.
Result<PolygonMesh> ParsePly(std::string_view content, std::string_view name);

/// The file content of `mesh` in `format`. Coordinates are written in the shortest decimal
/// form that reads back to the same double, except binary STL, which stores float32 (each
/// coordinate rounded to the nearest float). STL has only triangles, so each polygon is
/// written as a fan from its first vertex (exact for the convex faces this library uses).
/// Binary PLY stores doubles. An Error if the mesh has a non-finite coordinate, a face with
/// fewer than 3 vertices or an index out of range, or if `format` has no binary encoding.
Result<std::string> FormatMesh(const PolygonMesh& mesh, MeshFormat format,
                               MeshEncoding encoding = MeshEncoding::kAscii);

/// Writes FormatMesh(mesh, MeshFormatFromPath(path), encoding) to `path`.
Status WriteMesh(const PolygonMesh& mesh, const std::filesystem::path& path,
                 MeshEncoding encoding = MeshEncoding::kAscii);

/// Writes `mesh` as OFF, whatever the extension of `path`.
Status WriteOff(const PolygonMesh& mesh, const std::filesystem::path& path);

/// Writes `mesh` in the Ohio State format (1-based indices; nedges is the number of distinct
/// undirected edges), whatever the extension of `path`.
Status WriteOhio(const PolygonMesh& mesh, const std::filesystem::path& path);

}  // namespace sparsedyn
