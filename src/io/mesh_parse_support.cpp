// SPDX-License-Identifier: MIT
#include "io/mesh_parse_support.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>
#include <utility>

namespace sparsedyn::io_detail {

Error LineError(std::string_view name, std::int64_t line, std::string_view what) {
  return Error{Str(name, ":", line, ": ", what)};
}

Error ByteError(std::string_view name, std::uint64_t offset, std::string_view what) {
  return Error{Str(name, ": byte ", offset, ": ", what)};
}

bool LineCursor::Next(std::string_view& line) {
  if (position_ >= text_.size()) return false;
  std::size_t end = text_.find('\n', position_);
  const std::size_t next = end == std::string_view::npos ? text_.size() : end + 1;
  if (end == std::string_view::npos) end = text_.size();
  line = text_.substr(position_, end - position_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  position_ = next;
  ++line_number_;
  return true;
}

namespace {
bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}
}  // namespace

std::vector<std::string_view> SplitTokens(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && IsSpace(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !IsSpace(line[i])) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

std::string_view StripComment(std::string_view line, char comment) {
  const std::size_t at = line.find(comment);
  return at == std::string_view::npos ? line : line.substr(0, at);
}

bool IsBlank(std::string_view line) { return std::all_of(line.begin(), line.end(), IsSpace); }

std::optional<double> ParseDouble(std::string_view token) {
  // from_chars rejects a leading '+', which some writers emit; "++1" stays invalid.
  if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+') {
    token.remove_prefix(1);
  }
  double value = 0.0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  // Out-of-range literals such as 1e999 are refused rather than turned into infinity.
  if (error != std::errc() || end != token.data() + token.size()) return std::nullopt;
  return value;
}

std::optional<std::int64_t> ParseInteger(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') token.remove_prefix(1);
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size()) return std::nullopt;
  return value;
}

Result<Eigen::Vector3d> ParsePoint(const std::vector<std::string_view>& tokens, std::size_t first,
                                   std::string_view name, std::int64_t line, std::int64_t vertex) {
  Eigen::Vector3d p;
  for (int axis = 0; axis < 3; ++axis) {
    const std::string_view token = tokens[first + static_cast<std::size_t>(axis)];
    const std::optional<double> value = ParseDouble(token);
    if (!value) {
      return LineError(name, line, Str("vertex ", vertex, ": '", token, "' is not a number"));
    }
    if (!std::isfinite(*value)) {
      return LineError(name, line,
                       Str("vertex ", vertex, " has a non-finite coordinate '", token, "'"));
    }
    p[axis] = *value;
  }
  return p;
}

Result<std::int64_t> ParseCount(std::string_view token, std::string_view what,
                                std::string_view name, std::int64_t line) {
  const std::optional<std::int64_t> value = ParseInteger(token);
  if (!value || *value < 0) {
    return LineError(name, line, Str(what, " '", token, "' is not a non-negative integer"));
  }
  return *value;
}

std::string FormatDouble(double value) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof(buffer), value);
  SPARSEDYN_ASSERT(error == std::errc(), "to_chars of a double fits 32 characters");
  return std::string(buffer, end);
}

std::int64_t CountUniqueEdges(const PolygonMesh& mesh) {
  std::set<std::pair<std::int32_t, std::int32_t>> edges;
  for (const std::vector<std::int32_t>& face : mesh.faces) {
    for (std::size_t i = 0; i < face.size(); ++i) {
      const std::int32_t a = face[i];
      const std::int32_t b = face[(i + 1) % face.size()];
      edges.emplace(std::min(a, b), std::max(a, b));
    }
  }
  return static_cast<std::int64_t>(edges.size());
}

Status CheckWritable(const PolygonMesh& mesh) {
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!mesh.vertices[v].allFinite()) {
      return Error{Str("cannot write mesh: vertex ", v, " has a non-finite coordinate")};
    }
  }
  const auto vertex_count = static_cast<std::int64_t>(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<std::int32_t>& face = mesh.faces[f];
    const auto face_index = static_cast<std::int64_t>(f);
    if (face.size() < 3) {
      return Error{Str("cannot write mesh: ",
                       FaceTooSmall(face_index, static_cast<std::int64_t>(face.size())))};
    }
    for (const std::int32_t index : face) {
      if (index < 0 || index >= vertex_count) {
        return Error{Str("cannot write mesh: ", IndexOutOfRange(face_index, index, vertex_count))};
      }
    }
  }
  return Status::Ok();
}

std::string FaceTooSmall(std::int64_t face, std::int64_t size) {
  return Str("face ", face, " has ", size, " vertices; a polygon needs at least 3");
}

std::string IndexOutOfRange(std::int64_t face, std::int64_t index, std::int64_t vertex_count) {
  return Str("face ", face, " has index ", index, " but the file has ", vertex_count, " vertices");
}

std::string IndexZero(std::int64_t face) {
  return Str("face ", face, " has index 0 but indices in this format start at 1");
}

std::string TooManyDeclared(std::string_view what, std::int64_t declared, std::size_t bytes) {
  return Str("declares ", declared, " ", what, ", more than the remaining ", bytes,
             " bytes can hold");
}

std::string EndsEarly(std::string_view what, std::int64_t read, std::int64_t declared) {
  return Str("file ends after ", read, " of ", declared, " declared ", what);
}

}  // namespace sparsedyn::io_detail
