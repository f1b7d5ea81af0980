// SPDX-License-Identifier: MIT
// Wavefront OBJ, geometry statements only (v, f); see ParseObj in mesh_io.hpp.
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/mesh_parse_support.hpp"
#include "sparsedyn/io/mesh_io.hpp"

namespace sparsedyn {
namespace {

using io_detail::LineError;
using io_detail::Str;

// Statements that carry no polygon geometry and are skipped on purpose.
constexpr std::array<std::string_view, 8> kIgnored = {"vt", "vn", "vp",     "g",
                                                      "o",  "s",  "usemtl", "mtllib"};

// The vertex part of one face corner "v", "v/vt", "v//vn" or "v/vt/vn", resolved to 0-based
// against the vertices read so far (negative indices count back from the last one).
Result<std::int64_t> ParseCorner(std::string_view token, std::int64_t face,
                                 std::int64_t vertices_so_far, std::string_view name,
                                 std::int64_t line) {
  const std::string_view vertex_part = token.substr(0, token.find('/'));
  const std::optional<std::int64_t> index = io_detail::ParseInteger(vertex_part);
  if (!index) {
    return LineError(name, line, Str("face ", face, ": '", token, "' is not a vertex index"));
  }
  if (*index == 0) return LineError(name, line, io_detail::IndexZero(face));
  if (*index < 0) {
    if (-*index > vertices_so_far) {
      return LineError(name, line,
                       Str("face ", face, " has relative index ", *index, " but only ",
                           vertices_so_far, " vertices precede it"));
    }
    return vertices_so_far + *index;
  }
  return *index - 1;
}

}  // namespace

Result<PolygonMesh> ParseObj(std::string_view content, std::string_view name) {
  PolygonMesh mesh;
  // Positive indices may name vertices defined later in the file, so they are checked once
  // all vertices are known; the line of each face is kept for that message.
  std::vector<std::int64_t> face_lines;
  io_detail::LineCursor cursor(content);
  std::string_view line;
  while (cursor.Next(line)) {
    const std::vector<std::string_view> tokens =
        io_detail::SplitTokens(io_detail::StripComment(line, '#'));
    if (tokens.empty()) continue;
    const std::string_view keyword = tokens[0];
    const std::int64_t line_number = cursor.line_number();

    if (keyword == "v") {
      const auto vertex = static_cast<std::int64_t>(mesh.vertices.size());
      const std::size_t values = tokens.size() - 1;
      if (values != 3 && values != 4 && values != 6) {
        return LineError(name, line_number,
                         Str("vertex ", vertex, " has ", values,
                             " values; expected x y z, x y z w or x y z r g b"));
      }
      Result<Eigen::Vector3d> p = io_detail::ParsePoint(tokens, 1, name, line_number, vertex);
      if (!p) return p.error();
      // A rational weight other than 1 would move the point; refuse rather than guess.
      if (values == 4 && io_detail::ParseDouble(tokens[4]) != 1.0) {
        return LineError(
            name, line_number,
            Str("vertex ", vertex, " has weight '", tokens[4], "'; only 1 is supported"));
      }
      mesh.vertices.push_back(*p);
    } else if (keyword == "f") {
      const auto face = static_cast<std::int64_t>(mesh.faces.size());
      const auto size = static_cast<std::int64_t>(tokens.size()) - 1;
      if (size < 3) return LineError(name, line_number, io_detail::FaceTooSmall(face, size));
      std::vector<std::int32_t> indices;
      indices.reserve(static_cast<std::size_t>(size));
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        Result<std::int64_t> index = ParseCorner(
            tokens[k], face, static_cast<std::int64_t>(mesh.vertices.size()), name, line_number);
        if (!index) return index.error();
        // No file can hold 2^31 vertices (see the allocation bound of the other readers).
        if (*index >= INT32_MAX) {
          return LineError(name, line_number,
                           io_detail::IndexOutOfRange(
                               face, *index + 1, static_cast<std::int64_t>(mesh.vertices.size())));
        }
        indices.push_back(static_cast<std::int32_t>(*index));
      }
      mesh.faces.push_back(std::move(indices));
      face_lines.push_back(line_number);
    } else if (std::find(kIgnored.begin(), kIgnored.end(), keyword) == kIgnored.end()) {
      return LineError(
          name, line_number,
          Str("unsupported OBJ statement '", keyword, "' (only polygon geometry v/f is read)"));
    }
  }

  const auto vertex_count = static_cast<std::int64_t>(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    for (const std::int32_t index : mesh.faces[f]) {
      if (index >= vertex_count) {
        return LineError(
            name, face_lines[f],
            io_detail::IndexOutOfRange(static_cast<std::int64_t>(f), index + 1, vertex_count));
      }
    }
  }
  return mesh;
}

namespace io_detail {

std::string FormatObjText(const PolygonMesh& mesh) {
  std::string out =
      Str("# ", mesh.vertices.size(), " vertices, ", mesh.faces.size(), " faces (sparsedyn)\n");
  for (const Eigen::Vector3d& p : mesh.vertices) {
    out +=
        "v " + FormatDouble(p.x()) + " " + FormatDouble(p.y()) + " " + FormatDouble(p.z()) + "\n";
  }
  for (const std::vector<std::int32_t>& face : mesh.faces) {
    out += "f";
    for (const std::int32_t index : face) (out += ' ') += std::to_string(index + 1);
    out += "\n";
  }
  return out;
}

}  // namespace io_detail
}  // namespace sparsedyn
