// SPDX-License-Identifier: MIT
// What each fuzz target does with one input. The oracles are independent of the code under
// test where one exists: a parsed mesh must survive the writer and read back equal, a parsed
// scene must be a fixed point of FormatScene/ParseScene, an exported recording must be JSON
// that nlohmann parses, and a closest-feature distance must match the brute-force long double
// reference of tests/narrow/ (ReferenceSignedDistance). Refusals must name the input.
#include "fuzz/fuzz_entries.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <type_traits>
#include <variant>
#include <vector>

#include "narrow/narrow_oracles.hpp"
#include "sparsedyn/io/mesh_io.hpp"
#include "sparsedyn/io/recording.hpp"
#include "sparsedyn/io/scene_file.hpp"
#include "sparsedyn/narrow/closest_features.hpp"

namespace sparsedyn::fuzz {
namespace {

constexpr std::array<std::string_view, 8> kTargets = {"off",  "obj",   "stl",       "ply",
                                                      "ohio", "scene", "recording", "polyhedron"};

// A refusal must start with the name it was given ("<file>:<line>: ..." or "<file>: ...").
std::string CheckRefusalNamesInput(const Error& error, std::string_view name) {
  if (error.message.rfind(name, 0) == 0) return "";
  return "refusal does not name the input: " + error.message;
}

bool SameMesh(const PolygonMesh& a, const PolygonMesh& b) {
  if (a.faces != b.faces || a.vertices.size() != b.vertices.size()) return false;
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    if (a.vertices[i] != b.vertices[i]) return false;
  }
  return true;
}

std::string CheckMesh(std::string_view bytes, MeshFormat format, std::string_view name) {
  const Result<PolygonMesh> mesh = ParseMesh(bytes, format, name);
  if (!mesh) return CheckRefusalNamesInput(mesh.error(), name);

  // What the readers promise: finite coordinates, polygons of >= 3 in-range indices.
  const auto vertex_count = static_cast<std::int64_t>(mesh->vertices.size());
  for (const Eigen::Vector3d& v : mesh->vertices) {
    if (!v.allFinite()) return "accepted a non-finite coordinate";
  }
  for (const std::vector<std::int32_t>& face : mesh->faces) {
    if (face.size() < 3) return "accepted a face of fewer than 3 vertices";
    for (const std::int32_t i : face) {
      if (i < 0 || i >= vertex_count) return "accepted an index out of range";
    }
  }

  // Written back (ASCII: exact digits) and read again: the same mesh.
  const Result<std::string> text = FormatMesh(*mesh, format);
  if (!text) return "the writer refuses what the reader accepted: " + text.error().message;
  const Result<PolygonMesh> again = ParseMesh(*text, format, name);
  if (!again) return "the reader refuses what the writer wrote: " + again.error().message;
  if (!SameMesh(*mesh, *again)) return "the mesh changed through a write and a read";
  return "";
}

// Meshes named by a fuzzed scene are looked for next to data/'s files (cube.off, ...).
const std::filesystem::path kSceneDir = std::filesystem::path(SPARSEDYN_SOURCE_DIR) / "data";

// A small accepted scene is built and run for a moment: a refusal must name its body, and
// what the World accepted must stay valid.
std::string CheckSceneRuns(const SceneDescription& scene) {
  constexpr std::size_t kMaxBodies = 8;
  constexpr std::uint64_t kMaxEvents = 20000;
  if (scene.bodies.size() > kMaxBodies) return "";
  SceneDescription bounded = scene;
  bounded.settings.stall_event_limit =
      std::min<std::uint64_t>(scene.settings.stall_event_limit, 4096);
  Result<World> world = BuildWorld(bounded);
  if (!world) return "";
  if (const Status valid = world->Validate(); !valid) {
    return "BuildWorld accepted an invalid world: " + valid.error().message;
  }
  const double until = std::min(scene.duration, 1.0);
  // What `sparsedyn run` refuses before it runs: an end time whose clock step is too coarse
  // for the fastest body (a tetrahedron at 2e23 m/s bounced every 1e-23 s, for ever).
  if (!CheckClockResolution(*world, until)) return "";
  for (int step = 1; step <= 16 && world->Stats().events < kMaxEvents; ++step) {
    if (!world->AdvanceTo(until * step / 16)) return "";  // a named error is fine
  }
  if (const Status valid = world->Validate(); !valid) {
    return "a run broke an invariant: " + valid.error().message;
  }
  return "";
}

std::string CheckScene(std::string_view bytes) {
  constexpr std::string_view kName = "fuzz.json";
  const Result<SceneDescription> scene = ParseScene(bytes, kName, kSceneDir);
  if (!scene) return CheckRefusalNamesInput(scene.error(), kName);

  // FormatScene writes every field so that ParseScene reads it back: a fixed point.
  const std::string text = FormatScene(*scene);
  const Result<SceneDescription> again = ParseScene(text, kName, kSceneDir);
  if (!again) return "ParseScene refuses FormatScene's text: " + again.error().message;
  if (FormatScene(*again) != text) return "FormatScene(ParseScene(FormatScene(s))) differs";
  return CheckSceneRuns(*scene);
}

std::string CheckRecording(std::string_view bytes) {
  constexpr std::string_view kName = "fuzz.sdrec";
  const Result<Recording> recording = ParseRecording(bytes, kName);
  if (!recording) return CheckRefusalNamesInput(recording.error(), kName);

  // What the reader promises: indices in range, time never going backwards.
  const std::size_t bodies = recording->bodies.size();
  for (const RecordedBody& body : recording->bodies) {
    if (body.shape >= recording->header.shapes.size()) return "a body's shape is out of range";
  }
  double last = -std::numeric_limits<double>::infinity();
  for (const RecordingRecord& record : recording->records) {
    const double t = std::visit(
        [](const auto& r) {
          if constexpr (std::is_same_v<std::decay_t<decltype(r)>, RecordedSegment>)
            return r.t0;
          else
            return r.time;
        },
        record);
    if (t < last) return "time goes backwards";
    last = t;
    if (const auto* s = std::get_if<RecordedSegment>(&record); s && s->body >= bodies) {
      return "a segment's body is out of range";
    }
    if (const auto* c = std::get_if<RecordedCollision>(&record);
        c && (c->a >= bodies || (!c->b_is_wall && c->b >= bodies) || (c->b_is_wall && c->b > 5))) {
      return "a collision's body or wall is out of range";
    }
  }

  // The JSON-lines export: every line parses (nlohmann, strict).
  std::ostringstream out;
  WriteJsonLines(*recording, out);
  std::istringstream lines(out.str());
  for (std::string line; std::getline(lines, line);) {
    if (!nlohmann::json::accept(line)) return "export-jsonl wrote a line that is not JSON";
  }
  return "";
}

// Reads the input as numbers: a lattice of int16 / 64 (coplanar faces, duplicates, slivers) or,
// with the mode byte odd, raw doubles.
class NumberStream {
 public:
  explicit NumberStream(std::string_view bytes)
      : raw_(!bytes.empty() && (static_cast<unsigned char>(bytes[0]) & 1) != 0),
        bytes_(bytes.empty() ? bytes : bytes.substr(1)) {}

  bool Empty() const { return bytes_.size() < (raw_ ? 8u : 2u); }

  double Next() {
    if (Empty()) return 0.0;
    if (raw_) {
      double value = 0;
      std::memcpy(&value, bytes_.data(), 8);
      bytes_.remove_prefix(8);
      return value;
    }
    std::int16_t value = 0;
    std::memcpy(&value, bytes_.data(), 2);
    bytes_.remove_prefix(2);
    return value / 64.0;
  }

 private:
  bool raw_;
  std::string_view bytes_;
};

// The narrow phase's scale is what the World admits (src/world/hostile_values.cpp); beyond it
// only the building is fuzzed.
bool QueryableScale(const ConvexPolyhedron& p) { return p.scale() >= 1e-6 && p.scale() <= 1e6; }

std::string CheckClosestFeatures(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                                 const Pose& X_WB) {
  const auto shared_a = std::make_shared<const ConvexPolyhedron>(a);
  const auto shared_b = std::make_shared<const ConvexPolyhedron>(b);
  const TrackedPolyhedron tracked_a(shared_a), tracked_b(shared_b);
  const Pose X_WA;
  const ClosestFeatures found = FindClosestFeatures(tracked_a, X_WA, tracked_b, X_WB);
  if (found.status == ClosestFeatures::Status::kIterationCap) {
    return "the closest-feature walk hit its cap: " +
           DescribeQuery(tracked_a, X_WA, tracked_b, X_WB);
  }

  // Against brute force over every feature pair (long double), with room for slivers: the
  // tests' 1e-9 of the diameter holds for random hulls, a fuzzed one may be thinner.
  constexpr double kRelativeBound = 1e-7;
  const double diameter = 2 * std::max(a.bounding_radius(), b.bounding_radius());
  const double bound = kRelativeBound * (diameter + X_WB.translation.norm());
  const auto reference = static_cast<double>(testing::ReferenceSignedDistance(a, X_WA, b, X_WB));
  if (reference > bound && std::abs(found.distance - reference) > bound) {
    return "distance " + std::to_string(found.distance) + " but brute force says " +
           std::to_string(reference) + ": " + DescribeQuery(tracked_a, X_WA, tracked_b, X_WB);
  }
  if (reference < -bound && found.distance > bound) {
    return "separated by " + std::to_string(found.distance) +
           " but brute force finds overlap: " + DescribeQuery(tracked_a, X_WA, tracked_b, X_WB);
  }
  return "";
}

std::string CheckPolyhedron(std::string_view bytes) {
  NumberStream numbers(bytes);
  // Up to 24 points for A, then a pose for B, then up to 24 points for B.
  constexpr int kMaxPoints = 24;
  std::vector<Eigen::Vector3d> points_a, points_b;
  const auto read_points = [&](std::vector<Eigen::Vector3d>& points) {
    const double n = numbers.Next();
    const int count =
        4 + (std::isfinite(n) ? static_cast<int>(std::fmod(std::fabs(n), kMaxPoints - 3)) : 0);
    for (int i = 0; i < count && !numbers.Empty(); ++i) {
      const double x = numbers.Next(), y = numbers.Next(), z = numbers.Next();
      points.emplace_back(x, y, z);
    }
  };
  read_points(points_a);
  Pose X_WB;
  X_WB.translation = Eigen::Vector3d(numbers.Next(), numbers.Next(), numbers.Next());
  Eigen::Quaterniond q(numbers.Next(), numbers.Next(), numbers.Next(), numbers.Next());
  if (q.coeffs().allFinite() && q.norm() > 1e-3 && q.norm() < 1e3) X_WB.rotation = q.normalized();
  read_points(points_b);

  const Result<ConvexPolyhedron> a = ConvexPolyhedron::FromPoints(points_a);
  if (!a) return a.error().message.empty() ? "a refusal without a message" : "";
  const Result<ConvexPolyhedron> b =
      points_b.size() >= 4 ? ConvexPolyhedron::FromPoints(points_b) : Result<ConvexPolyhedron>(*a);
  if (!b || !QueryableScale(*a) || !QueryableScale(*b)) return "";
  if (!X_WB.translation.allFinite() || X_WB.translation.norm() > 1e6) return "";
  return CheckClosestFeatures(*a, *b, X_WB);
}

}  // namespace

std::span<const std::string_view> TargetNames() { return kTargets; }

std::string RunInput(std::string_view target, std::string_view bytes) {
  if (target == "off") return CheckMesh(bytes, MeshFormat::kOff, "fuzz.off");
  if (target == "obj") return CheckMesh(bytes, MeshFormat::kObj, "fuzz.obj");
  if (target == "stl") return CheckMesh(bytes, MeshFormat::kStl, "fuzz.stl");
  if (target == "ply") return CheckMesh(bytes, MeshFormat::kPly, "fuzz.ply");
  if (target == "ohio") return CheckMesh(bytes, MeshFormat::kOhio, "fuzz.ohio");
  if (target == "scene") return CheckScene(bytes);
  if (target == "recording") return CheckRecording(bytes);
  if (target == "polyhedron") return CheckPolyhedron(bytes);
  return "unknown fuzz target '" + std::string(target) + "'";
}

}  // namespace sparsedyn::fuzz
