// SPDX-License-Identifier: MIT
// OFF and the Ohio State format: both are "counts, then points, then counted polygons", and
// differ in the header keyword, comments, the index base and optional face colours.
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

using io_detail::LineCursor;
using io_detail::LineError;
using io_detail::Str;

// Every record is a line of at least two bytes (one character and its newline). Declared
// counts are checked against that before anything is reserved, so a 100-byte file that
// declares 2^31 vertices is refused without allocating (tests/io/hostile_counts_test.cpp),
// while a short but malformed record still gets its own error.
constexpr std::int64_t kMinRecordBytes = 2;

struct CountedFormat {
  char comment;             // '\0': the format has no comments
  std::int32_t index_base;  // 0 for OFF, 1 for Ohio
  bool allows_face_colour;  // OFF faces may end with RGB or RGBA
};

// Next line that is not blank once comments are removed; false at the end of the text.
bool NextContentLine(LineCursor& cursor, const CountedFormat& format, std::string_view& line) {
  while (cursor.Next(line)) {
    if (format.comment != '\0') line = io_detail::StripComment(line, format.comment);
    if (!io_detail::IsBlank(line)) return true;
  }
  return false;
}

// Rejects counts that the rest of the file cannot hold, then reserves them.
Status CheckAndReserve(std::int64_t vertex_count, std::int64_t face_count,
                       std::size_t remaining_bytes, std::string_view name, std::int64_t line,
                       PolygonMesh& mesh) {
  // The last record may lack its newline, hence the extra byte.
  const auto budget = static_cast<std::int64_t>(remaining_bytes) + 1;
  if (vertex_count > budget / kMinRecordBytes) {
    return LineError(name, line,
                     io_detail::TooManyDeclared("vertices", vertex_count, remaining_bytes));
  }
  if (face_count > (budget - vertex_count * kMinRecordBytes) / kMinRecordBytes) {
    return LineError(name, line, io_detail::TooManyDeclared("faces", face_count, remaining_bytes));
  }
  mesh.vertices.reserve(static_cast<std::size_t>(vertex_count));
  mesh.faces.reserve(static_cast<std::size_t>(face_count));
  return Status::Ok();
}

// One polygon line: "n i_1 ... i_n [colour]".
Result<std::vector<std::int32_t>> ParseFaceLine(std::string_view line, std::int64_t face,
                                                std::int64_t vertex_count,
                                                const CountedFormat& format, std::string_view name,
                                                std::int64_t line_number) {
  const std::vector<std::string_view> tokens = io_detail::SplitTokens(line);
  Result<std::int64_t> size =
      io_detail::ParseCount(tokens[0], Str("face ", face, ": vertex count"), name, line_number);
  if (!size) return size.error();
  if (*size < 3) return LineError(name, line_number, io_detail::FaceTooSmall(face, *size));

  // The declared size must match the tokens on the line (plus an optional OFF colour), so a
  // miscounted face is caught here rather than shifting every later record.
  const auto extra = static_cast<std::int64_t>(tokens.size()) - 1 - *size;
  const bool extra_ok = extra == 0 || (format.allows_face_colour && (extra == 3 || extra == 4));
  if (!extra_ok) {
    return LineError(name, line_number,
                     Str("face ", face, " declares ", *size, " vertices but the line has ",
                         tokens.size() - 1, " numbers after the count"));
  }

  std::vector<std::int32_t> indices;
  indices.reserve(static_cast<std::size_t>(*size));
  for (std::int64_t k = 1; k <= *size; ++k) {
    const std::string_view token = tokens[static_cast<std::size_t>(k)];
    const std::optional<std::int64_t> index = io_detail::ParseInteger(token);
    if (!index) {
      return LineError(name, line_number,
                       Str("face ", face, ": index '", token, "' is not an integer"));
    }
    if (format.index_base == 1 && *index == 0) {
      return LineError(name, line_number, io_detail::IndexZero(face));
    }
    if (*index < format.index_base || *index - format.index_base >= vertex_count) {
      return LineError(name, line_number, io_detail::IndexOutOfRange(face, *index, vertex_count));
    }
    indices.push_back(static_cast<std::int32_t>(*index - format.index_base));
  }
  return indices;
}

// Everything after the counts: the points, the polygons and nothing else.
Result<PolygonMesh> ParseRecords(LineCursor& cursor, std::int64_t vertex_count,
                                 std::int64_t face_count, const CountedFormat& format,
                                 std::string_view name) {
  PolygonMesh mesh;
  Status reserved = CheckAndReserve(vertex_count, face_count, cursor.remaining_bytes(), name,
                                    cursor.line_number(), mesh);
  if (!reserved) return reserved.error();

  std::string_view line;
  for (std::int64_t v = 0; v < vertex_count; ++v) {
    if (!NextContentLine(cursor, format, line)) {
      return LineError(name, cursor.line_number(),
                       io_detail::EndsEarly("vertices", v, vertex_count));
    }
    const std::vector<std::string_view> tokens = io_detail::SplitTokens(line);
    if (tokens.size() != 3) {
      return LineError(name, cursor.line_number(),
                       Str("vertex ", v, " needs 3 coordinates, the line has ", tokens.size()));
    }
    Result<Eigen::Vector3d> p = io_detail::ParsePoint(tokens, 0, name, cursor.line_number(), v);
    if (!p) return p.error();
    mesh.vertices.push_back(*p);
  }

  for (std::int64_t f = 0; f < face_count; ++f) {
    if (!NextContentLine(cursor, format, line)) {
      return LineError(name, cursor.line_number(), io_detail::EndsEarly("faces", f, face_count));
    }
    Result<std::vector<std::int32_t>> face =
        ParseFaceLine(line, f, vertex_count, format, name, cursor.line_number());
    if (!face) return face.error();
    mesh.faces.push_back(std::move(*face));
  }

  if (NextContentLine(cursor, format, line)) {
    return LineError(name, cursor.line_number(),
                     Str("unexpected content after the last of ", face_count, " faces"));
  }
  return mesh;
}

// The three counts "nvertices nfaces nedges" starting at tokens[first].
Result<std::array<std::int64_t, 3>> ParseCounts(const std::vector<std::string_view>& tokens,
                                                std::size_t first, std::string_view name,
                                                std::int64_t line) {
  if (tokens.size() != first + 3) {
    return LineError(name, line, "expected the three counts 'vertices faces edges'");
  }
  std::array<std::int64_t, 3> counts{};
  constexpr std::array<const char*, 3> kWhat = {"vertex count", "face count", "edge count"};
  for (std::size_t i = 0; i < 3; ++i) {
    Result<std::int64_t> count = io_detail::ParseCount(tokens[first + i], kWhat[i], name, line);
    if (!count) return count.error();
    counts[i] = *count;
  }
  return counts;
}

}  // namespace

Result<PolygonMesh> ParseOff(std::string_view content, std::string_view name) {
  constexpr CountedFormat kOff{.comment = '#', .index_base = 0, .allows_face_colour = true};
  LineCursor cursor(content);
  std::string_view line;
  if (!NextContentLine(cursor, kOff, line)) return LineError(name, 1, "empty file, expected 'OFF'");
  std::vector<std::string_view> tokens = io_detail::SplitTokens(line);
  if (tokens[0] != "OFF") {
    return LineError(name, cursor.line_number(), Str("expected 'OFF', found '", tokens[0], "'"));
  }
  // The counts usually have a line of their own but may follow "OFF" on the first line.
  if (tokens.size() == 1) {
    if (!NextContentLine(cursor, kOff, line)) {
      return LineError(name, cursor.line_number(), "file ends before the counts");
    }
    tokens = io_detail::SplitTokens(line);
  } else {
    tokens.erase(tokens.begin());
  }
  Result<std::array<std::int64_t, 3>> counts = ParseCounts(tokens, 0, name, cursor.line_number());
  if (!counts) return counts.error();
  return ParseRecords(cursor, (*counts)[0], (*counts)[1], kOff, name);
}

Result<PolygonMesh> ParseOhio(std::string_view content, std::string_view name) {
  constexpr CountedFormat kOhio{.comment = '\0', .index_base = 1, .allows_face_colour = false};
  LineCursor cursor(content);
  std::string_view line;
  if (!NextContentLine(cursor, kOhio, line)) {
    return LineError(name, 1, "empty file, expected 'npoints npolys nedges'");
  }
  Result<std::array<std::int64_t, 3>> counts =
      ParseCounts(io_detail::SplitTokens(line), 0, name, cursor.line_number());
  if (!counts) return counts.error();
  return ParseRecords(cursor, (*counts)[0], (*counts)[1], kOhio, name);
}

namespace io_detail {

// Writers for the two formats; the checks of CheckWritable have run.
std::string FormatCounted(const PolygonMesh& mesh, bool ohio) {
  std::string out = ohio ? "" : "OFF\n";
  out += Str(mesh.vertices.size(), " ", mesh.faces.size(), " ", CountUniqueEdges(mesh), "\n");
  for (const Eigen::Vector3d& p : mesh.vertices) {
    out += FormatDouble(p.x()) + " " + FormatDouble(p.y()) + " " + FormatDouble(p.z()) + "\n";
  }
  const std::int32_t base = ohio ? 1 : 0;
  for (const std::vector<std::int32_t>& face : mesh.faces) {
    out += std::to_string(face.size());
    for (const std::int32_t index : face) (out += ' ') += std::to_string(index + base);
    out += "\n";
  }
  return out;
}

}  // namespace io_detail
}  // namespace sparsedyn
