// SPDX-License-Identifier: MIT
#pragma once

// Shared pieces of the mesh readers and writers in io/: a line cursor that counts lines, token
// splitting, strict number parsing, error messages that name file:line or a byte offset, and
// the checks every writer runs. Internal to the library.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "sparsedyn/geometry/polygon_mesh.hpp"
#include "sparsedyn/result.hpp"

namespace sparsedyn::io_detail {

/// Concatenates the streamed forms of `parts` (error messages only).
template <typename... Parts>
std::string Str(const Parts&... parts) {
  std::ostringstream out;
  (out << ... << parts);
  return out.str();
}

/// "<name>:<line>: <what>".
Error LineError(std::string_view name, std::int64_t line, std::string_view what);

/// "<name>: byte <offset>: <what>", for binary data, which has no lines.
Error ByteError(std::string_view name, std::uint64_t offset, std::string_view what);

/// Walks a text line by line, 1-based line numbers; accepts LF and CRLF endings.
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}

  /// Moves to the next line and stores it (without its end of line) in `line`; false at the end.
  bool Next(std::string_view& line);

  /// The number of the line last returned by Next (0 before the first call).
  std::int64_t line_number() const { return line_number_; }

  /// Bytes after the line last returned, i.e. what later records must fit in.
  std::size_t remaining_bytes() const { return text_.size() - position_; }

 private:
  std::string_view text_;
  std::size_t position_ = 0;
  std::int64_t line_number_ = 0;
};

/// Splits `line` at spaces, tabs and other ASCII whitespace.
std::vector<std::string_view> SplitTokens(std::string_view line);

/// `line` without everything from the first `comment` character on.
std::string_view StripComment(std::string_view line, char comment);

/// True if `line` holds only whitespace.
bool IsBlank(std::string_view line);

/// The whole `token` as a double (a leading '+' is allowed); "nan" and "inf" parse, so callers
/// check finiteness to name the token. nullopt if the token is not a number.
std::optional<double> ParseDouble(std::string_view token);

/// The whole `token` as a decimal integer (optional sign); nullopt otherwise or on overflow.
std::optional<std::int64_t> ParseInteger(std::string_view token);

/// Reads three coordinates from `tokens[first..first+2]` for vertex `vertex` (0-based).
/// Errors name the non-numeric or non-finite token.
Result<Eigen::Vector3d> ParsePoint(const std::vector<std::string_view>& tokens, std::size_t first,
                                   std::string_view name, std::int64_t line, std::int64_t vertex);

/// A non-negative count from `token` for an error message's `what` ("vertex count").
Result<std::int64_t> ParseCount(std::string_view token, std::string_view what,
                                std::string_view name, std::int64_t line);

/// Shortest decimal text that reads back to exactly `value`.
std::string FormatDouble(double value);

/// Number of distinct undirected edges of the polygons (the Ohio/OFF edge count).
std::int64_t CountUniqueEdges(const PolygonMesh& mesh);

/// What every writer refuses: non-finite coordinates, faces with fewer than 3 vertices and
/// indices outside [0, vertex count).
Status CheckWritable(const PolygonMesh& mesh);

/// Error text for the classes of malformed input shared by the readers, so that each class
/// reads the same in every format (the tests look for these phrases).
std::string FaceTooSmall(std::int64_t face, std::int64_t size);
std::string IndexOutOfRange(std::int64_t face, std::int64_t index, std::int64_t vertex_count);
std::string IndexZero(std::int64_t face);
std::string TooManyDeclared(std::string_view what, std::int64_t declared, std::size_t bytes);
std::string EndsEarly(std::string_view what, std::int64_t read, std::int64_t declared);

// The writers behind FormatMesh, one per format and encoding; CheckWritable has passed.
std::string FormatCounted(const PolygonMesh& mesh, bool ohio);
std::string FormatObjText(const PolygonMesh& mesh);
std::string FormatStlText(const PolygonMesh& mesh);
std::string FormatStlBinary(const PolygonMesh& mesh);
std::string FormatPlyData(const PolygonMesh& mesh, bool binary);

}  // namespace sparsedyn::io_detail
