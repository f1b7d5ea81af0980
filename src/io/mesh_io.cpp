// SPDX-License-Identifier: MIT
// Format dispatch and file access for the mesh readers and writers.
#include "sparsedyn/io/mesh_io.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "io/mesh_parse_support.hpp"

namespace sparsedyn {
namespace {

using io_detail::Str;

Result<std::string> ReadFileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{Str(path.string(), ": cannot open: ", std::strerror(errno))};
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return Error{Str(path.string(), ": read error")};
  return bytes;
}

Status WriteFileBytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return Error{Str(path.string(), ": cannot open for writing: ", std::strerror(errno))};
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) return Error{Str(path.string(), ": write failed")};
  return Status::Ok();
}

Result<PolygonMesh> ReadAs(const std::filesystem::path& path, MeshFormat format) {
  Result<std::string> bytes = ReadFileBytes(path);
  if (!bytes) return bytes.error();
  return ParseMesh(*bytes, format, path.string());
}

Status WriteAs(const PolygonMesh& mesh, const std::filesystem::path& path, MeshFormat format,
               MeshEncoding encoding) {
  Result<std::string> text = FormatMesh(mesh, format, encoding);
  if (!text) return Error{Str(path.string(), ": ", text.error().message)};
  return WriteFileBytes(path, *text);
}

}  // namespace

Result<MeshFormat> MeshFormatFromPath(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".off") return MeshFormat::kOff;
  if (extension == ".ohio") return MeshFormat::kOhio;
  if (extension == ".obj") return MeshFormat::kObj;
  if (extension == ".stl") return MeshFormat::kStl;
  if (extension == ".ply") return MeshFormat::kPly;
  return Error{Str(path.string(), ": unknown mesh extension '", extension,
                   "' (expected .off, .ohio, .obj, .stl or .ply)")};
}

Result<PolygonMesh> ReadMesh(const std::filesystem::path& path) {
  Result<MeshFormat> format = MeshFormatFromPath(path);
  if (!format) return format.error();
  return ReadAs(path, *format);
}

Result<PolygonMesh> ReadOff(const std::filesystem::path& path) {
  return ReadAs(path, MeshFormat::kOff);
}
Result<PolygonMesh> ReadOhio(const std::filesystem::path& path) {
  return ReadAs(path, MeshFormat::kOhio);
}
Result<PolygonMesh> ReadObj(const std::filesystem::path& path) {
  return ReadAs(path, MeshFormat::kObj);
}
Result<PolygonMesh> ReadStl(const std::filesystem::path& path) {
  return ReadAs(path, MeshFormat::kStl);
}
Result<PolygonMesh> ReadPly(const std::filesystem::path& path) {
  return ReadAs(path, MeshFormat::kPly);
}

Result<PolygonMesh> ParseMesh(std::string_view content, MeshFormat format, std::string_view name) {
  switch (format) {
    case MeshFormat::kOff:
      return ParseOff(content, name);
    case MeshFormat::kOhio:
      return ParseOhio(content, name);
    case MeshFormat::kObj:
      return ParseObj(content, name);
    case MeshFormat::kStl:
      return ParseStl(content, name);
    case MeshFormat::kPly:
      return ParsePly(content, name);
  }
  return Error{Str(name, ": unknown mesh format")};
}

Result<std::string> FormatMesh(const PolygonMesh& mesh, MeshFormat format, MeshEncoding encoding) {
  Status writable = io_detail::CheckWritable(mesh);
  if (!writable) return writable.error();
  const bool binary = encoding == MeshEncoding::kBinary;
  switch (format) {
    case MeshFormat::kStl:
      return binary ? io_detail::FormatStlBinary(mesh) : io_detail::FormatStlText(mesh);
    case MeshFormat::kPly:
      return io_detail::FormatPlyData(mesh, binary);
    case MeshFormat::kOff:
    case MeshFormat::kOhio:
    case MeshFormat::kObj:
      break;
  }
  if (binary) return Error{"only STL and PLY have a binary encoding"};
  if (format == MeshFormat::kObj) return io_detail::FormatObjText(mesh);
  return io_detail::FormatCounted(mesh, format == MeshFormat::kOhio);
}

Status WriteMesh(const PolygonMesh& mesh, const std::filesystem::path& path,
                 MeshEncoding encoding) {
  Result<MeshFormat> format = MeshFormatFromPath(path);
  if (!format) return format.error();
  return WriteAs(mesh, path, *format, encoding);
}

Status WriteOff(const PolygonMesh& mesh, const std::filesystem::path& path) {
  return WriteAs(mesh, path, MeshFormat::kOff, MeshEncoding::kAscii);
}

Status WriteOhio(const PolygonMesh& mesh, const std::filesystem::path& path) {
  return WriteAs(mesh, path, MeshFormat::kOhio, MeshEncoding::kAscii);
}

}  // namespace sparsedyn
