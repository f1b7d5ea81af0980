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
#include "apps/cli/progress.hpp"
#include "apps/cli/run_options.hpp"
#include "apps/cli/run_support.hpp"
#include "scenes/presets.hpp"
#include "sparsedyn/io/recording.hpp"
#include "sparsedyn/io/run_summary.hpp"
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

// The recording file to write: --record, or the default file for the default scene.
std::string RecordingPath(const RunOptions& options) {
  if (options.no_record) return {};
  if (!options.record_file.empty()) return options.record_file;
  const bool default_scene = options.scene_file.empty() && !options.preset;
  return default_scene ? kDefaultRecording : std::string();
}

// The summary every run reports (RunSummaryJson, shared with the Python package).
nlohmann::json Summary(const Setup& setup, double wall, double energy_initial,
                       const Vec3& momentum_initial) {
  const RunContext context{.preset = setup.scene.name,
                           .density = setup.density,
                           .seed = setup.scene.seed,
                           .wall_seconds = wall,
                           .kinetic_energy_initial = energy_initial,
                           .momentum_initial = momentum_initial};
  return nlohmann::json::parse(RunSummaryJson(setup.world, context));
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
  const double until = options.until.value_or(scene.EndTime());
  if (until < scene.settings.start_time) {
    std::cerr << "sparsedyn run: --until " << until << " is before the scene's start_time "
              << scene.settings.start_time << "\n";
    return 2;
  }
  if (const Status clock = CheckClockResolution(world, until); !clock) {
    std::cerr << "sparsedyn run: " << (options.until ? "--until" : "duration") << ": "
              << clock.error().message << "\n";
    return 2;
  }

  // --write-scene writes the fully expanded scene (every body) and runs nothing.
  if (!options.write_scene.empty()) {
    scene.duration = until - scene.settings.start_time;
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
  // A failed run keeps what it did: the recording ends at the last processed event (where the
  // clock stopped), the summary is printed with the error, and the exit status says it failed.
  if (!status) std::cerr << "sparsedyn run: " << status.error().message << "\n";
  const int exit_status = status ? 0 : 1;
  if (recorder) {
    if (const Status finished = recorder->Finish(world.Time()); !finished) {
      std::cerr << "sparsedyn run: recording: " << finished.error().message << "\n";
      return 1;
    }
  }

  nlohmann::json out = Summary(*setup, wall, energy_initial, momentum_initial);
  if (recorder) {
    out["recording"] = recording_path;
    out["recording_bytes"] = recorder->BytesWritten();
  }
  if (!status) out["error"] = status.error().message;
  if (options.json) {
    std::cout << out.dump(2) << "\n";
    return exit_status;
  }
  PrintSummary(out);
  if (!status) {
    std::printf("  stopped by an error at t = %.17g: %s\n", world.Time(),
                status.error().message.c_str());
  }
  if (recorder) {
    const double collisions = std::max(1.0, out["collisions"].get<double>());
    std::printf("  recording %s: %llu bytes (%.0f per collision)\n", recording_path.c_str(),
                static_cast<unsigned long long>(recorder->BytesWritten()),
                static_cast<double>(recorder->BytesWritten()) / collisions);
    std::printf("\nView it with:\n  %s view %s\n", options.program.c_str(), recording_path.c_str());
  }
  return exit_status;
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
  run->add_option("--broadphase", options->broadphase, "allpairs | grid")
      ->check(CLI::IsMember({"allpairs", "grid"}));
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
