// SPDX-License-Identifier: MIT
// The one summary of a run, shared by `sparsedyn run --json` and the Python package.
#include "sparsedyn/io/run_summary.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace sparsedyn {
namespace {

nlohmann::json VectorJson(const Vec3& v) { return {v[0], v[1], v[2]}; }

const char* BroadphaseName(Broadphase broadphase) {
  return broadphase == Broadphase::kAllPairs ? "allpairs" : "grid";
}

// The bodies by kind: moving spheres, moving polyhedra (neither static nor god objects), static
// bodies and god objects (of either shape), so that the four add up to "bodies".
nlohmann::json BodiesByKind(const World& world) {
  std::size_t spheres = 0, polyhedra = 0, statics = 0, gods = 0;
  for (const BodyId id : world.Bodies()) {
    if (world.IsStatic(id)) {
      ++statics;
    } else if (world.IsGod(id)) {
      ++gods;
    } else if (world.IsPolyhedron(id)) {
      ++polyhedra;
    } else {
      ++spheres;
    }
  }
  return {{"spheres", spheres}, {"polyhedra", polyhedra}, {"static", statics}, {"god", gods}};
}

}  // namespace

double ReportedPacking(const SceneDescription& scene) {
  if (scene.packing) return *scene.packing;
  const Container& box = scene.settings.container;
  if (box.kind == Container::Kind::kOpen) return 0.0;
  double volume = 0;
  for (const SceneBody& body : scene.bodies) volume += scene.shapes[body.shape].Volume();
  return volume / (box.hi - box.lo).prod();
}

std::string RunSummaryJson(const World& world, const RunContext& context) {
  const Statistics& stats = world.Stats();
  nlohmann::json kinds = nlohmann::json::object();
  for (int k = 0; k < static_cast<int>(stats.events_by_kind.size()); ++k) {
    kinds[EventKindName(k)] = stats.events_by_kind[static_cast<std::size_t>(k)];
  }
  const double wall = context.wall_seconds;
  const double collisions = static_cast<double>(stats.collisions + stats.wall_collisions);
  const nlohmann::json out = {
      {"method", "event"},
      {"preset", context.preset},
      {"bodies", world.BodyCount()},
      {"bodies_by_kind", BodiesByKind(world)},
      {"density", context.density},
      {"seed", context.seed},
      {"broadphase", BroadphaseName(world.Settings().broadphase)},
      {"simulated_time", world.Time()},
      {"wall_seconds", wall},
      {"events", stats.events},
      {"events_by_kind", kinds},
      {"stale_events", stats.stale_target_absent + stats.stale_actor_absent},
      {"stale_target_absent", stats.stale_target_absent},
      {"stale_actor_absent", stats.stale_actor_absent},
      {"meetings", stats.meetings},
      {"engagements_started", stats.engagements_started},
      {"detail_predictions", stats.detail_predictions},
      {"detail_iterations", stats.detail_iterations},
      {"detail_checkpoints", stats.detail_checkpoints},
      {"drag_checks", stats.drag_checks},
      {"drag_steps", stats.drag_steps},
      {"collisions", stats.collisions + stats.wall_collisions},
      {"body_collisions", stats.collisions},
      {"wall_collisions", stats.wall_collisions},
      {"collisions_per_second", wall > 0 ? collisions / wall : 0.0},
      {"events_per_second", wall > 0 ? static_cast<double>(stats.events) / wall : 0.0},
      {"kinetic_energy_initial", context.kinetic_energy_initial},
      {"kinetic_energy_final", world.KineticEnergy()},
      {"momentum_initial", VectorJson(context.momentum_initial)},
      {"momentum_final", VectorJson(world.Momentum())},
      {"max_penetration", world.MaxPenetration()},
      {"bytes_per_body", static_cast<double>(world.MemoryBytes()) /
                             static_cast<double>(std::max<std::size_t>(1, world.BodyCount()))},
  };
  return out.dump();
}

}  // namespace sparsedyn
