// SPDX-License-Identifier: MIT
#include "io/scene_shapes.hpp"

#include <cmath>
#include <numbers>

#include "sparsedyn/geometry/generators.hpp"
#include "sparsedyn/io/mesh_io.hpp"

namespace sparsedyn {

double SceneShape::Volume() const {
  if (kind == Kind::kSphere) return 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  return polyhedron->volume();
}

SceneShape SphereShape(double radius) {
  SceneShape shape;
  shape.kind = SceneShape::Kind::kSphere;
  shape.radius = radius;
  shape.spec = nlohmann::json{{"sphere", {{"radius", radius}}}}.dump();
  return shape;
}

namespace json_input {
namespace {

// Largest face count RandomConvexPolyhedron accepts, and a sane bound on prism sides.
constexpr std::uint64_t kMaxRandomFaces = 100000;
constexpr std::uint64_t kMaxPrismSides = 10000;

// The generator name of a solid: its ToString with '_' for ' ' ("truncated_icosahedron").
std::string GeneratorName(std::string_view name) {
  std::string out(name);
  for (char& c : out) c = c == ' ' ? '_' : c;
  return out;
}

std::optional<PlatonicSolid> PlatonicNamed(const std::string& name) {
  for (int i = 0; i < kPlatonicSolidCount; ++i) {
    const auto solid = static_cast<PlatonicSolid>(i);
    if (GeneratorName(ToString(solid)) == name) return solid;
  }
  return std::nullopt;
}

std::optional<ArchimedeanSolid> ArchimedeanNamed(const std::string& name) {
  for (int i = 0; i < kArchimedeanSolidCount; ++i) {
    const auto solid = static_cast<ArchimedeanSolid>(i);
    if (GeneratorName(ToString(solid)) == name) return solid;
  }
  return std::nullopt;
}

std::string GeneratorNames() {
  std::string names = "box, prism, needle, slab, random_convex";
  for (int i = 0; i < kPlatonicSolidCount; ++i) {
    names += ", " + GeneratorName(ToString(static_cast<PlatonicSolid>(i)));
  }
  for (int i = 0; i < kArchimedeanSolidCount; ++i) {
    names += ", " + GeneratorName(ToString(static_cast<ArchimedeanSolid>(i)));
  }
  return names;
}

// Checks the optional "scale" / "bounding_radius" pair shared by meshes and generators.
void CheckSize(const json& value, const std::string& path, Checker& checker) {
  if (value.contains("scale")) {
    checker.NumberIn(value["scale"], Key(path, "scale"), 0, kInfinity, true);
  }
  if (value.contains("bounding_radius")) {
    checker.NumberIn(value["bounding_radius"], Key(path, "bounding_radius"), 0, kInfinity, true);
  }
  if (value.contains("scale") && value.contains("bounding_radius")) {
    checker.Fail(path, "give \"scale\" or \"bounding_radius\", not both");
  }
}

// Checks the parameters of generator `name`; fills defaults into `spec`.
void CheckGenerator(const std::string& name, json& spec, const std::string& path,
                    std::uint64_t default_seed, Checker& checker) {
  auto required = [&](const char* key) {
    if (!spec.contains(key)) checker.Fail(Key(path, key), "is missing (generator " + name + ")");
    return spec.contains(key);
  };
  auto positive = [&](const char* key) {
    if (required(key)) checker.NumberIn(spec[key], Key(path, key), 0, kInfinity, true);
  };
  auto optional_positive = [&](const char* key) {
    if (spec.contains(key)) checker.NumberIn(spec[key], Key(path, key), 0, kInfinity, true);
  };
  const auto common = {"generator", "scale", "bounding_radius"};
  auto allow = [&](std::initializer_list<const char*> extra) {
    std::vector<const char*> keys(common);
    keys.insert(keys.end(), extra);
    // Object() takes an initializer_list; check unknown keys by hand with the same wording.
    for (const auto& [key, unused] : spec.items()) {
      bool known = false;
      for (const char* k : keys) known = known || key == k;
      if (known) continue;
      std::string list;
      for (const char* k : keys) list += std::string(list.empty() ? "" : ", ") + k;
      checker.Fail(Key(path, key),
                   "unknown key for generator " + name + " (allowed: " + list + ")");
    }
  };
  if (PlatonicNamed(name) || ArchimedeanNamed(name)) {
    allow({});
  } else if (name == "box") {
    allow({"half_extents"});
    if (required("half_extents")) {
      if (auto h = checker.Vector(spec["half_extents"], Key(path, "half_extents"))) {
        if (!(h->minCoeff() > 0)) checker.Fail(Key(path, "half_extents"), "must all be > 0");
      }
    }
  } else if (name == "prism") {
    allow({"sides", "radius", "half_height"});
    if (required("sides")) checker.Unsigned(spec["sides"], Key(path, "sides"), kMaxPrismSides);
    positive("radius");
    positive("half_height");
  } else if (name == "needle") {
    allow({"length", "aspect_ratio", "sides"});
    positive("length");
    optional_positive("aspect_ratio");
    if (spec.contains("sides")) checker.Unsigned(spec["sides"], Key(path, "sides"), kMaxPrismSides);
  } else if (name == "slab") {
    allow({"width", "aspect_ratio"});
    positive("width");
    optional_positive("aspect_ratio");
  } else if (name == "random_convex") {
    allow({"faces", "seed", "radii"});
    if (required("faces")) checker.Unsigned(spec["faces"], Key(path, "faces"), kMaxRandomFaces);
    if (spec.contains("seed")) {
      checker.Unsigned(spec["seed"], Key(path, "seed"), UINT64_MAX);
    } else {
      spec["seed"] = default_seed;
    }
    if (spec.contains("radii")) {
      if (auto r = checker.Vector(spec["radii"], Key(path, "radii"))) {
        if (!(r->minCoeff() > 0)) checker.Fail(Key(path, "radii"), "must all be > 0");
      }
    }
  } else {
    checker.Fail(Key(path, "generator"),
                 "unknown generator \"" + name + "\" (known: " + GeneratorNames() + ")");
  }
}

// Runs the generator of a checked spec.
Result<ConvexPolyhedron> Generate(const json& spec) {
  const std::string name = spec["generator"].get<std::string>();
  if (auto solid = PlatonicNamed(name)) return MakeSolid(*solid);
  if (auto solid = ArchimedeanNamed(name)) return MakeSolid(*solid);
  auto number = [&](const char* key, double fallback) {
    return spec.contains(key) ? spec[key].get<double>() : fallback;
  };
  auto vector = [&](const char* key) {
    const json& v = spec[key];
    return Vec3(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
  };
  if (name == "box") return MakeBox(vector("half_extents"));
  if (name == "prism") {
    return MakePrism(spec["sides"].get<int>(), number("radius", 0), number("half_height", 0));
  }
  if (name == "needle") {
    return MakeNeedle(number("length", 0), number("aspect_ratio", 1000.0),
                      spec.contains("sides") ? spec["sides"].get<int>() : 6);
  }
  if (name == "slab") return MakeSlab(number("width", 0), number("aspect_ratio", 1000.0));
  RandomPolyhedronOptions options;
  if (spec.contains("radii")) options.radii = vector("radii");
  return RandomConvexPolyhedron(spec["faces"].get<int>(), spec["seed"].get<std::uint64_t>(),
                                options);
}

}  // namespace

std::optional<json> CanonicalShapeSpec(const json& value, const std::string& path,
                                       std::uint64_t default_seed, Checker& checker) {
  const std::size_t errors = checker.ErrorCount();
  if (value.is_string()) return json{{"mesh", value}};
  if (!value.is_object()) {
    checker.Fail(path,
                 "must be an object ({\"sphere\": ...}, {\"mesh\": ...} or "
                 "{\"generator\": ...}) or a mesh file path, got " +
                     Describe(value));
    return std::nullopt;
  }
  json spec = value;
  const int forms = (value.contains("sphere") ? 1 : 0) + (value.contains("mesh") ? 1 : 0) +
                    (value.contains("generator") ? 1 : 0);
  if (forms != 1) {
    checker.Fail(path, "must have exactly one of \"sphere\", \"mesh\", \"generator\"");
    return std::nullopt;
  }
  if (value.contains("sphere")) {
    checker.Object(value, path, {"sphere"});
    const std::string sphere_path = Key(path, "sphere");
    if (checker.Object(value["sphere"], sphere_path, {"radius"})) {
      if (!value["sphere"].contains("radius")) {
        checker.Fail(Key(sphere_path, "radius"), "is missing");
      } else {
        checker.NumberIn(value["sphere"]["radius"], Key(sphere_path, "radius"), 0, kInfinity, true);
      }
    }
  } else if (value.contains("mesh")) {
    checker.Object(value, path, {"mesh", "scale", "bounding_radius"});
    checker.String(value["mesh"], Key(path, "mesh"));
    CheckSize(value, path, checker);
  } else if (auto name = checker.String(value["generator"], Key(path, "generator"))) {
    CheckGenerator(*name, spec, path, default_seed, checker);
    CheckSize(value, path, checker);
  }
  if (checker.ErrorCount() != errors) return std::nullopt;
  return spec;
}

std::optional<SceneShape> BuildShape(const json& spec, const std::string& path,
                                     const std::filesystem::path& base_dir, Checker& checker) {
  if (spec.contains("sphere")) return SphereShape(spec["sphere"]["radius"].get<double>());

  // A polyhedron from a mesh file or a generator, recentred on its centroid, then sized.
  Result<ConvexPolyhedron> built = Error{};
  std::string where;
  if (spec.contains("mesh")) {
    where = Key(path, "mesh");
    const std::filesystem::path file = base_dir / spec["mesh"].get<std::string>();
    Result<PolygonMesh> mesh = ReadMesh(file);  // its errors say "<file>:<line>: ..."
    built = mesh ? ConvexPolyhedron::FromMesh(*mesh) : Result<ConvexPolyhedron>(mesh.error());
    // A mesh refused as a polyhedron (not convex, not closed...) names the file too.
    if (mesh && !built) built = Error{file.string() + ": " + built.error().message};
  } else {
    where = Key(path, "generator");
    built = Generate(spec);
  }
  if (!built) {
    checker.Fail(where, built.error().message);
    return std::nullopt;
  }
  ConvexPolyhedron polyhedron = built->Recentered();
  if (spec.contains("scale")) polyhedron = polyhedron.Scaled(spec["scale"].get<double>());
  if (spec.contains("bounding_radius")) {
    polyhedron =
        polyhedron.Scaled(spec["bounding_radius"].get<double>() / polyhedron.bounding_radius());
  }
  SceneShape shape;
  shape.kind = SceneShape::Kind::kPolyhedron;
  shape.radius = polyhedron.bounding_radius();
  shape.polyhedron = std::make_shared<const ConvexPolyhedron>(std::move(polyhedron));
  shape.spec = spec.dump();
  return shape;
}

}  // namespace json_input

Result<SceneShape> ParseShapeSpec(std::string_view spec_json, const std::filesystem::path& base_dir,
                                  std::uint64_t default_seed, std::string_view json_path) {
  using nlohmann::json;
  json_input::Checker checker("");
  const json value = json::parse(spec_json, nullptr, /*allow_exceptions=*/false);
  if (value.is_discarded()) return Error{std::string(json_path) + ": not valid JSON"};
  const std::string path(json_path);
  std::optional<json> spec = json_input::CanonicalShapeSpec(value, path, default_seed, checker);
  if (!spec) return checker.ToError();
  std::optional<SceneShape> shape = json_input::BuildShape(*spec, path, base_dir, checker);
  if (!shape) return checker.ToError();
  return std::move(*shape);
}

void RebaseMeshPaths(SceneDescription& scene, const std::filesystem::path& from_dir,
                     const std::filesystem::path& to_dir) {
  namespace fs = std::filesystem;
  // Lexically, as ReadMesh resolves them (base_dir / path): no file needs to exist yet. An
  // empty folder is the current one (the parent of a bare file name).
  const auto folder = [](const fs::path& dir) {
    return fs::absolute(dir.empty() ? fs::path(".") : dir).lexically_normal();
  };
  const fs::path from = folder(from_dir);
  const fs::path to = folder(to_dir);
  if (from == to) return;
  for (SceneShape& shape : scene.shapes) {
    if (shape.kind != SceneShape::Kind::kPolyhedron) continue;
    nlohmann::json spec = nlohmann::json::parse(shape.spec);
    if (!spec.contains("mesh")) continue;
    const fs::path mesh = spec["mesh"].get<std::string>();
    if (mesh.is_absolute()) continue;
    const fs::path moved = (from / mesh).lexically_normal().lexically_relative(to);
    // Different roots (another drive) have no relative path: name the file absolutely.
    spec["mesh"] = (moved.empty() ? (from / mesh).lexically_normal() : moved).generic_string();
    shape.spec = spec.dump();
  }
}

}  // namespace sparsedyn
