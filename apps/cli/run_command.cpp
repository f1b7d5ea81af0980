// SPDX-License-Identifier: MIT
#include "apps/cli/run_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "scenes/presets.hpp"
#include "sparsedyn/io/recording.hpp"

namespace sparsedyn::cli {
namespace {

struct RunOptions {
  std::string scene_file;
  std::string preset = "default";
  std::optional<std::uint32_t> n;
  std::optional<double> density;
  std::optional<std::uint64_t> seed;
  std::optional<double> until;
  std::string broadphase = "grid";
  bool json = false;
  std::string record_file;
};

nlohmann::json VectorJson(const Vec3& v) { return {v[0], v[1], v[2]}; }

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

int Run(const RunOptions& options) {
  if (!options.scene_file.empty()) {
    std::cerr << "sparsedyn run: scene files are not supported yet (issue #5): "
              << options.scene_file << "\n";
    return 2;
  }
  scenes::PresetRequest request;
  request.name = options.preset;
  request.n = options.n;
  request.density = options.density;
  request.seed = options.seed;
  request.broadphase = options.broadphase == "allpairs" ? Broadphase::kAllPairs : Broadphase::kGrid;
  if (options.broadphase == "hextree") {
    std::cerr << "sparsedyn run: --broadphase hextree is not available yet\n";
    return 2;
  }
  Result<scenes::Preset> preset = scenes::MakePreset(request);
  if (!preset) {
    std::cerr << "sparsedyn run: " << preset.error().message << "\n";
    return 2;
  }
  World& world = preset->world;
  const double until = options.until.value_or(preset->default_duration);
  const double energy_initial = world.KineticEnergy();
  const Vec3 momentum_initial = world.Momentum();

  // The recording is opened before the run so that a bad path fails before any work.
  std::optional<RecordingWriter> recorder;
  if (!options.record_file.empty()) {
    auto [header, bodies] = DescribeForRecording(world, preset->name, preset->seed, until);
    Result<RecordingWriter> writer = RecordingWriter::Open(options.record_file, header, bodies);
    if (!writer) {
      std::cerr << "sparsedyn run: --record: " << writer.error().message << "\n";
      return 2;
    }
    recorder.emplace(std::move(*writer));
    recorder->Attach(world);
  }

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
      std::cerr << "sparsedyn run: --record: " << finished.error().message << "\n";
      return 1;
    }
  }

  const Statistics& stats = world.Stats();
  nlohmann::json kinds = nlohmann::json::object();
  for (int k = 0; k < static_cast<int>(stats.events_by_kind.size()); ++k) {
    kinds[EventKindName(k)] = stats.events_by_kind[static_cast<std::size_t>(k)];
  }
  const double collisions = static_cast<double>(stats.collisions + stats.wall_collisions);
  nlohmann::json out = {
      {"preset", preset->name},
      {"bodies", world.BodyCount()},
      {"density", preset->density},
      {"seed", preset->seed},
      {"broadphase", options.broadphase},
      {"simulated_time", world.Time()},
      {"wall_seconds", wall},
      {"events", stats.events},
      {"events_by_kind", kinds},
      {"stale_events", stats.stale_target_absent + stats.stale_actor_absent},
      {"stale_target_absent", stats.stale_target_absent},
      {"stale_actor_absent", stats.stale_actor_absent},
      {"meetings", stats.meetings},
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
  if (recorder) {
    out["recording"] = options.record_file;
    out["recording_bytes"] = recorder->BytesWritten();
  }
  if (options.json) {
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  std::printf("sparsedyn run: preset '%s', %zu bodies, packing %.3g, seed %llu, %s\n",
              preset->name.c_str(), world.BodyCount(), preset->density,
              static_cast<unsigned long long>(preset->seed), options.broadphase.c_str());
  std::printf("  simulated %.6g s in %.3f s wall: %llu events (%llu stale), %.0f collisions\n",
              world.Time(), wall, static_cast<unsigned long long>(stats.events),
              static_cast<unsigned long long>(stats.stale_target_absent + stats.stale_actor_absent),
              collisions);
  std::printf("  %.0f collisions/s, %.0f events/s, %.0f bytes per body\n",
              out["collisions_per_second"].get<double>(), out["events_per_second"].get<double>(),
              out["bytes_per_body"].get<double>());
  std::printf("  kinetic energy %.17g -> %.17g, deepest overlap %.3g\n", energy_initial,
              world.KineticEnergy(), world.MaxPenetration());
  if (recorder) {
    std::printf("  recording %s: %llu bytes (%.1f per collision)\n", options.record_file.c_str(),
                static_cast<unsigned long long>(recorder->BytesWritten()),
                static_cast<double>(recorder->BytesWritten()) / std::max(1.0, collisions));
  }
  return 0;
}

}  // namespace

void AddRunCommand(CLI::App& app) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* run = app.add_subcommand("run", "Simulate a scene event by event and print a summary");
  run->add_option("scene", options->scene_file, "Scene file (JSON)");
  run->add_option("--preset", options->preset, "Preset scene")
      ->check(CLI::IsMember(scenes::PresetNames()));
  run->add_option("--n", options->n, "Number of bodies")->check(CLI::Range(1u, 100000000u));
  run->add_option("--density", options->density, "Packing fraction")
      ->check(CLI::Range(1e-9, 0.5235));
  run->add_option("--seed", options->seed, "Random seed");
  run->add_option("--until", options->until, "Simulated time to reach, s")
      ->check(CLI::Range(0.0, 1e12));
  run->add_option("--broadphase", options->broadphase, "allpairs | grid | hextree")
      ->check(CLI::IsMember({"allpairs", "grid", "hextree"}));
  run->add_flag("--json", options->json, "Print one JSON object on stdout");
  run->add_option("--record", options->record_file,
                  "Write a recording of the run (docs/recording-format.md)");
  run->callback([options] { throw CLI::RuntimeError(Run(*options)); });
}

}  // namespace sparsedyn::cli
