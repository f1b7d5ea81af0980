// SPDX-License-Identifier: MIT
#include "apps/cli/run_command.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <string>

#include "apps/cli/conventional_run.hpp"
#include "apps/cli/run_options.hpp"
#include "apps/cli/run_support.hpp"
#include "scenes/presets.hpp"
#include "sparsedyn/io/recording.hpp"
#include "sparsedyn/io/scene_file.hpp"

namespace sparsedyn::cli {
namespace {

// Where `sparsedyn run` with the default scene writes its recording unless told otherwise.
constexpr const char* kDefaultRecording = "sparsedyn-default.sdrec";

// What is about to run: the scene, its World and what the summary reports about it.
struct Setup {
  SceneDescription scene;
  World world;
  double density = 0;  // packing fraction reported as "density"
};

// The scene file or the preset, and its World; an Error names the bad option or file.
Result<Setup> MakeSetup(const RunOptions& options) {
  std::optional<Broadphase> broadphase;
  if (options.broadphase == "hextree") {
    return Error{"--broadphase hextree is not available yet"};
  }
  if (options.broadphase) {
    broadphase = *options.broadphase == "allpairs" ? Broadphase::kAllPairs : Broadphase::kGrid;
  }
  if (options.scene_file.empty()) {
    scenes::PresetRequest request = PresetRequestOf(options);
    request.broadphase = broadphase;
    Result<scenes::Preset> preset = scenes::MakePreset(request);
    if (!preset) return preset.error();
    return Setup{std::move(preset->scene), std::move(preset->world), preset->density};
  }
  // A scene file says everything itself; only the broad phase and the duration may be overridden.
  for (const auto& [given, name] : {std::pair{options.preset.has_value(), "--preset"},
                                    {options.n.has_value(), "--n"},
                                    {options.density.has_value(), "--density"},
                                    {options.seed.has_value(), "--seed"}}) {
    if (given) return Error{std::string(name) + " applies to presets, not to a scene file"};
  }
  Result<SceneDescription> scene = ReadScene(options.scene_file);
  if (!scene) return scene.error();
  if (broadphase) scene->settings.broadphase = *broadphase;
  Result<World> world = BuildWorld(*scene);
  if (!world) return Error{options.scene_file + ": " + world.error().message};
  const double density = PackingOf(*scene);
  return Setup{std::move(*scene), std::move(*world), density};
}

// Advances in slices so that a terminal can show progress; the slices do not change the result
// (AdvanceTo(t) processes the same events whatever the intermediate stops).
Status AdvanceWithProgress(World& world, double until) {
  const bool tty = isatty(STDERR_FILENO) != 0;
  if (!tty) return world.AdvanceTo(until);
  constexpr int kSlices = 50;
  for (int s = 1; s <= kSlices; ++s) {
    if (Status status = world.AdvanceTo(until * s / kSlices); !status) return status;
    std::fprintf(stderr, "\r  t = %-10.4g %3d%%  events %llu", world.Time(), 2 * s,
                 static_cast<unsigned long long>(world.Stats().events));
    std::fflush(stderr);
  }
  std::fprintf(stderr, "\n");
  return Status::Ok();
}

// The recording file to write: --record, or the default file for the default scene.
std::string RecordingPath(const RunOptions& options) {
  if (options.no_record) return {};
  if (!options.record_file.empty()) return options.record_file;
  const bool default_scene = options.scene_file.empty() && !options.preset;
  return default_scene ? kDefaultRecording : std::string();
}

nlohmann::json Summary(const Setup& setup, const std::string& broadphase, double wall,
                       double energy_initial, const Vec3& momentum_initial) {
  const World& world = setup.world;
  const Statistics& stats = world.Stats();
  nlohmann::json kinds = nlohmann::json::object();
  for (int k = 0; k < static_cast<int>(stats.events_by_kind.size()); ++k) {
    kinds[EventKindName(k)] = stats.events_by_kind[static_cast<std::size_t>(k)];
  }
  const double collisions = static_cast<double>(stats.collisions + stats.wall_collisions);
  return {
      {"method", "event"},
      {"preset", setup.scene.name},
      {"bodies", world.BodyCount()},
      {"density", setup.density},
      {"seed", setup.scene.seed},
      {"broadphase", broadphase},
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
      {"collisions", stats.collisions + stats.wall_collisions},
      {"body_collisions", stats.collisions},
      {"wall_collisions", stats.wall_collisions},
      {"collisions_per_second", wall > 0 ? collisions / wall : 0.0},
      {"events_per_second", wall > 0 ? static_cast<double>(stats.events) / wall : 0.0},
      {"kinetic_energy_initial", energy_initial},
      {"kinetic_energy_final", world.KineticEnergy()},
      {"momentum_initial", VectorJson(momentum_initial)},
      {"momentum_final", VectorJson(world.Momentum())},
      {"max_penetration", world.MaxPenetration()},
      {"bytes_per_body", static_cast<double>(world.MemoryBytes()) /
                             static_cast<double>(std::max<std::size_t>(1, world.BodyCount()))},
  };
}

void PrintSummary(const nlohmann::json& out) {
  const auto number = [&](const char* key) { return out[key].get<double>(); };
  std::printf("sparsedyn run: scene '%s', %zu bodies, packing %.3g, seed %llu, %s\n",
              out["preset"].get<std::string>().c_str(), out["bodies"].get<std::size_t>(),
              number("density"), static_cast<unsigned long long>(out["seed"].get<std::uint64_t>()),
              out["broadphase"].get<std::string>().c_str());
  std::printf("  simulated %.6g s in %.3f s wall: %.0f events (%.0f stale), %.0f collisions\n",
              number("simulated_time"), number("wall_seconds"), number("events"),
              number("stale_events"), number("collisions"));
  std::printf("  %.0f collisions/s, %.0f events/s, %.0f bytes per body\n",
              number("collisions_per_second"), number("events_per_second"),
              number("bytes_per_body"));
  std::printf("  kinetic energy %.17g -> %.17g, deepest overlap %.3g\n",
              number("kinetic_energy_initial"), number("kinetic_energy_final"),
              number("max_penetration"));
}

int Run(const RunOptions& options) {
  if (options.method == "conventional") return RunConventional(options);
  if (options.dt || options.digits) {
    std::cerr << "sparsedyn run: --dt and --digits apply to --method conventional\n";
    return 2;
  }
  Result<Setup> setup = MakeSetup(options);
  if (!setup) {
    std::cerr << "sparsedyn run: " << setup.error().message << "\n";
    return 2;
  }
  World& world = setup->world;
  SceneDescription& scene = setup->scene;
  const double until = options.until.value_or(scene.duration);

  // --write-scene writes the fully expanded scene (every body) and runs nothing.
  if (!options.write_scene.empty()) {
    scene.duration = until;
    if (const Status written = WriteScene(scene, options.write_scene); !written) {
      std::cerr << "sparsedyn run: --write-scene: " << written.error().message << "\n";
      return 1;
    }
    std::fprintf(stderr, "sparsedyn run: wrote %s (%zu bodies); run it with: %s run %s\n",
                 options.write_scene.c_str(), scene.bodies.size(), options.program.c_str(),
                 options.write_scene.c_str());
    return 0;
  }

  // The recording is opened before the run so that a bad path fails before any work.
  const std::string recording_path = RecordingPath(options);
  std::optional<RecordingWriter> recorder;
  if (!recording_path.empty()) {
    auto [header, bodies] = DescribeForRecording(scene, until);
    Result<RecordingWriter> writer = RecordingWriter::Open(recording_path, header, bodies);
    if (!writer) {
      std::cerr << "sparsedyn run: recording: " << writer.error().message << "\n";
      return 2;
    }
    recorder.emplace(std::move(*writer));
    recorder->Attach(world);
  }

  const double energy_initial = world.KineticEnergy();
  const Vec3 momentum_initial = world.Momentum();
  const auto start = std::chrono::steady_clock::now();
  const Status status = AdvanceWithProgress(world, until);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!status) {
    std::cerr << "sparsedyn run: " << status.error().message << "\n";
    return 1;
  }
  if (recorder) {
    if (const Status finished = recorder->Finish(world.Time()); !finished) {
      std::cerr << "sparsedyn run: recording: " << finished.error().message << "\n";
      return 1;
    }
  }

  const std::string broadphase =
      world.Settings().broadphase == Broadphase::kAllPairs ? "allpairs" : "grid";
  nlohmann::json out = Summary(*setup, broadphase, wall, energy_initial, momentum_initial);
  if (recorder) {
    out["recording"] = recording_path;
    out["recording_bytes"] = recorder->BytesWritten();
  }
  if (options.json) {
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  PrintSummary(out);
  if (recorder) {
    const double collisions = std::max(1.0, out["collisions"].get<double>());
    std::printf("  recording %s: %llu bytes (%.0f per collision)\n", recording_path.c_str(),
                static_cast<unsigned long long>(recorder->BytesWritten()),
                static_cast<double>(recorder->BytesWritten()) / collisions);
    std::printf("\nView it with:\n  %s view %s\n", options.program.c_str(), recording_path.c_str());
  }
  return 0;
}

}  // namespace

void AddRunCommand(CLI::App& app, const std::string& program) {
  auto options = std::make_shared<RunOptions>();
  options->program = program;
  CLI::App* run = app.add_subcommand(
      "run",
      "Simulate a scene event by event and print a summary. With no scene and no --preset it "
      "runs the embedded default scene and records it to " +
          std::string(kDefaultRecording) + " (see --record, --no-record)");
  run->add_option("scene", options->scene_file, "Scene file (JSON, docs/scene-format.md)");
  run->add_option("--preset", options->preset, "Preset scene")
      ->check(CLI::IsMember(scenes::PresetNames()));
  run->add_option("--n", options->n, "Number of bodies")->check(CLI::Range(1u, 100000000u));
  run->add_option("--density", options->density, "Packing fraction")
      ->check(CLI::Range(1e-9, 0.5235));
  run->add_option("--seed", options->seed, "Random seed");
  run->add_option("--until", options->until, "Simulated time to reach, s (default: the scene's)")
      ->check(CLI::Range(0.0, 1e12));
  run->add_option("--broadphase", options->broadphase, "allpairs | grid | hextree")
      ->check(CLI::IsMember({"allpairs", "grid", "hextree"}));
  run->add_flag("--json", options->json, "Print one JSON object on stdout");
  run->add_option("--record", options->record_file,
                  std::string("Write a recording (docs/recording-format.md); the default scene "
                              "records to ") +
                      kDefaultRecording + " unless --no-record");
  run->add_flag("--no-record", options->no_record, "Write no recording");
  run->add_option("--write-scene", options->write_scene,
                  "Write the scene with every body listed to this JSON file and exit "
                  "(`sparsedyn run FILE` then gives the same run)");
  run->add_option("--method", options->method,
                  "event (default: the event-driven World) | conventional (fixed steps of --dt, "
                  "collisions located by bisection to --digits more digits; polyhedra only)")
      ->check(CLI::IsMember({"event", "conventional"}));
  run->add_option("--dt", options->dt, "Time step of --method conventional, s (> 0)");
  run->add_option("--digits", options->digits,
                  "Digits the conventional method locates a collision to below the step "
                  "(default 4)")
      ->check(CLI::Range(0, 15));
  run->callback([options] { throw CLI::RuntimeError(Run(*options)); });
}

}  // namespace sparsedyn::cli
