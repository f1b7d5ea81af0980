// SPDX-License-Identifier: MIT
#include "io/recording_json.hpp"

#include <string>

namespace sparsedyn::recording {
namespace {

using nlohmann::json;

json VectorJson(const Vec3& v) { return json::array({v[0], v[1], v[2]}); }

json ShapeJson(const RecordingShape& shape) {
  if (shape.kind == RecordingShape::Kind::kSphere) {
    return {{"type", "sphere"}, {"radius", shape.radius}};
  }
  json vertices = json::array();
  for (const Vec3& v : shape.mesh.vertices) vertices.push_back(VectorJson(v));
  return {{"type", "polyhedron"}, {"vertices", vertices}, {"faces", shape.mesh.faces}};
}

// Reads the header field by field; the first problem ends the walk with `error` set.
class HeaderReader {
 public:
  explicit HeaderReader(std::string_view name) : name_(name) {}

  const std::string& error() const { return error_; }

  const json* Field(const json& object, const char* key, const std::string& path) {
    if (!error_.empty()) return nullptr;
    const auto it = object.find(key);
    if (it == object.end()) {
      Fail(path + key, "is missing");
      return nullptr;
    }
    return &*it;
  }

  double Number(const json* value, const std::string& path) {
    if (value == nullptr) return 0.0;
    if (!value->is_number()) Fail(path, "must be a number");
    return value->is_number() ? value->get<double>() : 0.0;
  }

  std::uint64_t Count(const json* value, const std::string& path, std::uint64_t max) {
    if (value == nullptr) return 0;
    if (!value->is_number_unsigned() || value->get<std::uint64_t>() > max) {
      Fail(path, "must be an integer in [0, " + std::to_string(max) + "]");
      return 0;
    }
    return value->get<std::uint64_t>();
  }

  Vec3 Vector(const json* value, const std::string& path) {
    Vec3 v = Vec3::Zero();
    if (value == nullptr) return v;
    if (!value->is_array() || value->size() != 3) {
      Fail(path, "must be an array of 3 numbers");
      return v;
    }
    for (std::size_t k = 0; k < 3; ++k) {
      v[static_cast<int>(k)] = Number(&(*value)[k], path + "[" + std::to_string(k) + "]");
    }
    return v;
  }

  void Fail(const std::string& path, const std::string& what) {
    if (error_.empty()) error_ = std::string(name_) + ": header: " + path + " " + what;
  }

 private:
  std::string_view name_;
  std::string error_;
};

RecordingShape ShapeFromJson(const json& value, const std::string& path, HeaderReader& in) {
  RecordingShape shape;
  if (!value.is_object()) {
    in.Fail(path, "must be an object");
    return shape;
  }
  const json* type = in.Field(value, "type", path + ".");
  if (type == nullptr) return shape;
  if (*type == "sphere") {
    shape.radius = in.Number(in.Field(value, "radius", path + "."), path + ".radius");
    return shape;
  }
  if (*type != "polyhedron") {
    in.Fail(path + ".type", "must be \"sphere\" or \"polyhedron\"");
    return shape;
  }
  shape.kind = RecordingShape::Kind::kPolyhedron;
  const json* vertices = in.Field(value, "vertices", path + ".");
  const json* faces = in.Field(value, "faces", path + ".");
  if (vertices == nullptr || faces == nullptr) return shape;
  if (!vertices->is_array() || !faces->is_array()) {
    in.Fail(path, "vertices and faces must be arrays");
    return shape;
  }
  for (std::size_t i = 0; i < vertices->size(); ++i) {
    shape.mesh.vertices.push_back(
        in.Vector(&(*vertices)[i], path + ".vertices[" + std::to_string(i) + "]"));
  }
  for (std::size_t f = 0; f < faces->size(); ++f) {
    const json& face = (*faces)[f];
    const std::string face_path = path + ".faces[" + std::to_string(f) + "]";
    if (!face.is_array() || face.size() < 3) {
      in.Fail(face_path, "must be an array of at least 3 vertex indices");
      return shape;
    }
    std::vector<std::int32_t> loop;
    for (std::size_t k = 0; k < face.size(); ++k) {
      loop.push_back(static_cast<std::int32_t>(
          in.Count(&face[k], face_path + "[" + std::to_string(k) + "]",
                   shape.mesh.vertices.empty() ? 0 : shape.mesh.vertices.size() - 1)));
    }
    shape.mesh.faces.push_back(std::move(loop));
  }
  return shape;
}

}  // namespace

nlohmann::json VectorJsonOf(const Vec3& v) { return VectorJson(v); }

std::string_view ContainerKindName(Container::Kind kind) {
  switch (kind) {
    case Container::Kind::kOpen:
      return "open";
    case Container::Kind::kWalledBox:
      return "walled";
    case Container::Kind::kPeriodicBox:
      return "periodic";
  }
  return "open";
}

nlohmann::json HeaderToJson(const RecordingHeader& header) {
  json shapes = json::array();
  for (const RecordingShape& shape : header.shapes) shapes.push_back(ShapeJson(shape));
  return {
      {"generator", header.generator},
      {"scene", header.scene},
      {"seed", header.seed},
      {"bodies", header.bodies},
      {"container",
       {{"kind", ContainerKindName(header.container.kind)},
        {"lo", VectorJson(header.container.lo)},
        {"hi", VectorJson(header.container.hi)}}},
      {"gravity", VectorJson(header.gravity)},
      {"shapes", shapes},
      {"start_time", header.start_time},
      {"end_time", header.end_time},
  };
}

Result<RecordingHeader> HeaderFromJson(const nlohmann::json& json_header, std::string_view name) {
  HeaderReader in(name);
  RecordingHeader header;
  if (!json_header.is_object()) return Error{std::string(name) + ": header is not a JSON object"};
  if (const auto it = json_header.find("generator"); it != json_header.end() && it->is_string()) {
    header.generator = it->get<std::string>();
  }
  if (const auto it = json_header.find("scene"); it != json_header.end() && it->is_string()) {
    header.scene = it->get<std::string>();
  }
  if (const auto it = json_header.find("seed"); it != json_header.end()) {
    header.seed = in.Count(&*it, "seed", UINT64_MAX);
  }
  header.bodies = static_cast<std::uint32_t>(
      in.Count(in.Field(json_header, "bodies", ""), "bodies", UINT32_MAX));
  if (const json* container = in.Field(json_header, "container", "")) {
    const json* kind = in.Field(*container, "kind", "container.");
    if (kind != nullptr && *kind == "walled") {
      header.container.kind = Container::Kind::kWalledBox;
    } else if (kind != nullptr && *kind == "periodic") {
      header.container.kind = Container::Kind::kPeriodicBox;
    } else if (kind != nullptr && *kind != "open") {
      in.Fail("container.kind", "must be \"open\", \"walled\" or \"periodic\"");
    }
    if (header.container.kind != Container::Kind::kOpen) {
      header.container.lo = in.Vector(in.Field(*container, "lo", "container."), "container.lo");
      header.container.hi = in.Vector(in.Field(*container, "hi", "container."), "container.hi");
    }
  }
  if (const auto it = json_header.find("gravity"); it != json_header.end()) {
    header.gravity = in.Vector(&*it, "gravity");
  }
  if (const json* shapes = in.Field(json_header, "shapes", "")) {
    if (!shapes->is_array()) in.Fail("shapes", "must be an array");
    for (std::size_t s = 0; shapes->is_array() && s < shapes->size(); ++s) {
      header.shapes.push_back(ShapeFromJson((*shapes)[s], "shapes[" + std::to_string(s) + "]", in));
    }
  }
  header.start_time = in.Number(in.Field(json_header, "start_time", ""), "start_time");
  header.end_time = in.Number(in.Field(json_header, "end_time", ""), "end_time");
  if (!in.error().empty()) return Error{in.error()};
  return header;
}

}  // namespace sparsedyn::recording

namespace sparsedyn {

void WriteJsonLines(const Recording& recording, std::ostream& out) {
  using nlohmann::json;
  using recording::VectorJsonOf;
  json header = recording::HeaderToJson(recording.header);
  header["record"] = "header";
  header["version"] = kRecordingVersion;
  out << header.dump() << '\n';
  for (std::size_t i = 0; i < recording.bodies.size(); ++i) {
    const RecordedBody& b = recording.bodies[i];
    out << json{{"record", "body"}, {"index", i},     {"shape", b.shape},
                {"flags", b.flags}, {"mass", b.mass}, {"bounding_radius", b.bounding_radius}}
               .dump()
        << '\n';
  }
  for (const RecordingRecord& record : recording.records) {
    json line;
    if (const auto* s = std::get_if<RecordedSegment>(&record)) {
      const int flags = (s->has_acceleration ? 1 : 0) | (s->has_rotation ? 2 : 0);
      line = {{"record", "segment"},
              {"flags", flags},
              {"body", s->body},
              {"t0", s->t0},
              {"position", VectorJsonOf(s->position)},
              {"velocity", VectorJsonOf(s->velocity)}};
      if (s->has_acceleration) line["acceleration"] = VectorJsonOf(s->acceleration);
      if (s->has_rotation) {
        const Eigen::Quaterniond& q = s->orientation;
        line["orientation"] = json::array({q.w(), q.x(), q.y(), q.z()});
        line["angular_velocity"] = VectorJsonOf(s->angular_velocity);
      }
    } else {
      const auto& c = std::get<RecordedCollision>(record);
      line = {{"record", "collision"},
              {"flags", c.b_is_wall ? 1 : 0},
              {"a", c.a},
              {"b", c.b},
              {"time", c.time},
              {"point", VectorJsonOf(c.point)},
              {"normal", VectorJsonOf(c.normal)},
              {"impulse", c.impulse}};
    }
    out << line.dump() << '\n';
  }
  out << json{{"record", "end"}, {"end_time", recording.end_time}}.dump() << '\n';
}

}  // namespace sparsedyn
