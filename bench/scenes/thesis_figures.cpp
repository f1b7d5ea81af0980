// SPDX-License-Identifier: MIT
// The thesis's figures on the `thesis` scene (docs/lab/measurements.md "The thesis's figures"):
//   --figure n        against N at density D: §7.0 CPU time per simulated second of sparsedyn
//                     and of the conventional method at equal accuracy, §7.1 sparsedyn's cost
//                     by phase, §7.2 collisions per simulated second, and the stale fraction;
//   --figure density  against D at fixed N: App. I.1 collisions per body per simulated second
//                     and the stale fraction.
// One CSV row per run on stdout (the conditions in every row); fits and progress on stderr.
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/support/collision_match.hpp"
#include "bench/support/least_squares.hpp"
#include "scenes/thesis.hpp"
#include "sparsedyn/conventional.hpp"
#include "sparsedyn/io/scene_file.hpp"
#include "sparsedyn/world.hpp"

namespace {

using sparsedyn::bench::CollisionRecord;
using sparsedyn::bench::PairCollision;

// Equal accuracy (docs/lab/measurements.md "The thesis's figures"): the conventional method locates a contact to within
// kTimeAccuracy by bisection, close to the World's contact tolerance (1e-9 of the summed radii
// at speeds ~1), and must find the World's collisions exactly: its step starts at kFirstDt
// (a tenth of the bounding radius at the mean speed) and is halved until it does.
constexpr double kTimeAccuracy = 1e-9;  // s
constexpr double kFirstDt = 0.1;        // s
// Two runs are "the same collision" within this time: generous next to kTimeAccuracy because
// a located time off by 1e-9 s is amplified ~10x by every later collision of the bodies (the
// scene is chaotic), yet far below any step, so a missed contact is never matched by luck.
constexpr double kMatchTolerance = 1e-4;  // s
// Two collisions of a pair this far apart are two encounters: after a bounce the bodies part at
// ~1 m/s, so within a second they are a bounding diameter apart unless they strike again.
constexpr double kEncounterGap = 1.0;  // s
// Kind indices in Statistics::events_by_kind (EventKindName order).
constexpr int kCellCrossing = 0;
constexpr int kSphereMeet = 2;

struct Options {
  std::string figure = "n";
  std::uint64_t seed = 1;
  double duration = 4.0;   // simulated s per run
  double density = 0.05;   // --figure n
  std::uint32_t n = 1000;  // --figure density
  std::vector<std::uint32_t> ns = {125, 250, 500, 1000, 2000, 4000, 8000, 16000};
  std::vector<double> densities = {0.01, 0.02, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3};
  double conventional_budget = 120;  // CPU s one conventional run may take before we stop halving
  bool conventional = true;
  int repeats = 3;  // event-driven runs per point; the least time is kept
};

double CpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// A counter as printf's %llu takes it.
unsigned long long Count(std::uint64_t value) { return value; }

[[noreturn]] void Fail(const std::string& message) {
  std::fprintf(stderr, "thesis_figures: %s\n", message.c_str());
  std::exit(1);
}

CollisionRecord Record(const sparsedyn::CollisionEvent& e) {
  if (!e.b.valid()) return {e.time, e.a.index, static_cast<std::uint32_t>(e.wall), true};
  return PairCollision(e.time, e.a.index, e.b.index);
}

sparsedyn::SceneDescription Scene(std::uint32_t n, double density, const Options& o) {
  auto scene = sparsedyn::scenes::MakeThesisScene(
      {.n = n, .packing = density, .seed = o.seed, .duration = o.duration});
  if (!scene) Fail(scene.error().message);
  return *scene;
}

// One event-driven run to o.duration: its statistics, CPU seconds and collisions.
struct EventRun {
  sparsedyn::Statistics stats;
  double cpu = 0;
  std::vector<CollisionRecord> collisions;
};

EventRun RunEventOnce(sparsedyn::SceneDescription scene, bool profile, const Options& o) {
  scene.settings.profile_phases = profile;
  auto world = sparsedyn::BuildWorld(scene);
  if (!world) Fail("BuildWorld: " + world.error().message);
  EventRun run;
  world->OnCollision(
      [&](const sparsedyn::CollisionEvent& e) { run.collisions.push_back(Record(e)); });
  const double start = CpuSeconds();
  if (auto ok = world->AdvanceTo(o.duration); !ok) Fail("AdvanceTo: " + ok.error().message);
  run.cpu = CpuSeconds() - start;
  run.stats = world->Stats();
  return run;
}

// The run repeated o.repeats times (the same events each time: deterministic), keeping the least
// CPU time and, per phase, the least seconds: other jobs on the machine only ever add time, and
// the phase timers read the wall clock, which counts the time the process waited for a core.
EventRun RunEvent(const sparsedyn::SceneDescription& scene, bool profile, const Options& o) {
  EventRun best = RunEventOnce(scene, profile, o);
  for (int k = 1; k < o.repeats; ++k) {
    const EventRun run = RunEventOnce(scene, profile, o);
    best.cpu = std::min(best.cpu, run.cpu);
    sparsedyn::Statistics& s = best.stats;
    s.seconds_sparse = std::min(s.seconds_sparse, run.stats.seconds_sparse);
    s.seconds_detailed = std::min(s.seconds_detailed, run.stats.seconds_detailed);
    s.seconds_response = std::min(s.seconds_response, run.stats.seconds_response);
    s.seconds_queue = std::min(s.seconds_queue, run.stats.seconds_queue);
  }
  return best;
}

// The equal-accuracy search's outcome: the step it ended at and whether that step was equal.
struct ConventionalRun {
  double dt = 0;
  int digits = 0;
  int halvings = 0;
  bool equal = false;
  double cpu = 0;
  std::uint64_t collisions = 0;
  sparsedyn::ConventionalStatistics stats;
  sparsedyn::bench::CollisionMatch match;
};

// The bisection digits A2 that locate a contact to kTimeAccuracy from a step dt.
int DigitsFor(double dt) {
  return std::clamp(static_cast<int>(std::ceil(std::log10(dt / kTimeAccuracy) - 1e-9)), 0, 15);
}

ConventionalRun RunConventionalOnce(const sparsedyn::SceneDescription& scene, double dt,
                                    const EventRun& reference, const Options& o) {
  ConventionalRun run{.dt = dt, .digits = DigitsFor(dt)};
  sparsedyn::ConventionalWorld world(scene.settings, {.dt = dt, .digits = run.digits});
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (auto id = world.AddBody(sparsedyn::SceneBodyDef(scene, i)); !id) {
      Fail("conventional AddBody: " + id.error().message);
    }
  }
  std::vector<CollisionRecord> found;
  world.OnCollision([&](const sparsedyn::CollisionEvent& e) { found.push_back(Record(e)); });
  const double start = CpuSeconds();
  if (auto ok = world.AdvanceTo(o.duration); !ok) Fail("conventional: " + ok.error().message);
  run.cpu = CpuSeconds() - start;
  run.collisions = found.size();
  run.stats = world.Stats();
  run.match = sparsedyn::bench::MatchCollisions(reference.collisions, found, kMatchTolerance);
  run.equal = run.match.Same();
  return run;
}

// Halves dt from kFirstDt until the conventional run finds the World's collisions, or until the
// next run would exceed the CPU budget (then the last, unequal, run is reported).
ConventionalRun SearchEqualAccuracy(const sparsedyn::SceneDescription& scene,
                                    const EventRun& reference, const Options& o) {
  ConventionalRun run;
  for (int halvings = 0;; ++halvings) {
    run = RunConventionalOnce(scene, kFirstDt * std::pow(0.5, halvings), reference, o);
    run.halvings = halvings;
    std::fprintf(stderr,
                 "  conventional dt=%g digits=%d cpu=%.2fs collisions=%llu missing=%llu "
                 "spurious=%llu\n",
                 run.dt, run.digits, run.cpu, Count(run.collisions), Count(run.match.missing),
                 Count(run.match.spurious));
    if (run.equal || 2 * run.cpu > o.conventional_budget) return run;
  }
}

double StaleFraction(const sparsedyn::Statistics& s, bool without_cells) {
  const double stale = static_cast<double>(s.stale_target_absent + s.stale_actor_absent);
  const auto events =
      static_cast<double>(s.events - (without_cells ? s.events_by_kind[kCellCrossing] : 0));
  return events > 0 ? stale / events : 0.0;
}

// Of the sphere-meet events taken from the queue, the stale ones: the thesis's events (§4.2)
// have no cell crossings, engagements or wall meets to dilute them.
double StaleOfSphereMeets(const sparsedyn::Statistics& s) {
  const auto meets = static_cast<double>(s.events_by_kind[kSphereMeet]);
  return meets > 0 ? static_cast<double>(s.stale_target_absent) / meets : 0.0;
}

// Columns common to both figures: conditions, then sparsedyn's counters per simulated second.
const char* kCommonHeader =
    "figure,seed,duration,n,density,sparsedyn_cpu_per_sim_s,events,cell_crossings,"
    "stale_target_absent,stale_actor_absent,stale_fraction,stale_fraction_no_cells,"
    "stale_of_sphere_meets,meetings,"
    "collisions,wall_collisions,collisions_per_s,collisions_per_body_s,meetings_per_body_s,"
    "encounters,encounters_per_body_s";

void PrintCommon(const char* figure, std::uint32_t n, double density, const EventRun& r,
                 const Options& o) {
  const sparsedyn::Statistics& s = r.stats;
  const double t = o.duration;
  const std::uint64_t encounters = sparsedyn::bench::CountEncounters(r.collisions, kEncounterGap);
  std::printf(
      "%s,%llu,%g,%u,%g,%.6g,%llu,%llu,%llu,%llu,%.4f,%.4f,%.4f,%llu,%llu,%llu,%.6g,%.6g,%.6g,%llu,"
      "%.6g",
      figure, Count(o.seed), t, n, density, r.cpu / t, Count(s.events),
      Count(s.events_by_kind[kCellCrossing]), Count(s.stale_target_absent),
      Count(s.stale_actor_absent), StaleFraction(s, false), StaleFraction(s, true),
      StaleOfSphereMeets(s), Count(s.meetings), Count(s.collisions), Count(s.wall_collisions),
      static_cast<double>(s.collisions) / t, static_cast<double>(s.collisions) / (n * t),
      static_cast<double>(s.meetings) / (n * t), Count(encounters),
      static_cast<double>(encounters) / (n * t));
}

void FigureN(const Options& o) {
  std::printf(
      "%s,sparse_s_per_sim_s,detailed_s_per_sim_s,response_s_per_sim_s,"
      "queue_s_per_sim_s,profiled_cpu_per_sim_s,conv_dt,conv_digits,conv_equal,"
      "conv_halvings,conv_cpu_per_sim_s,conv_collisions,conv_missing,conv_spurious,"
      "conv_over_sparsedyn,conv_steps,conv_pair_tests,conv_narrow_queries,"
      "conv_bisection_evaluations\n",
      kCommonHeader);
  std::vector<double> xs, ys;
  for (std::uint32_t n : o.ns) {
    std::fprintf(stderr, "N=%u D=%g\n", n, o.density);
    const sparsedyn::SceneDescription scene = Scene(n, o.density, o);
    const EventRun plain = RunEvent(scene, false, o);
    const EventRun profiled = RunEvent(scene, true, o);
    const sparsedyn::Statistics& p = profiled.stats;
    const double t = o.duration;
    PrintCommon("n", n, o.density, plain, o);
    std::printf(",%.6g,%.6g,%.6g,%.6g,%.6g", p.seconds_sparse / t, p.seconds_detailed / t,
                p.seconds_response / t, p.seconds_queue / t, profiled.cpu / t);
    if (o.conventional) {
      const ConventionalRun c = SearchEqualAccuracy(scene, plain, o);
      std::printf(",%g,%d,%d,%d,%.6g,%llu,%llu,%llu,%.4g,%llu,%llu,%llu,%llu\n", c.dt, c.digits,
                  c.equal ? 1 : 0, c.halvings, c.cpu / t, Count(c.collisions),
                  Count(c.match.missing), Count(c.match.spurious), c.cpu / plain.cpu,
                  Count(c.stats.steps), Count(c.stats.pair_tests), Count(c.stats.narrow_queries),
                  Count(c.stats.bisection_evaluations));
    } else {
      std::printf(",,,,,,,,,,,,,\n");
    }
    std::fflush(stdout);
    xs.push_back(n);
    ys.push_back(static_cast<double>(plain.stats.collisions) / t);
  }
  if (xs.size() >= 2) {
    const auto fit = sparsedyn::bench::FitLine(xs, ys);
    std::fprintf(stderr, "fit,7.2,collisions_per_s = %.6g + %.6g N,R2=%.5f\n", fit.intercept,
                 fit.slope, fit.r2);
  }
}

void FigureDensity(const Options& o) {
  std::printf("%s,law_x,box_side,density_accessible,law_x_accessible\n", kCommonHeader);
  std::vector<double> xs, xs_accessible, collisions, encounters;
  for (double d : o.densities) {
    std::fprintf(stderr, "N=%u D=%g\n", o.n, d);
    const EventRun run = RunEvent(Scene(o.n, d, o), false, o);
    const double x = d / (1 - d);  // App. I.1: C/N proportional to D/(1 - D)
    // A centre stays a bounding radius (1) from the walls: the spheres fill the box of side
    // L - 2 that their centres can reach to L^3 / (L - 2)^3 times D, not D.
    const double side = sparsedyn::scenes::ThesisBoxSide({.n = o.n, .packing = d});
    const double accessible = d * std::pow(side / (side - 2), 3);
    const double x_accessible = accessible / (1 - accessible);
    PrintCommon("density", o.n, d, run, o);
    std::printf(",%.6g,%.6g,%.6g,%.6g\n", x, side, accessible, x_accessible);
    std::fflush(stdout);
    xs.push_back(x);
    xs_accessible.push_back(x_accessible);
    collisions.push_back(static_cast<double>(run.stats.collisions) / (o.n * o.duration));
    encounters.push_back(
        static_cast<double>(sparsedyn::bench::CountEncounters(run.collisions, kEncounterGap)) /
        (o.n * o.duration));
  }
  if (xs.size() >= 2) {
    const auto c = sparsedyn::bench::FitProportional(xs, collisions);
    const auto e = sparsedyn::bench::FitProportional(xs, encounters);
    std::fprintf(stderr, "fit,I.1,collisions_per_body_s = %.5g D/(1-D),R2=%.5f\n", c.k, c.r2);
    std::fprintf(stderr, "fit,I.1,encounters_per_body_s = %.5g D/(1-D),R2=%.5f\n", e.k, e.r2);
    const auto ca = sparsedyn::bench::FitProportional(xs_accessible, collisions);
    const auto ea = sparsedyn::bench::FitProportional(xs_accessible, encounters);
    std::fprintf(stderr,
                 "fit,I.1,collisions_per_body_s = %.5g Da/(1-Da),R2=%.5f (Da: accessible "
                 "box)\n",
                 ca.k, ca.r2);
    std::fprintf(stderr,
                 "fit,I.1,encounters_per_body_s = %.5g Da/(1-Da),R2=%.5f (Da: accessible "
                 "box)\n",
                 ea.k, ea.r2);
    std::fprintf(stderr, "law,I.1,3 sqrt(2)/2 = %.5g (spheres of the bounding radius)\n",
                 1.5 * std::sqrt(2.0));
  }
}

template <typename T>
std::vector<T> ParseList(const std::string& text) {
  std::vector<T> values;
  for (std::size_t at = 0; at < text.size();) {
    std::size_t end = text.find(',', at);
    if (end == std::string::npos) end = text.size();
    values.push_back(static_cast<T>(std::stod(text.substr(at, end - at))));
    at = end + 1;
  }
  return values;
}

Options Parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto next = [&]() -> std::string {
      if (i + 1 >= argc) Fail("missing value after " + arg);
      return argv[++i];
    };
    if (arg == "--figure")
      o.figure = next();
    else if (arg == "--seed")
      o.seed = std::stoull(next());
    else if (arg == "--duration")
      o.duration = std::stod(next());
    else if (arg == "--density")
      o.density = std::stod(next());
    else if (arg == "--n")
      o.n = static_cast<std::uint32_t>(std::stoul(next()));
    else if (arg == "--ns")
      o.ns = ParseList<std::uint32_t>(next());
    else if (arg == "--densities")
      o.densities = ParseList<double>(next());
    else if (arg == "--budget")
      o.conventional_budget = std::stod(next());
    else if (arg == "--no-conventional")
      o.conventional = false;
    else if (arg == "--repeats")
      o.repeats = std::max(1, std::stoi(next()));
    else if (arg == "--large")
      o.ns.insert(o.ns.end(), {32000, 64000});
    else if (arg == "--quick") {
      o.ns = {125, 250, 500, 1000, 2000};
      o.densities = {0.02, 0.05, 0.1, 0.2};
      o.n = 250;
      o.duration = 2.0;
      o.conventional_budget = 5;
      o.repeats = 1;
    } else {
      Fail(
          "usage: thesis_figures [--figure n|density] [--quick] [--large] [--seed S] "
          "[--duration T] [--density D] [--ns N,N,..] [--n N] [--densities D,D,..] "
          "[--budget CPU_S] [--no-conventional] [--repeats K]");
    }
  }
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = Parse(argc, argv);
  if (o.figure == "n")
    FigureN(o);
  else if (o.figure == "density")
    FigureDensity(o);
  else
    Fail("--figure must be n or density");
  return 0;
}
