// SPDX-License-Identifier: MIT
// Round trips for every format: FormatMesh -> ParseMesh, files through Write*/Read*, and what
// the readers must keep (polygons, vertex order, unused vertices) or weld (STL).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/example_polyhedra.hpp"
#include "io/mesh_test_util.hpp"
#include "sparsedyn/io/mesh_io.hpp"

namespace sparsedyn {
namespace {

using testing::ExamplePolyhedra;
using testing::NamedPolyhedron;
using testing::RoundedToFloat;
using testing::SameMesh;
using testing::TriangleSoup;

struct Case {
  MeshFormat format;
  MeshEncoding encoding;
  const char* label;
};

constexpr Case kCases[] = {
    {MeshFormat::kOff, MeshEncoding::kAscii, "off"},
    {MeshFormat::kOhio, MeshEncoding::kAscii, "ohio"},
    {MeshFormat::kObj, MeshEncoding::kAscii, "obj"},
    {MeshFormat::kPly, MeshEncoding::kAscii, "ply ascii"},
    {MeshFormat::kPly, MeshEncoding::kBinary, "ply binary"},
    {MeshFormat::kStl, MeshEncoding::kAscii, "stl ascii"},
    {MeshFormat::kStl, MeshEncoding::kBinary, "stl binary"},
};

TEST(MeshRoundTrip, EveryFormatReadsBackWhatItWrote) {
  for (const NamedPolyhedron& solid : ExamplePolyhedra()) {
    for (const Case& c : kCases) {
      SCOPED_TRACE(solid.name + " as " + c.label);
      Result<std::string> text = FormatMesh(solid.mesh, c.format, c.encoding);
      ASSERT_TRUE(text) << text.error().message;
      Result<PolygonMesh> back = ParseMesh(*text, c.format, "roundtrip");
      ASSERT_TRUE(back) << back.error().message;
      if (c.format != MeshFormat::kStl) {
        // Polygon formats: identical vertices (bitwise doubles), order and polygons.
        EXPECT_TRUE(SameMesh(*back, solid.mesh));
        continue;
      }
      // STL: the same oriented triangles; welding restores the shared vertices.
      const PolygonMesh expected =
          c.encoding == MeshEncoding::kBinary ? RoundedToFloat(solid.mesh) : solid.mesh;
      EXPECT_EQ(TriangleSoup(*back), TriangleSoup(expected));
      EXPECT_EQ(back->vertices.size(), solid.mesh.vertices.size());
      for (const std::vector<std::int32_t>& face : back->faces) EXPECT_EQ(face.size(), 3u);
    }
  }
}

TEST(MeshRoundTrip, WriteOffAndWriteOhioFilesReadBackExactly) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("sparsedyn_io_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const NamedPolyhedron& solid : ExamplePolyhedra()) {
    SCOPED_TRACE(solid.name);
    ASSERT_TRUE(WriteOff(solid.mesh, dir / "a.off"));
    ASSERT_TRUE(WriteOhio(solid.mesh, dir / "a.ohio"));
    Result<PolygonMesh> off = ReadOff(dir / "a.off");
    Result<PolygonMesh> ohio = ReadMesh(dir / "a.ohio");
    ASSERT_TRUE(off) << off.error().message;
    ASSERT_TRUE(ohio) << ohio.error().message;
    EXPECT_TRUE(SameMesh(*off, solid.mesh));
    EXPECT_TRUE(SameMesh(*ohio, solid.mesh));
  }
  std::filesystem::remove_all(dir);
}

TEST(MeshFormatFromPath, ExtensionIsCaseInsensitive) {
  EXPECT_EQ(*MeshFormatFromPath("a/B.OFF"), MeshFormat::kOff);
  EXPECT_EQ(*MeshFormatFromPath("x.Ohio"), MeshFormat::kOhio);
  EXPECT_EQ(*MeshFormatFromPath("x.Obj"), MeshFormat::kObj);
  EXPECT_EQ(*MeshFormatFromPath("x.STL"), MeshFormat::kStl);
  EXPECT_EQ(*MeshFormatFromPath("x.pLy"), MeshFormat::kPly);
  Result<MeshFormat> unknown = MeshFormatFromPath("mesh.3ds");
  ASSERT_FALSE(unknown);
  EXPECT_EQ(unknown.error().message,
            "mesh.3ds: unknown mesh extension '.3ds' (expected .off, .ohio, .obj, .stl or .ply)");
}

TEST(ReadMesh, MissingFileNamesThePath) {
  Result<PolygonMesh> mesh = ReadMesh("/nonexistent/sparsedyn/cube.off");
  ASSERT_FALSE(mesh);
  EXPECT_NE(mesh.error().message.find("/nonexistent/sparsedyn/cube.off: cannot open"),
            std::string::npos);
}

// A quad and a triangle sharing an edge, plus an unused vertex 0 and vertices listed in an
// order the faces do not follow: readers must keep all of it as is.
PolygonMesh QuadAndTriangle() {
  PolygonMesh mesh;
  mesh.vertices = {{9, 9, 9}, {1, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 2, 0}};
  mesh.faces = {{2, 3, 1, 4}, {4, 1, 5}};
  return mesh;
}

TEST(MeshReaders, KeepPolygonsVertexOrderAndUnusedVertices) {
  const PolygonMesh mesh = QuadAndTriangle();
  for (const Case& c : kCases) {
    if (c.format == MeshFormat::kStl) continue;
    SCOPED_TRACE(c.label);
    Result<PolygonMesh> back = ParseMesh(*FormatMesh(mesh, c.format, c.encoding), c.format, "m");
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_TRUE(SameMesh(*back, mesh));
  }
}

TEST(MeshReaders, ReadHandWrittenQuadsInEachPolygonFormat) {
  const PolygonMesh expected{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}}};
  const char* off =
      "OFF # a comment\n# another\n4 1 4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
      "4 0 1 2 3 255 0 0\n";
  const char* ohio = "4 1 4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 1 2 3 4\n";
  const char* obj =
      "o quad\nv 0 0 0\nv 1 0 0\nvn 0 0 1\nv 1 1 0\nv 0 1 0\nvt 0 0\n"
      "f 1/1/1 2//1 -2 -1/1\n";
  const char* ply =
      "ply\r\nformat ascii 1.0\r\ncomment crlf\r\nelement vertex 4\r\n"
      "property float x\r\nproperty float y\r\nproperty float z\r\n"
      "property uchar red\r\nelement face 1\r\n"
      "property list uchar uint vertex_index\r\nend_header\r\n"
      "0 0 0 1\r\n1 0 0 2\r\n1 1 0 3\r\n0 1 0 4\r\n4 0 1 2 3\r\n";
  for (const auto& [text, format] :
       {std::pair{off, MeshFormat::kOff}, std::pair{ohio, MeshFormat::kOhio},
        std::pair{obj, MeshFormat::kObj}, std::pair{ply, MeshFormat::kPly}}) {
    Result<PolygonMesh> mesh = ParseMesh(text, format, "quad");
    ASSERT_TRUE(mesh) << mesh.error().message;
    EXPECT_TRUE(SameMesh(*mesh, expected)) << text;
  }
}

TEST(StlReader, WeldsExactlyEqualPositionsIncludingSignedZero) {
  const char* stl =
      "solid t\n"
      "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n"
      " endloop\nendfacet\n"
      "facet normal 0 0 1\n outer loop\n  vertex 1 0 0\n  vertex 1 1 -0\n  vertex -0 1 0\n"
      " endloop\nendfacet\n"
      "facet normal 0 0 1\n outer loop\n  vertex 1 0 0\n  vertex 1.0000000000000002 1 0\n"
      "  vertex 0 1 0\n endloop\nendfacet\n"
      "endsolid t\n";
  Result<PolygonMesh> mesh = ParseStl(stl, "t.stl");
  ASSERT_TRUE(mesh) << mesh.error().message;
  // 1.0000000000000002 differs from 1 in the last bit: kept apart, nothing approximate.
  ASSERT_EQ(mesh->vertices.size(), 5u);
  EXPECT_EQ(mesh->faces, (std::vector<std::vector<std::int32_t>>{{0, 1, 2}, {1, 3, 2}, {1, 4, 2}}));
}

TEST(StlReader, BinaryFileWhoseHeaderStartsWithSolidIsReadAsBinary) {
  std::string bytes =
      *FormatMesh(ExamplePolyhedra()[0].mesh, MeshFormat::kStl, MeshEncoding::kBinary);
  bytes.replace(0, 5, "solid");
  Result<PolygonMesh> mesh = ParseStl(bytes, "solid_header.stl");
  ASSERT_TRUE(mesh) << mesh.error().message;
  EXPECT_EQ(mesh->faces.size(), 12u);
}

TEST(PlyReader, ReadsBigEndianAndSkipsOtherElementsAndLists) {
  std::string ply =
      "ply\nformat binary_big_endian 1.0\nelement material 1\nproperty list uchar float k\n"
      "element vertex 3\nproperty short x\nproperty short y\nproperty short z\n"
      "element face 1\nproperty list uchar int vertex_indices\nproperty uchar flags\n"
      "end_header\n";
  const unsigned char data[] = {2,    0x3f, 0x80, 0, 0, 0x40, 0, 0, 0,  // material: 1.0, 2.0
                                0,    1,    0,    2, 0, 3,              // vertex (1, 2, 3)
                                0xff, 0xff, 0,    0, 0, 0,              // vertex (-1, 0, 0)
                                0,    0,    0,    5, 0, 0,              // vertex (0, 5, 0)
                                3,    0,    0,    0, 2, 0,              // face (2 1 0), flags 7
                                0,    0,    1,    0, 0, 0,    0, 7};
  ply.append(reinterpret_cast<const char*>(data), sizeof(data));
  Result<PolygonMesh> mesh = ParsePly(ply, "be.ply");
  ASSERT_TRUE(mesh) << mesh.error().message;
  const PolygonMesh expected{{{1, 2, 3}, {-1, 0, 0}, {0, 5, 0}}, {{2, 1, 0}}};
  EXPECT_TRUE(SameMesh(*mesh, expected));
}

TEST(FormatMesh, RefusesWhatNoFileCanHold) {
  PolygonMesh bad = QuadAndTriangle();
  bad.faces.push_back({0, 1});
  Result<std::string> text = FormatMesh(bad, MeshFormat::kOff);
  ASSERT_FALSE(text);
  EXPECT_EQ(text.error().message,
            "cannot write mesh: face 2 has 2 vertices; a polygon needs at least 3");
  EXPECT_FALSE(FormatMesh(QuadAndTriangle(), MeshFormat::kOff, MeshEncoding::kBinary));
  bad = QuadAndTriangle();
  bad.vertices[3].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(FormatMesh(bad, MeshFormat::kPly));
}

}  // namespace
}  // namespace sparsedyn
