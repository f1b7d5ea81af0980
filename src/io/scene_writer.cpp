// SPDX-License-Identifier: MIT
// Scene files: writing a SceneDescription back (FormatScene), the scene of a World at its end
// (FinalScene) and building its World.
#include <algorithm>
#include <fstream>

#include "io/json_checker.hpp"
#include "io/recording_json.hpp"
#include "sparsedyn/io/scene_file.hpp"

namespace sparsedyn {
namespace {

using nlohmann::ordered_json;

ordered_json VectorJson(const Vec3& v) { return ordered_json::array({v[0], v[1], v[2]}); }

ordered_json ContainerJson(const Container& container) {
  ordered_json out = {{"kind", recording::ContainerKindName(container.kind)}};
  if (container.kind != Container::Kind::kOpen) {
    out["lo"] = VectorJson(container.lo);
    out["hi"] = VectorJson(container.hi);
  }
  return out;
}

ordered_json DragJson(const Drag& drag) {
  return ordered_json{{"linear", drag.linear}, {"quadratic", drag.quadratic}};
}

// Every field of a body, on one line of the file.
ordered_json BodyJson(const SceneDescription& scene, const SceneBody& body) {
  ordered_json out;
  out["shape"] = ordered_json::parse(scene.shapes[body.shape].spec);
  out["position"] = VectorJson(body.position);
  const Eigen::Quaterniond& q = body.orientation;
  out["orientation"] = ordered_json::array({q.w(), q.x(), q.y(), q.z()});
  out["velocity"] = VectorJson(body.velocity);
  out["angular_velocity"] = VectorJson(body.angular_velocity);
  if (!body.thrust.isZero(0.0)) out["thrust"] = VectorJson(body.thrust);
  if (!body.thrust_schedule.empty()) {
    ordered_json schedule = ordered_json::array();
    for (const ThrustChange& change : body.thrust_schedule) {
      schedule.push_back({{"time", change.time}, {"thrust", VectorJson(change.thrust)}});
    }
    out["thrust_schedule"] = std::move(schedule);
  }
  if (body.density) {
    out["density"] = *body.density;
  } else {
    out["mass"] = body.mass;
  }
  out["restitution"] = body.restitution;
  out["friction"] = body.friction;
  if (body.is_static) out["static"] = true;
  if (body.god) {
    ordered_json track = ordered_json::array();
    for (const GodTarget& target : body.god->track) {
      ordered_json entry{{"time", target.time}, {"position", VectorJson(target.position)}};
      if (target.velocity) entry["velocity"] = VectorJson(*target.velocity);
      track.push_back(std::move(entry));
    }
    out["god"] = {{"max_acceleration", body.god->max_acceleration}, {"track", std::move(track)}};
  }
  if (body.drag) out["drag"] = DragJson(*body.drag);
  return out;
}

}  // namespace

std::string FormatScene(const SceneDescription& scene) {
  const WorldSettings& settings = scene.settings;
  ordered_json top;
  top["name"] = scene.name;
  top["seed"] = scene.seed;
  if (scene.packing) top["packing"] = *scene.packing;
  // Written only when not 0, so that scenes that start at 0 read as they always did.
  if (settings.start_time != 0.0) top["start_time"] = settings.start_time;
  top["duration"] = scene.duration;
  top["container"] = ContainerJson(settings.container);
  top["gravity"] = VectorJson(settings.gravity);
  // Written only when not zero, so that scenes without drag read as they always did.
  if (!settings.drag.IsZero()) top["drag"] = DragJson(settings.drag);
  top["broadphase"] = settings.broadphase == Broadphase::kGrid ? "grid" : "allpairs";
  top["grid_cells_per_body"] = settings.grid_cells_per_body;
  if (settings.stall_event_limit != WorldSettings{}.stall_event_limit) {
    top["stall_event_limit"] = settings.stall_event_limit;  // written only when not the default
  }
  top["tolerances"] = {{"contact", settings.contact_tolerance},
                       {"elastic_below_speed", settings.elastic_below_speed}};

  // One top-level key per line, then one body per line: readable and diff-able at any size.
  std::string out = "{\n";
  for (const auto& [key, value] : top.items()) {
    out += "  " + ordered_json(key).dump() + ": " + value.dump() + ",\n";
  }
  out += "  \"bodies\": [\n";
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    out += "    " + BodyJson(scene, scene.bodies[i]).dump() +
           (i + 1 < scene.bodies.size() ? ",\n" : "\n");
  }
  out += "  ]\n}\n";
  return out;
}

Status WriteScene(const SceneDescription& scene, const std::filesystem::path& path) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file) return Error{path.string() + ": cannot open for writing"};
  file << FormatScene(scene);
  file.close();
  if (!file) return Error{path.string() + ": write failed"};
  return Status::Ok();
}

namespace {

// The body's thrust at `now` and what is left of its schedule: the changes at times <= now
// have been processed (AdvanceTo processes every event with time <= its end).
void RunScheduleTo(SceneBody& body, double now) {
  std::vector<ThrustChange>& schedule = body.thrust_schedule;
  const auto later = std::find_if(schedule.begin(), schedule.end(),
                                  [now](const ThrustChange& change) { return change.time > now; });
  if (later != schedule.begin()) body.thrust = std::prev(later)->thrust;
  schedule.erase(schedule.begin(), later);
}

}  // namespace

SceneDescription FinalScene(const SceneDescription& scene, const World& world,
                            const std::vector<BodyId>& ids) {
  SPARSEDYN_ASSERT(ids.size() == scene.bodies.size(), "FinalScene: one handle per scene body");
  const double now = world.Time();
  SceneDescription out = scene;
  out.settings.start_time = now;
  out.bodies.clear();
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (!world.IsValid(ids[i])) continue;  // removed
    SceneBody body = scene.bodies[i];
    const BodyState state = world.StateAt(ids[i], now);
    body.position = state.position;
    body.orientation = state.orientation;
    body.velocity = state.velocity;
    body.angular_velocity = state.angular_velocity;
    RunScheduleTo(body, now);
    // A god object's targets still ahead; from there a new plan (the move under way is planned
    // again from its middle, docs/scene-format.md).
    if (body.god) body.god = world.GodTrackOf(ids[i]);
    out.bodies.push_back(std::move(body));
  }
  return out;
}

BodyDef SceneBodyDef(const SceneDescription& scene, std::size_t index) {
  const SceneBody& body = scene.bodies[index];
  const SceneShape& shape = scene.shapes[body.shape];
  BodyDef def;
  def.radius = shape.radius;
  def.shape = shape.polyhedron;  // null for a sphere; shared by the bodies of one shape
  def.position = body.position;
  def.orientation = body.orientation;
  def.velocity = body.velocity;
  def.angular_velocity = body.angular_velocity;
  def.thrust = body.thrust;
  def.thrust_schedule = body.thrust_schedule;
  def.mass = body.mass;
  def.restitution = body.restitution;
  def.friction = body.friction;
  def.is_static = body.is_static;
  def.god = body.god;
  def.drag = body.drag;
  return def;
}

Result<World> BuildWorld(const SceneDescription& scene) {
  if (Status settings = ValidateSettings(scene.settings); !settings) return settings.error();
  World world(scene.settings);
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    Result<BodyId> id = world.AddBody(SceneBodyDef(scene, i));
    if (!id) return Error{"bodies[" + std::to_string(i) + "]: " + id.error().message};
  }
  return world;
}

}  // namespace sparsedyn
