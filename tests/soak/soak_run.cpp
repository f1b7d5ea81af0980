// SPDX-License-Identifier: MIT
// The soak (issue #39 part 5, scripts/soak.sh, docs/reliability.md): one long run of a preset
// with World::Validate() every 10^4 events, watching what must not move over 10^8 collisions:
// the kinetic energy of an elastic world and, in a periodic box, its momentum (round-off only;
// max_momentum_drift stays 0 in a walled box, whose walls take momentum), and memory (the World's
// own MemoryBytes and the process's resident set, after the first tenth of the run).
//   sparsedyn_soak gas|thesis COLLISIONS [N]
// Prints one JSON line per tenth of the run and a final JSON object; exits 1 when an invariant
// broke, the drift passed its bound or memory grew.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "scenes/presets.hpp"
#include "sparsedyn/world.hpp"

namespace {

constexpr std::uint64_t kEventsPerValidation = 10000;
// Relative energy drift allowed over the whole run: each elastic collision conserves energy to
// a few ulps and the errors do not add up coherently, so 10^8 collisions drift ~1e-10 at most.
constexpr double kMaxRelativeDrift = 1e-8;
// Memory may not grow by more than this after the first tenth, plus a fixed slack for the
// allocator's own steps (a 10^4-body gas steps its resident set once by ~1.2 MiB, at a
// Validate(), and stays there); a leak of a few bytes per event over 10^8 collisions is far
// beyond both.
constexpr double kMaxMemoryGrowth = 1.05;
constexpr double kResidentSlackKiB = 2048;

long ResidentKiB() {
  std::ifstream statm("/proc/self/statm");
  long size = 0, resident = 0;
  statm >> size >> resident;
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

double Collisions(const sparsedyn::World& world) {
  return static_cast<double>(world.Stats().collisions + world.Stats().wall_collisions);
}

struct Watch {
  double energy0 = 0, max_drift = 0, max_momentum_drift = 0;
  sparsedyn::Vec3 momentum0 = sparsedyn::Vec3::Zero();
  long rss_base = 0;
  std::size_t bytes_base = 0;
  std::uint64_t validations = 0;
};

void PrintLine(const sparsedyn::World& world, const Watch& watch, double wall, bool last) {
  std::printf(
      "{\"%s\": true, \"collisions\": %.0f, \"events\": %llu, \"time\": %.17g, "
      "\"validations\": %llu, \"max_relative_energy_drift\": %.3e, "
      "\"max_momentum_drift\": %.3e, \"rss_kib\": %ld, \"rss_kib_base\": %ld, "
      "\"memory_bytes\": %zu, \"memory_bytes_base\": %zu, \"wall_seconds\": %.1f}\n",
      last ? "final" : "progress", Collisions(world),
      static_cast<unsigned long long>(world.Stats().events), world.Time(),
      static_cast<unsigned long long>(watch.validations), watch.max_drift, watch.max_momentum_drift,
      ResidentKiB(), watch.rss_base, world.MemoryBytes(), watch.bytes_base, wall);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: sparsedyn_soak gas|thesis COLLISIONS [N]\n");
    return 2;
  }
  sparsedyn::scenes::PresetRequest request;
  request.name = argv[1];
  const double target = std::strtod(argv[2], nullptr);
  if (argc > 3) request.n = static_cast<std::uint32_t>(std::strtoul(argv[3], nullptr, 10));
  sparsedyn::Result<sparsedyn::scenes::Preset> preset = sparsedyn::scenes::MakePreset(request);
  if (!preset) {
    std::fprintf(stderr, "sparsedyn_soak: %s\n", preset.error().message.c_str());
    return 2;
  }
  sparsedyn::World& world = preset->world;
  Watch watch;
  watch.energy0 = world.KineticEnergy();
  watch.momentum0 = world.Momentum();
  // Momentum relative to the sum of the bodies' momentum magnitudes' scale sqrt(2 E N m).
  const double momentum_scale =
      std::sqrt(2 * watch.energy0 * static_cast<double>(world.BodyCount()));
  const bool periodic = world.Settings().container.kind == sparsedyn::Container::Kind::kPeriodicBox;

  // Slices of simulated time sized to ~10^4 events each, from the rate of the slice before.
  const auto start = std::chrono::steady_clock::now();
  double slice = 1e-3;
  double next_report = target / 10;
  while (Collisions(world) < target) {
    const std::uint64_t events_before = world.Stats().events;
    if (sparsedyn::Status status = world.AdvanceTo(world.Time() + slice); !status) {
      std::fprintf(stderr, "sparsedyn_soak: %s\n", status.error().message.c_str());
      return 1;
    }
    const auto events = static_cast<double>(world.Stats().events - events_before);
    slice *=
        std::clamp(static_cast<double>(kEventsPerValidation) / std::max(events, 1.0), 0.5, 2.0);
    ++watch.validations;
    if (sparsedyn::Status valid = world.Validate(); !valid) {
      std::fprintf(stderr, "sparsedyn_soak: invariant broken at t = %.17g: %s\n", world.Time(),
                   valid.error().message.c_str());
      return 1;
    }
    watch.max_drift =
        std::max(watch.max_drift, std::abs(world.KineticEnergy() - watch.energy0) / watch.energy0);
    // Walls exchange momentum with the bodies: only a periodic box conserves it.
    if (periodic) {
      watch.max_momentum_drift = std::max(
          watch.max_momentum_drift, (world.Momentum() - watch.momentum0).norm() / momentum_scale);
    }
    if (Collisions(world) >= next_report) {
      if (watch.rss_base == 0) {
        watch.rss_base = ResidentKiB();  // after the first tenth: what the run settled at
        watch.bytes_base = world.MemoryBytes();
      }
      next_report += target / 10;
      const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
      PrintLine(world, watch, wall.count(), false);
    }
  }
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
  PrintLine(world, watch, wall.count(), true);

  bool ok = true;
  if (watch.max_drift > kMaxRelativeDrift) {
    std::fprintf(stderr, "sparsedyn_soak: energy drifted by %.3e (bound %.1e)\n", watch.max_drift,
                 kMaxRelativeDrift);
    ok = false;
  }
  if (static_cast<double>(ResidentKiB()) >
          kMaxMemoryGrowth * static_cast<double>(watch.rss_base) + kResidentSlackKiB ||
      static_cast<double>(world.MemoryBytes()) >
          kMaxMemoryGrowth * static_cast<double>(watch.bytes_base)) {
    std::fprintf(stderr, "sparsedyn_soak: memory grew after the first tenth of the run\n");
    ok = false;
  }
  return ok ? 0 : 1;
}
