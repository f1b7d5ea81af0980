// SPDX-License-Identifier: MIT
// Stanford PLY 1.0 (ascii, binary_little_endian, binary_big_endian); see ParsePly.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
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

enum class PlyType { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };
enum class PlyEncoding { kAscii, kBinaryLittle, kBinaryBig };

struct PlyTypeInfo {
  std::string_view names[2];  // PLY 1.0 name and the sized alias
  PlyType type;
  std::size_t bytes;
  bool is_integer;
  double min;
  double max;
};

constexpr std::array<PlyTypeInfo, 8> kTypes = {{
    {{"char", "int8"}, PlyType::kInt8, 1, true, -128.0, 127.0},
    {{"uchar", "uint8"}, PlyType::kUint8, 1, true, 0.0, 255.0},
    {{"short", "int16"}, PlyType::kInt16, 2, true, -32768.0, 32767.0},
    {{"ushort", "uint16"}, PlyType::kUint16, 2, true, 0.0, 65535.0},
    {{"int", "int32"}, PlyType::kInt32, 4, true, -2147483648.0, 2147483647.0},
    {{"uint", "uint32"}, PlyType::kUint32, 4, true, 0.0, 4294967295.0},
    {{"float", "float32"}, PlyType::kFloat32, 4, false, 0.0, 0.0},
    {{"double", "float64"}, PlyType::kFloat64, 8, false, 0.0, 0.0},
}};

const PlyTypeInfo& Info(PlyType type) { return kTypes[static_cast<std::size_t>(type)]; }

std::optional<PlyType> TypeFromName(std::string_view name) {
  for (const PlyTypeInfo& info : kTypes) {
    if (name == info.names[0] || name == info.names[1]) return info.type;
  }
  return std::nullopt;
}

struct PlyProperty {
  std::string_view name;
  PlyType type = PlyType::kFloat32;  // the value type (of the entries, for a list)
  std::optional<PlyType> list_count_type;
};

struct PlyElement {
  std::string_view name;
  std::int64_t count = 0;
  std::int64_t header_line = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::kAscii;
  std::vector<PlyElement> elements;
  std::size_t data_offset = 0;  // first byte after "end_header\n"
  std::int64_t end_line = 0;    // line number of "end_header"
};

// Adds a "property" line to the last element.
Status ParseProperty(const std::vector<std::string_view>& tokens, PlyHeader& header,
                     std::string_view name, std::int64_t line) {
  if (header.elements.empty()) return LineError(name, line, "property before any element");
  PlyProperty property;
  const bool is_list = tokens.size() == 5 && tokens[1] == "list";
  if (!is_list && tokens.size() != 3) {
    return LineError(name, line, "expected 'property TYPE NAME' or 'property list T T NAME'");
  }
  const std::size_t type_at = is_list ? 3 : 1;
  const std::optional<PlyType> type = TypeFromName(tokens[type_at]);
  if (!type) return LineError(name, line, Str("unknown PLY type '", tokens[type_at], "'"));
  property.type = *type;
  if (is_list) {
    property.list_count_type = TypeFromName(tokens[2]);
    if (!property.list_count_type || !Info(*property.list_count_type).is_integer) {
      return LineError(name, line, Str("list count type '", tokens[2], "' is not an integer type"));
    }
  }
  property.name = tokens.back();
  header.elements.back().properties.push_back(property);
  return Status::Ok();
}

Result<PlyHeader> ParseHeader(std::string_view content, std::string_view name) {
  io_detail::LineCursor cursor(content);
  std::string_view line;
  if (!cursor.Next(line) || line != "ply") return LineError(name, 1, "expected 'ply'");
  PlyHeader header;
  bool has_format = false;
  while (cursor.Next(line)) {
    const std::int64_t n = cursor.line_number();
    const std::vector<std::string_view> tokens = io_detail::SplitTokens(line);
    if (tokens.empty() || tokens[0] == "comment" || tokens[0] == "obj_info") continue;
    if (tokens[0] == "end_header") {
      if (!has_format) return LineError(name, n, "no 'format' line before 'end_header'");
      header.data_offset = content.size() - cursor.remaining_bytes();
      header.end_line = n;
      return header;
    }
    if (tokens[0] == "format") {
      if (tokens.size() != 3 || tokens[2] != "1.0") {
        return LineError(name, n, "expected 'format ENCODING 1.0'");
      }
      if (tokens[1] == "ascii") {
        header.encoding = PlyEncoding::kAscii;
      } else if (tokens[1] == "binary_little_endian") {
        header.encoding = PlyEncoding::kBinaryLittle;
      } else if (tokens[1] == "binary_big_endian") {
        header.encoding = PlyEncoding::kBinaryBig;
      } else {
        return LineError(name, n, Str("unknown PLY encoding '", tokens[1], "'"));
      }
      has_format = true;
    } else if (tokens[0] == "element") {
      if (tokens.size() != 3) return LineError(name, n, "expected 'element NAME COUNT'");
      Result<std::int64_t> count =
          io_detail::ParseCount(tokens[2], Str("element '", tokens[1], "' count"), name, n);
      if (!count) return count.error();
      header.elements.push_back(
          {.name = tokens[1], .count = *count, .header_line = n, .properties = {}});
    } else if (tokens[0] == "property") {
      Status added = ParseProperty(tokens, header, name, n);
      if (!added) return added.error();
    } else {
      return LineError(name, n, Str("unknown PLY header keyword '", tokens[0], "'"));
    }
  }
  return LineError(name, cursor.line_number(), "file ends before 'end_header'");
}

// The fewest bytes one record of `element` can take: every scalar and list count present
// (lists empty); in ASCII, one digit and one separator per value.
std::size_t MinRecordBytes(const PlyElement& element, PlyEncoding encoding) {
  std::size_t bytes = 0;
  for (const PlyProperty& property : element.properties) {
    if (encoding == PlyEncoding::kAscii) {
      bytes += 2;
    } else {
      bytes += Info(property.list_count_type.value_or(property.type)).bytes;
    }
  }
  return bytes;
}

// Declared counts must fit the bytes after the header, checked before anything is reserved:
// a 100-byte file that declares 2^31 vertices fails here.
Status CheckCounts(const PlyHeader& header, std::size_t data_bytes, std::string_view name) {
  // ASCII: the last value may lack its separator.
  std::uint64_t budget = data_bytes + (header.encoding == PlyEncoding::kAscii ? 1 : 0);
  for (const PlyElement& element : header.elements) {
    const std::size_t min_bytes = MinRecordBytes(element, header.encoding);
    if (min_bytes == 0) {
      return LineError(name, element.header_line,
                       Str("element '", element.name, "' has no properties"));
    }
    const auto count = static_cast<std::uint64_t>(element.count);
    if (count > budget / min_bytes) {
      return LineError(name, element.header_line,
                       io_detail::TooManyDeclared(Str("'", element.name, "' records"),
                                                  element.count, data_bytes));
    }
    budget -= count * min_bytes;
  }
  return Status::Ok();
}

// Reads PLY values from ASCII text: whitespace-separated tokens, records may span lines.
class AsciiValues {
 public:
  AsciiValues(std::string_view data, std::int64_t first_line, std::string_view name)
      : cursor_(data), line_offset_(first_line), name_(name) {}

  Result<double> Read(PlyType type) {
    if (!FillTokens()) return Fail("file ends inside the data");
    const std::string_view token = tokens_[next_++];
    if (Info(type).is_integer) {
      const std::optional<std::int64_t> value = io_detail::ParseInteger(token);
      const auto as_double = static_cast<double>(value.value_or(0));
      if (!value || as_double < Info(type).min || as_double > Info(type).max) {
        return Fail(Str("'", token, "' is not a ", Info(type).names[0]));
      }
      return as_double;
    }
    const std::optional<double> value = io_detail::ParseDouble(token);
    if (!value) return Fail(Str("'", token, "' is not a number"));
    last_token_ = token;
    return *value;
  }

  // Upper bound on the values left, to cap a reserve() from a declared list length.
  std::size_t MaxValuesLeft() const { return cursor_.remaining_bytes() / 2 + tokens_.size(); }

  std::string_view last_token() const { return last_token_; }

  Status ExpectEnd() {
    if (FillTokens()) return Fail("unexpected data after the last element");
    return Status::Ok();
  }

  Error Fail(std::string_view what) const {
    return LineError(name_, line_offset_ + cursor_.line_number(), what);
  }

 private:
  bool FillTokens() {
    std::string_view line;
    while (next_ == tokens_.size()) {
      if (!cursor_.Next(line)) return false;
      tokens_ = io_detail::SplitTokens(line);
      next_ = 0;
    }
    return true;
  }

  io_detail::LineCursor cursor_;
  std::int64_t line_offset_;
  std::string_view name_;
  std::vector<std::string_view> tokens_;
  std::size_t next_ = 0;
  std::string_view last_token_;
};

// Reads PLY values from binary data of either byte order, with byte offsets for errors.
class BinaryValues {
 public:
  BinaryValues(std::string_view content, std::size_t offset, bool big_endian, std::string_view name)
      : content_(content), offset_(offset), big_endian_(big_endian), name_(name) {}

  Result<double> Read(PlyType type) {
    const std::size_t size = Info(type).bytes;
    if (content_.size() - offset_ < size) return Fail("file ends inside the data");
    std::uint64_t bits = 0;
    for (std::size_t i = 0; i < size; ++i) {
      const std::size_t at = big_endian_ ? i : size - 1 - i;
      bits = (bits << 8) | static_cast<unsigned char>(content_[offset_ + at]);
    }
    value_offset_ = offset_;
    offset_ += size;
    return Decode(type, bits);
  }

  std::size_t MaxValuesLeft() const { return content_.size() - offset_; }

  Status ExpectEnd() const {
    if (offset_ != content_.size()) {
      return Fail(Str(content_.size() - offset_, " bytes of data after the last element"));
    }
    return Status::Ok();
  }

  // Errors about a value point at its first byte.
  Error Fail(std::string_view what) const { return ByteError(name_, value_offset_, what); }

 private:
  static double Decode(PlyType type, std::uint64_t bits) {
    switch (type) {
      case PlyType::kInt8:
        return static_cast<std::int8_t>(bits);
      case PlyType::kUint8:
        return static_cast<std::uint8_t>(bits);
      case PlyType::kInt16:
        return static_cast<std::int16_t>(bits);
      case PlyType::kUint16:
        return static_cast<std::uint16_t>(bits);
      case PlyType::kInt32:
        return static_cast<std::int32_t>(bits);
      case PlyType::kUint32:
        return static_cast<std::uint32_t>(bits);
      case PlyType::kFloat32:
        return std::bit_cast<float>(static_cast<std::uint32_t>(bits));
      case PlyType::kFloat64:
        return std::bit_cast<double>(bits);
    }
    return 0.0;
  }

  std::string_view content_;
  std::size_t offset_;
  std::size_t value_offset_ = 0;
  bool big_endian_;
  std::string_view name_;
};

// Where x, y, z and the face indices live in the records.
struct MeshLayout {
  std::int64_t vertex_count = 0;
  std::array<std::optional<std::size_t>, 3> xyz;  // property positions in "vertex"
  std::optional<std::size_t> indices;             // property position in "face"
};

Result<MeshLayout> FindLayout(const PlyHeader& header, std::string_view name) {
  MeshLayout layout;
  bool has_vertex = false;
  for (const PlyElement& element : header.elements) {
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty& property = element.properties[p];
      if (element.name == "vertex" && !property.list_count_type) {
        for (std::size_t axis = 0; axis < 3; ++axis) {
          if (property.name == std::string_view(&"xyz"[axis], 1)) layout.xyz[axis] = p;
        }
      }
      if (element.name == "face" && property.list_count_type &&
          (property.name == "vertex_indices" || property.name == "vertex_index")) {
        if (!Info(property.type).is_integer) {
          return LineError(name, element.header_line, "face indices must have an integer type");
        }
        layout.indices = p;
      }
    }
    if (element.name == "vertex") {
      has_vertex = true;
      layout.vertex_count = element.count;
      if (!layout.xyz[0] || !layout.xyz[1] || !layout.xyz[2]) {
        return LineError(name, element.header_line, "element 'vertex' lacks x, y or z");
      }
    }
    if (element.name == "face" && !layout.indices) {
      return LineError(name, element.header_line, "element 'face' lacks 'vertex_indices'");
    }
  }
  if (!has_vertex) return LineError(name, header.end_line, "no element 'vertex'");
  return layout;
}

// One face list: count, then that many indices checked against the vertex count.
template <typename Values>
Result<std::vector<std::int32_t>> ReadFace(Values& values, const PlyProperty& property,
                                           std::int64_t face, std::int64_t vertex_count) {
  Result<double> size = values.Read(*property.list_count_type);
  if (!size) return size.error();
  const auto n = static_cast<std::int64_t>(*size);
  if (n < 3) return values.Fail(io_detail::FaceTooSmall(face, n));
  std::vector<std::int32_t> indices;
  indices.reserve(std::min(static_cast<std::size_t>(n), values.MaxValuesLeft()));
  for (std::int64_t k = 0; k < n; ++k) {
    Result<double> index = values.Read(property.type);
    if (!index) return index.error();
    if (*index < 0.0 || *index >= static_cast<double>(vertex_count)) {
      return values.Fail(
          io_detail::IndexOutOfRange(face, static_cast<std::int64_t>(*index), vertex_count));
    }
    indices.push_back(static_cast<std::int32_t>(*index));
  }
  return indices;
}

// Reads every element's records, keeping vertex positions and face index lists.
template <typename Values>
Result<PolygonMesh> ReadData(Values& values, const PlyHeader& header, const MeshLayout& layout) {
  PolygonMesh mesh;
  for (const PlyElement& element : header.elements) {
    const bool is_vertex = element.name == "vertex";
    const bool is_face = element.name == "face";
    // CheckCounts bounded these counts by the file size.
    if (is_vertex) mesh.vertices.reserve(static_cast<std::size_t>(element.count));
    if (is_face) mesh.faces.reserve(static_cast<std::size_t>(element.count));
    for (std::int64_t r = 0; r < element.count; ++r) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const PlyProperty& property = element.properties[k];
        if (is_face && k == layout.indices) {
          Result<std::vector<std::int32_t>> face = ReadFace(
              values, property, static_cast<std::int64_t>(mesh.faces.size()), layout.vertex_count);
          if (!face) return face.error();
          mesh.faces.push_back(std::move(*face));
          continue;
        }
        // Other lists are skipped entry by entry; their length is read, not trusted.
        std::int64_t entries = 1;
        if (property.list_count_type) {
          Result<double> n = values.Read(*property.list_count_type);
          if (!n) return n.error();
          entries = static_cast<std::int64_t>(*n);
        }
        for (std::int64_t e = 0; e < entries; ++e) {
          Result<double> value = values.Read(property.type);
          if (!value) return value.error();
          for (std::size_t axis = 0; axis < 3; ++axis) {
            if (!is_vertex || k != layout.xyz[axis]) continue;
            if (!std::isfinite(*value)) {
              return values.Fail(Str("vertex ", r, " has a non-finite coordinate '", *value, "'"));
            }
            p[static_cast<Eigen::Index>(axis)] = *value;
          }
        }
      }
      if (is_vertex) mesh.vertices.push_back(p);
    }
  }
  Status end = values.ExpectEnd();
  if (!end) return end.error();
  return mesh;
}

}  // namespace

Result<PolygonMesh> ParsePly(std::string_view content, std::string_view name) {
  Result<PlyHeader> header = ParseHeader(content, name);
  if (!header) return header.error();
  Status counts = CheckCounts(*header, content.size() - header->data_offset, name);
  if (!counts) return counts.error();
  Result<MeshLayout> layout = FindLayout(*header, name);
  if (!layout) return layout.error();

  if (header->encoding == PlyEncoding::kAscii) {
    AsciiValues values(content.substr(header->data_offset), header->end_line, name);
    return ReadData(values, *header, *layout);
  }
  BinaryValues values(content, header->data_offset, header->encoding == PlyEncoding::kBinaryBig,
                      name);
  return ReadData(values, *header, *layout);
}

namespace io_detail {

namespace {
template <typename Unsigned>
void AppendLe(std::string& out, Unsigned bits) {
  for (std::size_t i = 0; i < sizeof(Unsigned); ++i) {
    out.push_back(static_cast<char>((bits >> (8 * i)) & 0xFFu));
  }
}
}  // namespace

std::string FormatPlyData(const PolygonMesh& mesh, bool binary) {
  // A uchar list length is what most tools expect; wider faces need a wider count.
  std::size_t widest = 0;
  for (const std::vector<std::int32_t>& face : mesh.faces) widest = std::max(widest, face.size());
  const bool wide = widest > 255;
  std::string out = Str("ply\nformat ", binary ? "binary_little_endian" : "ascii",
                        " 1.0\ncomment written by sparsedyn\nelement vertex ", mesh.vertices.size(),
                        "\nproperty double x\nproperty double y\nproperty double z\n"
                        "element face ",
                        mesh.faces.size(), "\nproperty list ", wide ? "uint" : "uchar",
                        " int vertex_indices\nend_header\n");
  for (const Eigen::Vector3d& p : mesh.vertices) {
    if (binary) {
      for (int axis = 0; axis < 3; ++axis) AppendLe(out, std::bit_cast<std::uint64_t>(p[axis]));
    } else {
      out += FormatDouble(p.x()) + " " + FormatDouble(p.y()) + " " + FormatDouble(p.z()) + "\n";
    }
  }
  for (const std::vector<std::int32_t>& face : mesh.faces) {
    if (binary) {
      if (wide) {
        AppendLe(out, static_cast<std::uint32_t>(face.size()));
      } else {
        AppendLe(out, static_cast<std::uint8_t>(face.size()));
      }
      for (const std::int32_t index : face) AppendLe(out, static_cast<std::uint32_t>(index));
    } else {
      out += std::to_string(face.size());
      for (const std::int32_t index : face) (out += ' ') += std::to_string(index);
      out += "\n";
    }
  }
  return out;
}

}  // namespace io_detail
}  // namespace sparsedyn
