// SPDX-License-Identifier: MIT
#include "apps/cli/progress.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>

namespace sparsedyn::cli {
namespace {

// A run shorter than this shows no progress at all (most runs of the tests and the examples).
constexpr double kQuietSeconds = 0.5;
// Slices of the simulated span: a line at least every 0.5% of the run.
constexpr int kSlices = 200;

// "42 s", "3 min 20 s", "2 h 05 min".
std::string FormatDuration(double seconds) {
  char text[32];
  const long s = static_cast<long>(seconds + 0.5);
  if (s < 60) {
    std::snprintf(text, sizeof text, "%ld s", s);
  } else if (s < 3600) {
    std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
  } else {
    std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  }
  return text;
}

}  // namespace

std::string FormatProgress(double t, double until, std::uint64_t events, double elapsed,
                           double fraction) {
  char text[160];
  const std::string left =
      fraction > 0 ? "about " + FormatDuration(elapsed * (1 - fraction) / fraction) + " left"
                   : "estimating the time left";
  std::snprintf(text, sizeof text, "  t = %.4g of %.4g s  %3.0f%%  %llu events  %s", t, until,
                100 * fraction, static_cast<unsigned long long>(events), left.c_str());
  return text;
}

Status AdvanceWithProgress(World& world, double until) {
  if (isatty(STDERR_FILENO) == 0) return world.AdvanceTo(until);
  const auto start = std::chrono::steady_clock::now();
  const double from = world.Time();
  bool shown = false;
  for (int s = 1; s <= kSlices; ++s) {
    const double fraction = static_cast<double>(s) / kSlices;
    const double stop = s == kSlices ? until : from + (until - from) * fraction;
    if (Status status = world.AdvanceTo(stop); !status) {
      if (shown) std::fprintf(stderr, "\n");
      return status;
    }
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed < kQuietSeconds || s == kSlices) continue;
    // \r and erase-to-end-of-line: the line is rewritten in place.
    std::fprintf(
        stderr, "\r%s\033[K",
        FormatProgress(world.Time(), until, world.Stats().events, elapsed, fraction).c_str());
    std::fflush(stderr);
    shown = true;
  }
  if (shown) std::fprintf(stderr, "\r\033[K");
  return Status::Ok();
}

}  // namespace sparsedyn::cli
