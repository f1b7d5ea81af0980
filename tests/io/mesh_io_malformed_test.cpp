// SPDX-License-Identifier: MIT
// Each class of malformed file, in every format where it can occur, gives its own error that
// names file:line (or the byte offset in binary data). Fixtures are inline strings.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "sparsedyn/io/mesh_io.hpp"

namespace sparsedyn {
namespace {

// The error message of parsing `content`, or "<parsed>" if it was accepted.
std::string ErrorOf(MeshFormat format, const std::string& content, const char* name) {
  Result<PolygonMesh> mesh = ParseMesh(content, format, name);
  return mesh ? std::string("<parsed>") : mesh.error().message;
}

constexpr const char* kPlyHead =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

// --- counts larger than the data -------------------------------------------------------------

TEST(MalformedMesh, CountsLargerThanTheData) {
  // Enough bytes for the declared counts to pass the size bound, but too few records.
  EXPECT_EQ(ErrorOf(MeshFormat::kOff,
                    "OFF\n8 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n\n\n\n\n\n\n\n\n\n\n\n\n"
                    "\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n",
                    "short.off"),
            "short.off:6: vertex 3 needs 3 coordinates, the line has 4");
  EXPECT_EQ(ErrorOf(MeshFormat::kOff, "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n          \n",
                    "short.off"),
            "short.off:7: file ends after 1 of 2 declared faces");
  EXPECT_EQ(
      ErrorOf(MeshFormat::kOhio, "3 1 3\n0 0 0\n1 0 0\n          \n            \n", "short.ohio"),
      "short.ohio:5: file ends after 2 of 3 declared vertices");
  // Too few bytes for the counts at all: refused at the header line, before reserving.
  EXPECT_EQ(ErrorOf(MeshFormat::kOff, "OFF\n8 6 12\n0 0 0\n", "cube.off"),
            "cube.off:2: declares 8 vertices, more than the remaining 6 bytes can hold");
  EXPECT_EQ(ErrorOf(MeshFormat::kOhio, "3 19 3\n0 0 0\n1 0 0\n0 1 0\n1 1 2 3\n", "t.ohio"),
            "t.ohio:1: declares 19 faces, more than the remaining 26 bytes can hold");
  EXPECT_EQ(ErrorOf(MeshFormat::kPly, std::string(kPlyHead) + "0 0 0\n1 0 0\n", "t.ply"),
            "t.ply:3: declares 3 'vertex' records, more than the remaining 12 bytes can hold");
  EXPECT_EQ(
      ErrorOf(MeshFormat::kPly, std::string(kPlyHead) + "0 0 0\n1 0 0\n0 1 0\n3 0 1", "t.ply"),
      "t.ply:13: file ends inside the data");
}

// --- indices out of range, or 0 where indices are 1-based ------------------------------------

TEST(MalformedMesh, IndexOutOfRange) {
  EXPECT_EQ(ErrorOf(MeshFormat::kOff, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 17\n", "a.off"),
            "a.off:6: face 0 has index 17 but the file has 3 vertices");
  EXPECT_EQ(ErrorOf(MeshFormat::kOff, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "a.off"),
            "a.off:6: face 0 has index -1 but the file has 3 vertices");
  EXPECT_EQ(ErrorOf(MeshFormat::kOhio, "3 1 3\n0 0 0\n1 0 0\n0 1 0\n3 1 2 4\n", "a.ohio"),
            "a.ohio:5: face 0 has index 4 but the file has 3 vertices");
  EXPECT_EQ(ErrorOf(MeshFormat::kObj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 17\n", "a.obj"),
            "a.obj:5: face 1 has index 17 but the file has 3 vertices");
  EXPECT_EQ(ErrorOf(MeshFormat::kObj, "v 0 0 0\nv 1 0 0\nf 1 2 -3\nv 0 1 0\n", "a.obj"),
            "a.obj:3: face 0 has relative index -3 but only 2 vertices precede it");
  EXPECT_EQ(
      ErrorOf(MeshFormat::kPly, std::string(kPlyHead) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 17\n", "a.ply"),
      "a.ply:13: face 0 has index 17 but the file has 3 vertices");
}

TEST(MalformedMesh, IndexZeroInOneBasedFormats) {
  EXPECT_EQ(ErrorOf(MeshFormat::kOhio, "3 1 3\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "z.ohio"),
            "z.ohio:5: face 0 has index 0 but indices in this format start at 1");
  EXPECT_EQ(ErrorOf(MeshFormat::kObj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0/1 1/1 2/1\n", "z.obj"),
            "z.obj:4: face 0 has index 0 but indices in this format start at 1");
}

// --- NaN / Inf tokens ------------------------------------------------------------------------

TEST(MalformedMesh, NonFiniteCoordinates) {
  EXPECT_EQ(ErrorOf(MeshFormat::kOff, "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "n.off"),
            "n.off:4: vertex 1 has a non-finite coordinate 'nan'");
  EXPECT_EQ(ErrorOf(MeshFormat::kOhio, "3 1 3\n0 0 0\n1 0 0\n0 1 -inf\n3 1 2 3\n", "n.ohio"),
            "n.ohio:4: vertex 2 has a non-finite coordinate '-inf'");
  EXPECT_EQ(ErrorOf(MeshFormat::kObj, "v 0 0 0\nv INF 0 0\nv 0 1 0\nf 1 2 3\n", "n.obj"),
            "n.obj:2: vertex 1 has a non-finite coordinate 'INF'");
  EXPECT_EQ(ErrorOf(MeshFormat::kStl,
                    "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex NaN 0 0\n"
                    "vertex 0 1 0\nendloop\nendfacet\nendsolid s\n",
                    "n.stl"),
            "n.stl:5: vertex 1 has a non-finite coordinate 'NaN'");
  EXPECT_EQ(ErrorOf(MeshFormat::kPly,
                    std::string(kPlyHead) + "0 0 0\n1 0 0\n0 infinity 0\n3 0 1 2\n", "n.ply"),
            "n.ply:12: vertex 2 has a non-finite coordinate 'inf'");
  // A literal too large for a double is not silently turned into infinity.
  EXPECT_EQ(ErrorOf(MeshFormat::kOff, "OFF\n3 1 0\n0 0 0\n1e999 0 0\n0 1 0\n3 0 1 2\n", "o.off"),
            "o.off:4: vertex 1: '1e999' is not a number");
}

TEST(MalformedMesh, NonFiniteCoordinateInBinaryStlNamesTheByte) {
  PolygonMesh triangle{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}};
  std::string bytes = *FormatMesh(triangle, MeshFormat::kStl, MeshEncoding::kBinary);
  // Triangle 0 starts at byte 84; its second corner's y is at 84 + 12 + 12 + 4 = 112.
  const unsigned char nan_bits[] = {0x00, 0x00, 0xc0, 0x7f};
  bytes.replace(112, 4, reinterpret_cast<const char*>(nan_bits), 4);
  EXPECT_EQ(ErrorOf(MeshFormat::kStl, bytes, "n.stl"),
            "n.stl: byte 112: triangle 0 has a non-finite coordinate (nan)");
}

// --- faces with fewer than 3 vertices --------------------------------------------------------

TEST(MalformedMesh, FacesWithFewerThanThreeVertices) {
  EXPECT_EQ(ErrorOf(MeshFormat::kOff, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "f.off"),
            "f.off:6: face 0 has 2 vertices; a polygon needs at least 3");
  EXPECT_EQ(ErrorOf(MeshFormat::kOhio, "3 2 3\n0 0 0\n1 0 0\n0 1 0\n3 1 2 3\n0\n", "f.ohio"),
            "f.ohio:6: face 1 has 0 vertices; a polygon needs at least 3");
  EXPECT_EQ(ErrorOf(MeshFormat::kObj, "v 0 0 0\nv 1 0 0\nf 1 2\n", "f.obj"),
            "f.obj:3: face 0 has 2 vertices; a polygon needs at least 3");
  EXPECT_EQ(ErrorOf(MeshFormat::kStl,
                    "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                    "endloop\nendfacet\nendsolid s\n",
                    "f.stl"),
            "f.stl:6: face 0 has 2 vertices; a polygon needs at least 3");
  EXPECT_EQ(
      ErrorOf(MeshFormat::kPly, std::string(kPlyHead) + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "f.ply"),
      "f.ply:13: face 0 has 2 vertices; a polygon needs at least 3");
  // A miscounted face is caught on its own line instead of shifting the rest of the file.
  EXPECT_EQ(
      ErrorOf(MeshFormat::kOff, "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2 3\n", "c.off"),
      "c.off:7: face 0 declares 3 vertices but the line has 4 numbers after the count");
}

// --- truncated binary STL --------------------------------------------------------------------

TEST(MalformedMesh, TruncatedBinaryStl) {
  PolygonMesh quad{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}}};
  const std::string bytes = *FormatMesh(quad, MeshFormat::kStl, MeshEncoding::kBinary);
  ASSERT_EQ(bytes.size(), 84u + 2 * 50u);
  EXPECT_EQ(ErrorOf(MeshFormat::kStl, bytes.substr(0, 150), "cut.stl"),
            "cut.stl: byte 80: binary STL declares 2 triangles (184 bytes) but the file has 150 "
            "bytes");
  EXPECT_EQ(ErrorOf(MeshFormat::kStl, bytes.substr(0, 50), "cut.stl"),
            "cut.stl: byte 50: binary STL ends inside its 84-byte header (50 bytes)");
}

TEST(MalformedMesh, TruncatedBinaryPly) {
  PolygonMesh triangle{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}};
  const std::string bytes = *FormatMesh(triangle, MeshFormat::kPly, MeshEncoding::kBinary);
  // Cut inside the last index of the face list: the bounded counts pass, the read fails.
  const std::size_t cut = bytes.size() - 2;
  EXPECT_EQ(ErrorOf(MeshFormat::kPly, bytes.substr(0, cut), "cut.ply"),
            "cut.ply: byte " + std::to_string(cut - 6) + ": file ends inside the data");
}

// --- everything else a strict reader refuses -------------------------------------------------

TEST(MalformedMesh, OtherStructuralErrorsNameTheLine) {
  EXPECT_EQ(
      ErrorOf(MeshFormat::kOff, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n", "x.off"),
      "x.off:7: unexpected content after the last of 1 faces");
  EXPECT_EQ(ErrorOf(MeshFormat::kOff, "COFF\n", "x.off"), "x.off:1: expected 'OFF', found 'COFF'");
  EXPECT_EQ(ErrorOf(MeshFormat::kOff, "OFF\n3 x 0\n", "x.off"),
            "x.off:2: face count 'x' is not a non-negative integer");
  EXPECT_EQ(ErrorOf(MeshFormat::kOff, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0,5\n3 0 1 2\n", "x.off"),
            "x.off:5: vertex 2: '0,5' is not a number");
  EXPECT_EQ(ErrorOf(MeshFormat::kObj, "v 0 0 0\nl 1 2\n", "x.obj"),
            "x.obj:2: unsupported OBJ statement 'l' (only polygon geometry v/f is read)");
  EXPECT_EQ(ErrorOf(MeshFormat::kObj, "v 0 0 0 0.5\n", "x.obj"),
            "x.obj:1: vertex 0 has weight '0.5'; only 1 is supported");
  EXPECT_EQ(ErrorOf(MeshFormat::kStl, "solid s\nfacet normal 0 0 1\nouter loop\n", "x.stl"),
            "x.stl:3: face 0 has 0 vertices; a polygon needs at least 3");
  EXPECT_EQ(
      ErrorOf(MeshFormat::kPly, "ply\nformat ascii 1.0\nelement vertex 0\nend_header\n", "x.ply"),
      "x.ply:3: element 'vertex' has no properties");
  EXPECT_EQ(
      ErrorOf(MeshFormat::kPly,
              "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nend_header\n", "x.ply"),
      "x.ply:3: element 'vertex' lacks x, y or z");
  EXPECT_EQ(ErrorOf(MeshFormat::kPly, std::string(kPlyHead) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 7\n",
                    "x.ply"),
            "x.ply:13: unexpected data after the last element");
  EXPECT_EQ(ErrorOf(MeshFormat::kPly, "ply\nformat ascii 2.0\n", "x.ply"),
            "x.ply:2: expected 'format ENCODING 1.0'");
}

}  // namespace
}  // namespace sparsedyn
