// SPDX-License-Identifier: MIT
// STL, ASCII and binary; see ParseStl in mesh_io.hpp.
#include <Eigen/Geometry>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "io/mesh_parse_support.hpp"
#include "sparsedyn/io/mesh_io.hpp"

namespace sparsedyn {
namespace {

using io_detail::ByteError;
using io_detail::LineError;
using io_detail::Str;

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kCountBytes = 4;
constexpr std::size_t kTriangleBytes = 50;  // normal, three corners (12 float32), uint16

// Collects triangles and welds exactly equal positions, numbering vertices by first use.
class Welder {
 public:
  std::int32_t Add(const Eigen::Vector3d& p) {
    // std::array compares with <, so 0.0 and -0.0 are the same key (NaN never gets here).
    const auto [it, inserted] = index_.emplace(std::array<double, 3>{p.x(), p.y(), p.z()},
                                               static_cast<std::int32_t>(mesh_.vertices.size()));
    if (inserted) mesh_.vertices.push_back(p);
    return it->second;
  }
  void AddTriangle(const std::array<Eigen::Vector3d, 3>& corners) {
    mesh_.faces.push_back({Add(corners[0]), Add(corners[1]), Add(corners[2])});
  }
  PolygonMesh Take() { return std::move(mesh_); }

 private:
  PolygonMesh mesh_;
  std::map<std::array<double, 3>, std::int32_t> index_;
};

std::uint32_t ReadU32Le(std::string_view bytes, std::size_t offset) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    value |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[offset + i])) << (8 * i);
  }
  return value;
}

float ReadF32Le(std::string_view bytes, std::size_t offset) {
  return std::bit_cast<float>(ReadU32Le(bytes, offset));
}

// A file whose size is exactly header + count + 50 * count is binary, whatever its first
// bytes say (some exporters start binary headers with "solid").
bool LooksBinary(std::string_view content) {
  if (content.size() < kHeaderBytes + kCountBytes) return false;
  const std::uint64_t count = ReadU32Le(content, kHeaderBytes);
  return content.size() == kHeaderBytes + kCountBytes + kTriangleBytes * count;
}

bool StartsWithSolid(std::string_view content) {
  const std::size_t first = content.find_first_not_of(" \t\r\n");
  return first != std::string_view::npos && content.substr(first, 5) == "solid";
}

Result<PolygonMesh> ParseBinary(std::string_view content, std::string_view name) {
  if (content.size() < kHeaderBytes + kCountBytes) {
    return ByteError(name, content.size(),
                     Str("binary STL ends inside its 84-byte header (", content.size(), " bytes)"));
  }
  // The count is checked against the size before anything is reserved from it.
  const std::uint64_t count = ReadU32Le(content, kHeaderBytes);
  const std::uint64_t expected = kHeaderBytes + kCountBytes + kTriangleBytes * count;
  if (content.size() != expected) {
    return ByteError(name, kHeaderBytes,
                     Str("binary STL declares ", count, " triangles (", expected,
                         " bytes) but the file has ", content.size(), " bytes"));
  }
  Welder welder;
  for (std::uint64_t t = 0; t < count; ++t) {
    const std::size_t record = kHeaderBytes + kCountBytes + kTriangleBytes * t;
    std::array<Eigen::Vector3d, 3> corners;
    for (std::size_t c = 0; c < 3; ++c) {
      for (std::size_t axis = 0; axis < 3; ++axis) {
        const std::size_t offset = record + 12 + 12 * c + 4 * axis;
        const float value = ReadF32Le(content, offset);
        if (!std::isfinite(value)) {
          return ByteError(name, offset,
                           Str("triangle ", t, " has a non-finite coordinate (", value, ")"));
        }
        corners[c][static_cast<Eigen::Index>(axis)] = value;
      }
    }
    welder.AddTriangle(corners);
  }
  return welder.Take();
}

// ASCII STL is a keyword grammar; it is read token by token with line numbers.
class AsciiStlReader {
 public:
  AsciiStlReader(std::string_view content, std::string_view name) : cursor_(content), name_(name) {}

  Result<PolygonMesh> Parse() {
    if (!NextLine() || tokens_[0] != "solid") return Fail("expected 'solid'");
    std::int64_t facet = 0;
    while (NextLine()) {
      if (tokens_[0] == "endsolid") {
        if (NextLine()) return Fail("unexpected content after 'endsolid'");
        return welder_.Take();
      }
      if (tokens_[0] != "facet") return Fail(Str("expected 'facet' or 'endsolid'"));
      Status read = ReadFacet(facet++);
      if (!read) return read.error();
    }
    return Fail("file ends before 'endsolid'");
  }

 private:
  // "facet normal n n n / outer loop / vertex x y z (x3) / endloop / endfacet".
  Status ReadFacet(std::int64_t facet) {
    if (tokens_.size() != 5 || tokens_[1] != "normal")
      return Fail("expected 'facet normal nx ny nz'");
    if (!NextLine() || tokens_.size() != 2 || tokens_[0] != "outer" || tokens_[1] != "loop") {
      return Fail("expected 'outer loop'");
    }
    std::vector<Eigen::Vector3d> corners;
    while (NextLine() && tokens_[0] == "vertex") {
      if (tokens_.size() != 4) return Fail("expected 'vertex x y z'");
      // A facet is a triangle: a fourth vertex is refused before it is parsed.
      if (corners.size() == 3) return Fail(Str("facet ", facet, " has more than 3 vertices"));
      Result<Eigen::Vector3d> p =
          io_detail::ParsePoint(tokens_, 1, name_, cursor_.line_number(),
                                static_cast<std::int64_t>(3 * facet + corners.size()));
      if (!p) return p.error();
      corners.push_back(*p);
    }
    if (corners.size() < 3) {
      return Fail(io_detail::FaceTooSmall(facet, static_cast<std::int64_t>(corners.size())));
    }
    if (tokens_.empty() || tokens_[0] != "endloop") return Fail("expected 'endloop'");
    if (!NextLine() || tokens_[0] != "endfacet") return Fail("expected 'endfacet'");
    welder_.AddTriangle({corners[0], corners[1], corners[2]});
    return Status::Ok();
  }

  // Next non-blank line, split; false (and no tokens) at the end of the text.
  bool NextLine() {
    std::string_view line;
    while (cursor_.Next(line)) {
      tokens_ = io_detail::SplitTokens(line);
      if (!tokens_.empty()) return true;
    }
    tokens_.clear();
    return false;
  }

  Error Fail(std::string_view what) const { return LineError(name_, cursor_.line_number(), what); }

  io_detail::LineCursor cursor_;
  std::string_view name_;
  std::vector<std::string_view> tokens_;
  Welder welder_;
};

// Outward unit normal of a triangle for the STL record (zero if degenerate).
Eigen::Vector3d TriangleNormal(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double length = n.norm();
  return length > 0.0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
}

// Calls `emit(a, b, c)` for the fan triangulation of every face.
template <typename Emit>
void ForEachFanTriangle(const PolygonMesh& mesh, Emit emit) {
  for (const std::vector<std::int32_t>& face : mesh.faces) {
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      emit(mesh.vertices[static_cast<std::size_t>(face[0])],
           mesh.vertices[static_cast<std::size_t>(face[k])],
           mesh.vertices[static_cast<std::size_t>(face[k + 1])]);
    }
  }
}

void AppendU32Le(std::string& out, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xFFu));
}

}  // namespace

Result<PolygonMesh> ParseStl(std::string_view content, std::string_view name) {
  if (LooksBinary(content) || !StartsWithSolid(content)) return ParseBinary(content, name);
  return AsciiStlReader(content, name).Parse();
}

namespace io_detail {

std::string FormatStlText(const PolygonMesh& mesh) {
  std::string out = "solid sparsedyn\n";
  const auto point = [](const Eigen::Vector3d& p) {
    return FormatDouble(p.x()) + " " + FormatDouble(p.y()) + " " + FormatDouble(p.z());
  };
  ForEachFanTriangle(
      mesh, [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
        out += "  facet normal " + point(TriangleNormal(a, b, c)) + "\n    outer loop\n";
        for (const Eigen::Vector3d* p : {&a, &b, &c}) out += "      vertex " + point(*p) + "\n";
        out += "    endloop\n  endfacet\n";
      });
  out += "endsolid sparsedyn\n";
  return out;
}

std::string FormatStlBinary(const PolygonMesh& mesh) {
  // The header must not start with "solid", or naive readers take the file for ASCII.
  std::string out = "binary STL written by sparsedyn";
  out.resize(kHeaderBytes, ' ');
  const std::size_t count_at = out.size();
  AppendU32Le(out, 0);
  std::uint32_t count = 0;
  ForEachFanTriangle(
      mesh, [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
        for (const Eigen::Vector3d& p : {TriangleNormal(a, b, c), a, b, c}) {
          for (int axis = 0; axis < 3; ++axis) {
            AppendU32Le(out, std::bit_cast<std::uint32_t>(static_cast<float>(p[axis])));
          }
        }
        out.append(2, '\0');  // attribute byte count, unused
        ++count;
      });
  std::string count_bytes;
  AppendU32Le(count_bytes, count);
  out.replace(count_at, kCountBytes, count_bytes);
  return out;
}

}  // namespace io_detail
}  // namespace sparsedyn
