// SPDX-License-Identifier: MIT
#include "apps/cli/conventional_run.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "apps/cli/run_support.hpp"
#include "scenes/presets.hpp"
#include "sparsedyn/conventional.hpp"
#include "sparsedyn/io/scene_file.hpp"

namespace sparsedyn::cli {
namespace {

// The scene to run: the file, or the preset's fully expanded scene.
Result<SceneDescription> LoadScene(const RunOptions& options) {
  if (options.scene_file.empty()) {
    Result<scenes::Preset> preset = scenes::MakePreset(PresetRequestOf(options));
    if (!preset) return preset.error();
    return std::move(preset->scene);
  }
  if (options.preset || options.n || options.density || options.seed) {
    return Error{"--preset, --n, --density and --seed apply to presets, not to a scene file"};
  }
  return ReadScene(options.scene_file);
}

// The scene's bodies in a ConventionalWorld; an Error names the body.
Result<ConventionalWorld> Build(const SceneDescription& scene,
                                const ConventionalSettings& conventional) {
  if (Status ok = ConventionalWorld::CheckSettings(scene.settings, conventional); !ok) {
    return ok.error();
  }
  ConventionalWorld world(scene.settings, conventional);
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    // A sphere has no polyhedron: AddBody refuses it.
    Result<BodyId> id = world.AddBody(SceneBodyDef(scene, i));
    if (!id) return Error{"bodies[" + std::to_string(i) + "]: " + id.error().message};
  }
  return world;
}

nlohmann::json Summary(const SceneDescription& scene, const ConventionalWorld& world, double wall,
                       double energy_initial, const Vec3& momentum_initial) {
  const ConventionalStatistics& s = world.Stats();
  const double collisions = static_cast<double>(s.collisions + s.wall_collisions);
  // The World's keys, with a step in the role of an event (the unit of work) and no meetings
  // or stale events (the method has neither); the method's own counters follow.
  return {
      {"method", "conventional"},
      {"dt", world.Conventional().dt},
      {"digits", world.Conventional().digits},
      {"steps", s.steps},
      {"preset", scene.name},
      {"bodies", world.BodyCount()},
      // The method simulates moving polyhedra only (ConventionalWorld::AddBody).
      {"bodies_by_kind",
       {{"spheres", 0}, {"polyhedra", world.BodyCount()}, {"static", 0}, {"god", 0}}},
      {"density", PackingOf(scene)},
      {"seed", scene.seed},
      {"broadphase", "sweep"},
      {"simulated_time", world.Time()},
      {"wall_seconds", wall},
      {"events", s.steps},
      {"events_by_kind", {{"step", s.steps}}},
      {"stale_events", 0},
      {"meetings", 0},
      {"collisions", s.collisions + s.wall_collisions},
      {"body_collisions", s.collisions},
      {"wall_collisions", s.wall_collisions},
      {"collisions_per_second", wall > 0 ? collisions / wall : 0.0},
      {"events_per_second", wall > 0 ? static_cast<double>(s.steps) / wall : 0.0},
      {"steps_per_second", wall > 0 ? static_cast<double>(s.steps) / wall : 0.0},
      {"pair_tests", s.pair_tests},
      {"narrow_queries", s.narrow_queries},
      {"bisection_evaluations", s.bisection_evaluations},
      {"kinetic_energy_initial", energy_initial},
      {"kinetic_energy_final", world.KineticEnergy()},
      {"momentum_initial", VectorJson(momentum_initial)},
      {"momentum_final", VectorJson(world.Momentum())},
      {"max_penetration", s.max_penetration},
  };
}

}  // namespace

int RunConventional(const RunOptions& options) {
  auto fail = [](const std::string& message, int status) {
    std::cerr << "sparsedyn run: " << message << "\n";
    return status;
  };
  if (!options.dt) return fail("--method conventional needs --dt (the time step, s)", 2);
  if (!options.record_file.empty() || !options.write_scene.empty() ||
      !options.write_final_scene.empty() || options.broadphase) {
    return fail(
        "--record, --write-scene, --write-final-scene and --broadphase apply to --method event", 2);
  }
  Result<SceneDescription> scene = LoadScene(options);
  if (!scene) return fail(scene.error().message, 2);
  // The time-stepped method starts at 0 with constant thrusts (docs/conventional.md).
  if (scene->settings.start_time != 0.0) {
    return fail("--method conventional: the scene's start_time must be 0", 2);
  }
  if (!scene->settings.drag.IsZero()) {
    return fail("--method conventional: drag: drag applies to --method event", 2);
  }
  for (std::size_t i = 0; i < scene->bodies.size(); ++i) {
    if (scene->bodies[i].drag && !scene->bodies[i].drag->IsZero()) {
      return fail("--method conventional: bodies[" + std::to_string(i) +
                      "].drag: drag applies to --method event",
                  2);
    }
    if (!scene->bodies[i].thrust_schedule.empty()) {
      return fail("--method conventional: bodies[" + std::to_string(i) +
                      "].thrust_schedule: thrust schedules apply to --method event",
                  2);
    }
    if (scene->bodies[i].god) {
      return fail("--method conventional: bodies[" + std::to_string(i) +
                      "].god: god objects apply to --method event",
                  2);
    }
  }
  const ConventionalSettings conventional{.dt = *options.dt, .digits = options.digits.value_or(4)};
  Result<ConventionalWorld> world = Build(*scene, conventional);
  if (!world) {
    const std::string where = options.scene_file.empty() ? "" : options.scene_file + ": ";
    return fail(where + world.error().message, 2);
  }

  const double until = options.until.value_or(scene->EndTime());
  const double energy_initial = world->KineticEnergy();
  const Vec3 momentum_initial = world->Momentum();
  const auto start = std::chrono::steady_clock::now();
  const Status status = world->AdvanceTo(until);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!status) return fail(status.error().message, 1);

  const nlohmann::json out = Summary(*scene, *world, wall, energy_initial, momentum_initial);
  if (options.json) {
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  std::printf("sparsedyn run --method conventional: scene '%s', %zu bodies, dt %g, %d digits\n",
              scene->name.c_str(), world->BodyCount(), conventional.dt, conventional.digits);
  std::printf("  simulated %.6g s in %.3f s wall: %.0f steps (%.0f/s), %.0f collisions\n",
              world->Time(), wall, out["steps"].get<double>(),
              out["steps_per_second"].get<double>(), out["collisions"].get<double>());
  std::printf("  %.0f pair tests, %.0f narrow queries, %.0f bisection evaluations\n",
              out["pair_tests"].get<double>(), out["narrow_queries"].get<double>(),
              out["bisection_evaluations"].get<double>());
  std::printf("  kinetic energy %.17g -> %.17g, deepest overlap at a step end %.3g\n",
              energy_initial, world->KineticEnergy(), world->Stats().max_penetration);
  return 0;
}

}  // namespace sparsedyn::cli
