// SPDX-License-Identifier: MIT
#include "apps/cli/run_command.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "apps/cli/conventional_run.hpp"
#include "apps/cli/progress.hpp"
#include "apps/cli/run_options.hpp"
#include "apps/cli/run_support.hpp"
#include "apps/cli/scene_output.hpp"
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
  double density = 0;       // packing fraction reported as "density"
  std::vector<BodyId> ids;  // the handle of every scene body, in the scene's order
};

// The handles of a World's bodies just after it was built: scene body i is in slot i.
std::vector<BodyId> Handles(const World& world) {
  std::vector<BodyId> ids;
  ids.reserve(world.BodyCount());
  for (std::uint32_t i = 0; i < world.BodyCount(); ++i) ids.push_back(world.IdOf(i));
  return ids;
}

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
    std::vector<BodyId> ids = Handles(preset->world);
    return Setup{std::move(preset->scene), std::move(preset->world), preset->density,
                 std::move(ids)};
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
  std::vector<BodyId> ids = Handles(*world);
  return Setup{std::move(*scene), std::move(*world), density, std::move(ids)};
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

// Options that cannot go together, and output paths that cannot be written, before any work.
Status CheckOptions(const RunOptions& options) {
  if (options.dt || options.digits) {
    return Error{"--dt and --digits apply to --method conventional"};
  }
  if (!options.write_scene.empty() && !options.write_final_scene.empty()) {
    return Error{"--write-scene runs nothing, --write-final-scene writes after a run: give one"};
  }
  for (const auto& [path, name] : {std::pair{&options.write_scene, "--write-scene"},
                                   {&options.write_final_scene, "--write-final-scene"}}) {
    if (path->empty()) continue;
    if (Status ok = CheckScenePath(*path); !ok) {
      return Error{std::string(name) + ": " + ok.error().message};
    }
  }
  return Status::Ok();
}

// The time the run advances to: --until (absolute) or the scene's start_time + duration.
Result<double> EndTimeOf(const RunOptions& options, const Setup& setup) {
  const double until = options.until.value_or(setup.scene.EndTime());
  const double start = setup.scene.settings.start_time;
  const char* name = options.until ? "--until" : "duration";
  if (until < start) {
    std::ostringstream message;
    message << std::setprecision(17) << name << " " << until << " is before the scene's start_time "
            << start;
    return Error{message.str()};
  }
  if (const Status clock = CheckClockResolution(setup.world, until); !clock) {
    return Error{std::string(name) + ": " + clock.error().message};
  }
  return until;
}

// --write-scene: the fully expanded scene (every body) to run until `until`; runs nothing.
int WriteStartScene(const RunOptions& options, SceneDescription scene, double until) {
  scene.duration = until - scene.settings.start_time;
  const std::size_t bodies = scene.bodies.size();
  if (const Status written =
          WriteSceneFile(std::move(scene), options.scene_file, options.write_scene);
      !written) {
    std::cerr << "sparsedyn run: --write-scene: " << written.error().message << "\n";
    return 1;
  }
  std::fprintf(stderr, "sparsedyn run: wrote %s (%zu bodies); run it with: %s run %s\n",
               options.write_scene.c_str(), bodies, options.program.c_str(),
               options.write_scene.c_str());
  return 0;
}

// The recording of the run (--record, or the default scene's), opened before the run so that
// a bad path fails before any work; nullopt when none is asked for, an Error when it fails.
Result<std::optional<RecordingWriter>> OpenRecording(const std::string& path, Setup& setup,
                                                     double until) {
  if (path.empty()) return std::optional<RecordingWriter>{};
  auto [header, bodies] = DescribeForRecording(setup.scene, until);
  Result<RecordingWriter> writer = RecordingWriter::Open(path, header, bodies);
  if (!writer) return writer.error();
  writer->Attach(setup.world);
  return std::optional<RecordingWriter>(std::move(*writer));
}

// --write-final-scene after a run that succeeded; the Error says why nothing was written.
Status WriteFinalSceneOf(const RunOptions& options, const Setup& setup, const Status& run) {
  if (!run) return Error{"not written: the run stopped with an error"};
  return WriteFinalScene(setup.scene, options.scene_file, setup.world, setup.ids,
                         options.write_final_scene);
}

// Prints the summary (JSON or text) and returns the exit status.
int Report(const RunOptions& options, const nlohmann::json& out, const Status& status,
           double clock) {
  const int exit_status = status ? 0 : 1;
  if (options.json) {
    std::cout << out.dump(2) << "\n";
    return exit_status;
  }
  PrintSummary(out);
  if (!status) {
    std::printf("  stopped by an error at t = %.17g: %s\n", clock, status.error().message.c_str());
  }
  if (out.contains("final_scene")) {
    std::printf("  final scene %s: run on with %s run %s --until T\n",
                options.write_final_scene.c_str(), options.program.c_str(),
                options.write_final_scene.c_str());
  }
  if (out.contains("recording")) {
    const std::string path = out["recording"].get<std::string>();
    const double bytes = out["recording_bytes"].get<double>();
    std::printf("  recording %s: %.0f bytes (%.0f per collision)\n", path.c_str(), bytes,
                bytes / std::max(1.0, out["collisions"].get<double>()));
    std::printf("\nView it with:\n  %s view %s\n", options.program.c_str(), path.c_str());
  }
  return exit_status;
}

int Run(const RunOptions& options) {
  if (options.method == "conventional") return RunConventional(options);
  if (Status checked = CheckOptions(options); !checked) {
    std::cerr << "sparsedyn run: " << checked.error().message << "\n";
    return 2;
  }
  Result<Setup> setup = MakeSetup(options);
  if (!setup) {
    std::cerr << "sparsedyn run: " << setup.error().message << "\n";
    return 2;
  }
  const Result<double> until = EndTimeOf(options, *setup);
  if (!until) {
    std::cerr << "sparsedyn run: " << until.error().message << "\n";
    return 2;
  }
  if (!options.write_scene.empty()) return WriteStartScene(options, setup->scene, *until);
  const std::string recording_path = RecordingPath(options);
  Result<std::optional<RecordingWriter>> recorder = OpenRecording(recording_path, *setup, *until);
  if (!recorder) {
    std::cerr << "sparsedyn run: recording: " << recorder.error().message << "\n";
    return 2;
  }

  World& world = setup->world;
  const double energy_initial = world.KineticEnergy();
  const Vec3 momentum_initial = world.Momentum();
  const auto start = std::chrono::steady_clock::now();
  const Status status = AdvanceWithProgress(world, *until);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // A failed run keeps what it did: the recording ends at the last processed event (where the
  // clock stopped), the summary is printed with the error, and the exit status says it failed.
  if (!status) std::cerr << "sparsedyn run: " << status.error().message << "\n";
  nlohmann::json out = Summary(*setup, wall, energy_initial, momentum_initial);
  if (*recorder) {
    if (const Status finished = (*recorder)->Finish(world.Time()); !finished) {
      std::cerr << "sparsedyn run: recording: " << finished.error().message << "\n";
      return 1;
    }
    out["recording"] = recording_path;
    out["recording_bytes"] = (*recorder)->BytesWritten();
  }
  if (!options.write_final_scene.empty()) {
    if (const Status written = WriteFinalSceneOf(options, *setup, status); !written) {
      std::cerr << "sparsedyn run: --write-final-scene: " << written.error().message << "\n";
      if (status) return 1;
    } else {
      out["final_scene"] = options.write_final_scene;
    }
  }
  if (!status) out["error"] = status.error().message;
  return Report(options, out, status, world.Time());
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
  run->add_option("--write-final-scene", options->write_final_scene,
                  "After the run, write the World at the end time to this JSON file as a scene "
                  "that runs on from there (`sparsedyn run FILE --until T`)");
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
