// SPDX-License-Identifier: MIT
// Scene files (docs/scene-format.md): strict parsing into a SceneDescription.
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "io/json_checker.hpp"
#include "io/scene_shapes.hpp"
#include "sparsedyn/io/scene_file.hpp"

namespace sparsedyn {

using json_input::Checker;
using json_input::Index;
using json_input::Key;
using nlohmann::json;

namespace {

// A unit quaternion is accepted within this relative error of norm 1 and then normalised:
// files written with ~9 digits stay valid, a typo (e.g. [1, 1, 0, 0]) does not.
constexpr double kQuaternionNormTolerance = 1e-6;
// Upper bound on bodies in one file (the World's indices are 32-bit).
constexpr std::uint64_t kMaxBodies = 100000000;
// Upper bound on times in a file (start, duration, thrust changes), s: far beyond any run, and
// small enough that the clock still resolves events there (CheckClockResolution).
constexpr double kMaxTime = 1e12;
// Upper bound on drag coefficients (1/s, 1/m), the World's bound on magnitudes.
constexpr double kMaxDrag = 1e100;

// "line L, column C" of a byte offset, for JSON syntax errors.
std::string LineColumn(std::string_view text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

class SceneParser {
 public:
  SceneParser(std::string_view name, std::filesystem::path base_dir)
      : checker_(std::string(name)), base_dir_(std::move(base_dir)) {}

  Result<SceneDescription> Parse(const json& root) {
    if (checker_.Object(root, "",
                        {"name", "description", "seed", "packing", "start_time", "duration",
                         "gravity", "drag", "broadphase", "grid_cells_per_body",
                         "stall_event_limit", "container", "tolerances", "bodies"})) {
      ParseTopLevel(root);
    }
    if (!checker_.ok()) return checker_.ToError();
    return std::move(scene_);
  }

 private:
  void ParseTopLevel(const json& root) {
    if (root.contains("name")) {
      if (auto s = checker_.String(root["name"], "name")) scene_.name = *s;
    }
    if (root.contains("description")) checker_.String(root["description"], "description");
    if (root.contains("seed")) {
      if (auto s = checker_.Unsigned(root["seed"], "seed", UINT64_MAX)) scene_.seed = *s;
    }
    if (root.contains("packing")) {
      scene_.packing = checker_.NumberIn(root["packing"], "packing", 0, 1, true);
    }
    WorldSettings& settings = scene_.settings;
    // Read before the bodies: their thrust schedules may not start before it.
    if (root.contains("start_time")) {
      if (auto t = checker_.NumberIn(root["start_time"], "start_time", 0, kMaxTime)) {
        settings.start_time = *t;
      }
    }
    if (root.contains("duration")) {
      if (auto d = checker_.NumberIn(root["duration"], "duration", 0, kMaxTime))
        scene_.duration = *d;
    }
    if (root.contains("gravity")) {
      if (auto g = checker_.Vector(root["gravity"], "gravity")) settings.gravity = *g;
    }
    if (root.contains("drag")) {
      if (std::optional<Drag> drag = ParseDrag(root["drag"], "drag")) settings.drag = *drag;
    }
    if (root.contains("broadphase")) ParseBroadphase(root["broadphase"]);
    if (root.contains("grid_cells_per_body")) {
      if (auto c =
              checker_.NumberIn(root["grid_cells_per_body"], "grid_cells_per_body", 0, 1e6, true)) {
        settings.grid_cells_per_body = *c;
      }
    }
    if (root.contains("stall_event_limit")) {
      const auto limit =
          checker_.Unsigned(root["stall_event_limit"], "stall_event_limit", UINT64_MAX);
      if (limit && *limit == 0) checker_.Fail("stall_event_limit", "must be at least 1");
      if (limit && *limit > 0) settings.stall_event_limit = *limit;
    }
    if (root.contains("container")) ParseContainer(root["container"]);
    if (root.contains("tolerances")) ParseTolerances(root["tolerances"]);
    if (!root.contains("bodies")) {
      checker_.Fail("bodies", "is missing (a scene needs at least one body)");
      return;
    }
    ParseBodies(root["bodies"]);
  }

  void ParseBroadphase(const json& value) {
    const std::optional<std::string> name = checker_.String(value, "broadphase");
    if (!name) return;
    if (*name == "grid") {
      scene_.settings.broadphase = Broadphase::kGrid;
    } else if (*name == "allpairs") {
      scene_.settings.broadphase = Broadphase::kAllPairs;
    } else if (*name == "hextree") {
      checker_.Fail("broadphase", "\"hextree\" is not available yet (use grid or allpairs)");
    } else {
      checker_.Fail("broadphase", "must be \"grid\" or \"allpairs\", got " + value.dump());
    }
  }

  // {"linear": c1, "quadratic": c2}: each finite and >= 0, a missing one 0.
  std::optional<Drag> ParseDrag(const json& value, const std::string& path) {
    if (!checker_.Object(value, path, {"linear", "quadratic"})) return std::nullopt;
    Drag drag;
    bool ok = true;
    for (const auto& [key, out] : {std::pair<const char*, double*>{"linear", &drag.linear},
                                   std::pair<const char*, double*>{"quadratic", &drag.quadratic}}) {
      if (!value.contains(key)) continue;
      const std::optional<double> c = checker_.NumberIn(value[key], Key(path, key), 0, kMaxDrag);
      if (c) {
        *out = *c;
      } else {
        ok = false;
      }
    }
    if (!ok) return std::nullopt;
    return drag;
  }

  void ParseContainer(const json& value) {
    if (!checker_.Object(value, "container", {"kind", "lo", "hi"})) return;
    if (!value.contains("kind")) {
      checker_.Fail("container.kind", "is missing (open, walled or periodic)");
      return;
    }
    const std::optional<std::string> kind = checker_.String(value["kind"], "container.kind");
    if (!kind) return;
    Container& container = scene_.settings.container;
    if (*kind == "open") {
      for (const char* key : {"lo", "hi"}) {
        if (value.contains(key)) {
          checker_.Fail(Key("container", key), "an open container has no bounds");
        }
      }
      container = Container::Open();
      return;
    }
    if (*kind != "walled" && *kind != "periodic") {
      checker_.Fail("container.kind",
                    "must be \"open\", \"walled\" or \"periodic\", got " + value["kind"].dump());
      return;
    }
    std::optional<Vec3> lo, hi;
    for (const char* key : {"lo", "hi"}) {
      if (!value.contains(key)) checker_.Fail(Key("container", key), "is missing");
    }
    if (value.contains("lo")) lo = checker_.Vector(value["lo"], "container.lo");
    if (value.contains("hi")) hi = checker_.Vector(value["hi"], "container.hi");
    if (!lo || !hi) return;
    for (int k = 0; k < 3; ++k) {
      if (!((*hi)[k] > (*lo)[k])) {
        checker_.Fail(Index("container.hi", static_cast<std::size_t>(k)),
                      "must be greater than container.lo[" + std::to_string(k) + "]");
      }
    }
    container =
        *kind == "walled" ? Container::WalledBox(*lo, *hi) : Container::PeriodicBox(*lo, *hi);
  }

  void ParseTolerances(const json& value) {
    if (!checker_.Object(value, "tolerances", {"contact", "elastic_below_speed"})) return;
    if (value.contains("contact")) {
      if (auto c = checker_.NumberIn(value["contact"], "tolerances.contact", 0, 0.1)) {
        scene_.settings.contact_tolerance = *c;
      }
    }
    if (value.contains("elastic_below_speed")) {
      if (auto s = checker_.NumberIn(value["elastic_below_speed"], "tolerances.elastic_below_speed",
                                     0, kInfinity)) {
        scene_.settings.elastic_below_speed = *s;
      }
    }
  }

  void ParseBodies(const json& value) {
    if (!value.is_array() || value.empty()) {
      checker_.Fail("bodies", "must be a non-empty array of bodies, got " +
                                  (value.is_array() ? std::string("an empty array")
                                                    : json_input::Describe(value)));
      return;
    }
    if (value.size() > kMaxBodies) {
      checker_.Fail("bodies", "has " + std::to_string(value.size()) + " bodies, more than " +
                                  std::to_string(kMaxBodies));
      return;
    }
    scene_.bodies.reserve(value.size());
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (checker_.ErrorCount() >= Checker::kMaxErrors) return;
      ParseBody(value[i], Index("bodies", i));
    }
  }

  void ParseBody(const json& value, const std::string& path) {
    if (!checker_.Object(
            value, path,
            {"shape", "position", "orientation", "velocity", "angular_velocity", "thrust",
             "thrust_schedule", "mass", "density", "restitution", "friction", "drag", "static",
             "god"})) {
      return;
    }
    SceneBody body;
    if (!value.contains("shape")) {
      checker_.Fail(Key(path, "shape"), "is missing");
    } else if (auto shape = ShapeIndex(value["shape"], Key(path, "shape"))) {
      body.shape = *shape;
    }
    auto vector = [&](const char* key, Vec3& out) {
      if (!value.contains(key)) return;
      if (auto v = checker_.Vector(value[key], Key(path, key))) out = *v;
    };
    vector("position", body.position);
    vector("velocity", body.velocity);
    vector("angular_velocity", body.angular_velocity);
    vector("thrust", body.thrust);
    if (value.contains("orientation")) ParseOrientation(value["orientation"], path, body);
    if (value.contains("static")) {
      if (value["static"].is_boolean()) {
        body.is_static = value["static"].get<bool>();
      } else {
        checker_.Fail(Key(path, "static"), "must be true or false");
      }
    }
    if (value.contains("thrust_schedule")) {
      ParseThrustSchedule(value["thrust_schedule"], Key(path, "thrust_schedule"), body);
    }
    if (value.contains("god")) ParseGod(value["god"], Key(path, "god"), body);
    if (value.contains("drag")) body.drag = ParseDrag(value["drag"], Key(path, "drag"));
    ParseMass(value, path, body);
    if (value.contains("restitution")) {
      if (auto e = checker_.NumberIn(value["restitution"], Key(path, "restitution"), 0, 1)) {
        body.restitution = *e;
      }
    }
    if (value.contains("friction")) {
      if (auto f = checker_.NumberIn(value["friction"], Key(path, "friction"), 0, kInfinity)) {
        body.friction = *f;
      }
    }
    scene_.bodies.push_back(body);
  }

  void ParseOrientation(const json& value, const std::string& path, SceneBody& body) {
    const std::string at = Key(path, "orientation");
    if (!value.is_array() || value.size() != 4) {
      checker_.Fail(at, "must be a quaternion [w, x, y, z], got " + json_input::Describe(value));
      return;
    }
    double q[4];
    for (std::size_t k = 0; k < 4; ++k) {
      const std::optional<double> c = checker_.Number(value[k], Index(at, k));
      if (!c) return;
      q[k] = *c;
    }
    Eigen::Quaterniond quaternion(q[0], q[1], q[2], q[3]);
    if (std::abs(quaternion.norm() - 1) > kQuaternionNormTolerance) {
      checker_.Fail(at, "must be a unit quaternion [w, x, y, z], its norm is " +
                            json_input::FormatNumber(quaternion.norm()));
      return;
    }
    body.orientation = quaternion.norm() == 1.0 ? quaternion : quaternion.normalized();
  }

  // [{"time": t, "thrust": [x, y, z]}, ...]: times strictly increasing, none before the start.
  void ParseThrustSchedule(const json& value, const std::string& at, SceneBody& body) {
    if (!value.is_array()) {
      checker_.Fail(at, "must be an array of {\"time\": t, \"thrust\": [x, y, z]}, got " +
                            json_input::Describe(value));
      return;
    }
    const double start = scene_.settings.start_time;
    std::optional<double> previous;
    for (std::size_t k = 0; k < value.size(); ++k) {
      const std::string entry = Index(at, k);
      if (!checker_.Object(value[k], entry, {"time", "thrust"})) return;
      for (const char* key : {"time", "thrust"}) {
        if (!value[k].contains(key)) checker_.Fail(Key(entry, key), "is missing");
      }
      if (!value[k].contains("time") || !value[k].contains("thrust")) return;
      const std::optional<double> time =
          checker_.NumberIn(value[k]["time"], Key(entry, "time"), 0, kMaxTime);
      const std::optional<Vec3> thrust = checker_.Vector(value[k]["thrust"], Key(entry, "thrust"));
      if (!time || !thrust) return;
      if (*time < start) {
        checker_.Fail(Key(entry, "time"), "must not be before start_time (" +
                                              json_input::FormatNumber(start) + "), got " +
                                              json_input::FormatNumber(*time));
        return;
      }
      if (previous && !(*time > *previous)) {
        checker_.Fail(Key(entry, "time"), "must be later than " + Index(at, k - 1) + ".time (" +
                                              json_input::FormatNumber(*previous) + "), got " +
                                              json_input::FormatNumber(*time));
        return;
      }
      previous = time;
      body.thrust_schedule.push_back(ThrustChange{*time, *thrust});
    }
  }

  // {"max_acceleration": A, "track": [{"time": t, "position": [x, y, z], "velocity": [...]}]}:
  // A > 0, times strictly increasing and not before the start.
  void ParseGod(const json& value, const std::string& at, SceneBody& body) {
    if (!checker_.Object(value, at, {"max_acceleration", "track"})) return;
    GodDef god;
    if (!value.contains("max_acceleration")) {
      checker_.Fail(Key(at, "max_acceleration"), "is missing");
      return;
    }
    const std::optional<double> a = checker_.NumberIn(value["max_acceleration"],
                                                      Key(at, "max_acceleration"), 0, kMaxTime,
                                                      /*lo_open=*/true);
    if (!a) return;
    god.max_acceleration = *a;
    const std::string track = Key(at, "track");
    if (!value.contains("track")) {
      checker_.Fail(track, "is missing");
      return;
    }
    if (!value["track"].is_array()) {
      checker_.Fail(track, "must be an array of {\"time\": t, \"position\": [x, y, z]}, got " +
                               json_input::Describe(value["track"]));
      return;
    }
    const json& entries = value["track"];
    for (std::size_t k = 0; k < entries.size(); ++k) {
      const std::string entry = Index(track, k);
      if (!checker_.Object(entries[k], entry, {"time", "position", "velocity"})) return;
      for (const char* key : {"time", "position"}) {
        if (!entries[k].contains(key)) checker_.Fail(Key(entry, key), "is missing");
      }
      if (!entries[k].contains("time") || !entries[k].contains("position")) return;
      const std::optional<double> time =
          checker_.NumberIn(entries[k]["time"], Key(entry, "time"), 0, kMaxTime);
      const std::optional<Vec3> position =
          checker_.Vector(entries[k]["position"], Key(entry, "position"));
      if (!time || !position) return;
      GodTarget target{*time, *position, std::nullopt};
      if (entries[k].contains("velocity")) {
        const std::optional<Vec3> v = checker_.Vector(entries[k]["velocity"], Key(entry, "velocity"));
        if (!v) return;
        target.velocity = *v;
      }
      if (*time < scene_.settings.start_time) {
        checker_.Fail(Key(entry, "time"), "must not be before start_time (" +
                                              json_input::FormatNumber(scene_.settings.start_time) +
                                              "), got " + json_input::FormatNumber(*time));
        return;
      }
      if (k > 0 && !(*time > god.track.back().time)) {
        checker_.Fail(Key(entry, "time"), "must be later than " + Index(track, k - 1) +
                                              ".time (" +
                                              json_input::FormatNumber(god.track.back().time) +
                                              "), got " + json_input::FormatNumber(*time));
        return;
      }
      god.track.push_back(target);
    }
    body.god = std::move(god);
  }

  // "mass" or "density" (not both); neither means 1 kg.
  void ParseMass(const json& value, const std::string& path, SceneBody& body) {
    if (value.contains("mass") && value.contains("density")) {
      checker_.Fail(path, "give \"mass\" or \"density\", not both");
      return;
    }
    if (value.contains("mass")) {
      if (auto m = checker_.NumberIn(value["mass"], Key(path, "mass"), 0, kInfinity, true)) {
        body.mass = *m;
      }
    }
    if (value.contains("density")) {
      body.density = checker_.NumberIn(value["density"], Key(path, "density"), 0, kInfinity, true);
      if (body.density && body.shape < scene_.shapes.size() && value.contains("shape")) {
        body.mass = *body.density * scene_.shapes[body.shape].Volume();
      }
    }
  }

  // The index of the body's shape in scene_.shapes, built once per distinct spec.
  std::optional<std::uint32_t> ShapeIndex(const json& value, const std::string& path) {
    std::optional<json> spec = json_input::CanonicalShapeSpec(value, path, scene_.seed, checker_);
    if (!spec) return std::nullopt;
    const std::string key = spec->dump();
    if (const auto it = shape_of_spec_.find(key); it != shape_of_spec_.end()) return it->second;
    std::optional<SceneShape> shape = json_input::BuildShape(*spec, path, base_dir_, checker_);
    if (!shape) return std::nullopt;
    const std::uint32_t index = scene_.AddShape(std::move(*shape));
    shape_of_spec_.emplace(key, index);
    return index;
  }

  Checker checker_;
  std::filesystem::path base_dir_;
  SceneDescription scene_;
  std::map<std::string, std::uint32_t> shape_of_spec_;
};

}  // namespace

std::uint32_t SceneDescription::AddShape(SceneShape shape) {
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    if (shapes[i].spec == shape.spec) return static_cast<std::uint32_t>(i);
  }
  shapes.push_back(std::move(shape));
  return static_cast<std::uint32_t>(shapes.size() - 1);
}

std::size_t SceneDescription::PolyhedralBodyCount() const {
  std::size_t count = 0;
  for (const SceneBody& body : bodies) {
    count += shapes[body.shape].kind == SceneShape::Kind::kPolyhedron ? 1 : 0;
  }
  return count;
}

Result<SceneDescription> ParseScene(std::string_view json_text, std::string_view name,
                                    const std::filesystem::path& base_dir) {
  // nlohmann keeps the last of repeated keys silently; a strict reader refuses them.
  std::vector<std::set<std::string>> open_objects;
  std::string duplicate;
  const json::parser_callback_t find_duplicates = [&](int, json::parse_event_t event,
                                                      json& parsed) {
    if (event == json::parse_event_t::object_start) open_objects.emplace_back();
    if (event == json::parse_event_t::object_end && !open_objects.empty()) open_objects.pop_back();
    if (event == json::parse_event_t::key && !open_objects.empty() &&
        !open_objects.back().insert(parsed.get<std::string>()).second && duplicate.empty()) {
      duplicate = parsed.get<std::string>();
    }
    return true;
  };
  json root;
  try {
    root = json::parse(json_text, find_duplicates);
  } catch (const json::exception& e) {
    // nlohmann's message starts "[json.exception.parse_error.101] parse error at line ...";
    // a syntax error knows its byte, a number overflow ("1e999") does not.
    std::string what = e.what();
    if (const auto bracket = what.find("] "); bracket != std::string::npos) {
      what = what.substr(bracket + 2);
    }
    const auto* parse_error = dynamic_cast<const json::parse_error*>(&e);
    const std::string where =
        parse_error != nullptr
            ? LineColumn(json_text, parse_error->byte == 0 ? 0 : parse_error->byte - 1) + ": "
            : std::string();
    return Error{std::string(name) + ": " + where + "not valid JSON: " + what};
  }
  if (!duplicate.empty()) {
    return Error{std::string(name) + ": duplicate key " + json(duplicate).dump() +
                 " (a key may appear only once in an object)"};
  }
  return SceneParser(name, base_dir).Parse(root);
}

Result<SceneDescription> ReadScene(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return Error{path.string() + ": cannot open"};
  std::ostringstream content;
  content << file.rdbuf();
  Result<SceneDescription> scene = ParseScene(content.str(), path.string(), path.parent_path());
  if (scene && scene->name.empty()) scene->name = path.stem().string();
  return scene;
}

}  // namespace sparsedyn
