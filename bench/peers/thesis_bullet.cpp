// SPDX-License-Identifier: MIT
// The thesis scene (scenes/thesis.hpp) in Bullet and in sparsedyn, one CSV line per run
// (docs/lab/measurements.md "The thesis scene against Bullet"; scripts/bench-thesis.sh runs it).
//   thesis_bullet [--n N] [--density D] [--seed S] [--duration T] [--dt 60hz|SECONDS]...
//                 [--no-sparsedyn] [--no-bullet] [--header]
// Bullet runs once per --dt (default: 1/60 s and 0.01 s, a hundredth of a radius at mean speed
// 1). Only stepSimulation is timed; energy and the contact probe are measured between steps.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <optional>
#include <string>
#include <vector>

#include "bench/peers/thesis/bullet_world.hpp"
#include "bench/peers/thesis/contact_probe.hpp"
#include "scenes/thesis.hpp"

namespace sparsedyn::bench {
namespace {

using Clock = std::chrono::steady_clock;

// How often sparsedyn's poses are probed: Bullet's smaller step.
constexpr double kProbeStep = 0.01;

// CPU seconds of this thread: on a shared machine the wall clock also counts the time other
// processes held the core, so both are reported.
double ThreadCpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

struct Options {
  scenes::ThesisOptions scene;
  double duration = 2.0;
  std::vector<double> steps;  // dt of each Bullet run, s
  bool sparsedyn = true;
  bool bullet = true;
  bool header = false;
};

// What one engine did over the run; fields an engine does not report stay empty.
struct RunResult {
  std::string engine;
  std::optional<double> dt;
  std::uint64_t steps = 0;  // Bullet steps, or sparsedyn events
  double wall = 0;          // s spent in stepSimulation / AdvanceTo
  double cpu = 0;           // thread CPU s of the same
  // The start-up part of `cpu`: sparsedyn's initial prediction of every element (its first
  // AdvanceTo, to t = 0), Bullet's first step (which builds its pair cache) covering dt of it.
  double startup_cpu = 0;
  double startup_sim = 0;
  double energy_drift = 0, max_energy_drift = 0, max_penetration = 0;
  std::optional<ProbeTotals> probe;
  std::optional<std::uint64_t> collisions;
};

[[noreturn]] void Usage(const char* program) {
  std::fprintf(stderr,
               "usage: %s [--n N] [--density D] [--seed S] [--duration T] [--dt 60hz|SECONDS]... "
               "[--no-sparsedyn] [--no-bullet] [--header]\n",
               program);
  std::exit(2);
}

Options Parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) Usage(argv[0]);
      return argv[++i];
    };
    if (arg == "--n")
      o.scene.n = static_cast<std::uint32_t>(std::stoul(value()));
    else if (arg == "--density")
      o.scene.packing = std::stod(value());
    else if (arg == "--seed")
      o.scene.seed = std::stoull(value());
    else if (arg == "--duration")
      o.duration = std::stod(value());
    else if (arg == "--dt") {
      const std::string v = value();
      o.steps.push_back(v == "60hz" ? 1.0 / 60.0 : std::stod(v));
    } else if (arg == "--no-sparsedyn")
      o.sparsedyn = false;
    else if (arg == "--no-bullet")
      o.bullet = false;
    else if (arg == "--header")
      o.header = true;
    else
      Usage(argv[0]);
  }
  if (o.steps.empty()) o.steps = {1.0 / 60.0, 0.01};
  return o;
}

// Our World from the same scene; nullopt (with the reason on stdout) while BuildWorld refuses
// polyhedra (issue #4). It advances in slices of `probe_dt` (AdvanceTo processes the same events
// whatever the stops) so that the contact probe sees its poses as often as Bullet's.
std::optional<RunResult> RunSparsedyn(const SceneDescription& scene, double duration,
                                      double probe_dt) {
  Result<World> world = BuildWorld(scene);
  if (!world) {
    std::printf("sparsedyn: unavailable: %s\n", world.error().message.c_str());
    return std::nullopt;
  }
  RunResult run{.engine = "sparsedyn"};
  ContactProbe probe(scene);
  std::vector<Pose> poses(world->BodyCount());
  const double energy = world->KineticEnergy();
  const auto slices = static_cast<std::uint64_t>(std::llround(duration / probe_dt));
  {
    const Clock::time_point start = Clock::now();
    const double cpu_start = ThreadCpuSeconds();
    const Status started = world->AdvanceTo(0.0);
    run.startup_cpu = ThreadCpuSeconds() - cpu_start;
    run.cpu += run.startup_cpu;
    run.wall += std::chrono::duration<double>(Clock::now() - start).count();
    if (!started) {
      std::printf("sparsedyn: failed: %s\n", started.error().message.c_str());
      return std::nullopt;
    }
  }
  for (std::uint64_t k = 1; k <= slices; ++k) {
    const double t = k == slices ? duration : static_cast<double>(k) * probe_dt;
    const Clock::time_point start = Clock::now();
    const double cpu_start = ThreadCpuSeconds();
    const Status advanced = world->AdvanceTo(t);
    run.cpu += ThreadCpuSeconds() - cpu_start;
    run.wall += std::chrono::duration<double>(Clock::now() - start).count();
    if (!advanced) {
      std::printf("sparsedyn: failed: %s\n", advanced.error().message.c_str());
      return std::nullopt;
    }

    // Untimed: energy and the contact probe.
    const double drift = (world->KineticEnergy() - energy) / energy;
    run.max_energy_drift = std::max(run.max_energy_drift, std::abs(drift));
    run.energy_drift = drift;
    for (std::uint32_t i = 0; i < poses.size(); ++i) {
      const BodyState state = world->StateAt(world->IdOf(i), t);
      poses[i].rotation = state.orientation;
      poses[i].translation = state.position;
    }
    probe.Measure(poses);
  }
  run.steps = world->Stats().events;
  run.probe = probe.Finish();
  run.max_penetration = std::max(world->MaxPenetration(), run.probe->max_penetration);
  run.collisions = world->Stats().collisions + world->Stats().wall_collisions;
  return run;
}

// The scene's own kinetic energy, from our inertia tensor in the world frame.
double SceneKineticEnergy(const SceneDescription& scene) {
  double energy = 0;
  for (const SceneBody& body : scene.bodies) {
    const ConvexPolyhedron& p = *scene.shapes[body.shape].polyhedron;
    const Eigen::Matrix3d R = body.orientation.toRotationMatrix();
    const Eigen::Matrix3d I_W = body.mass / p.volume() * R * p.inertia() * R.transpose();
    energy += 0.5 * body.mass * body.velocity.squaredNorm() +
              0.5 * body.angular_velocity.dot(I_W * body.angular_velocity);
  }
  return energy;
}

// Bullet must start from our scene: the same poses and the same energy (which checks the
// masses and the inertia handed over through the principal frames). False with a message if not.
bool StartsFromTheScene(const SceneDescription& scene, const BulletThesisWorld& world) {
  constexpr double kTolerance = 1e-9;  // a few rotations and an eigen-decomposition of round-off
  double pose_error = 0;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Pose X_WB = world.PoseOf(i);
    pose_error = std::max({pose_error, (X_WB.translation - scene.bodies[i].position).norm(),
                           X_WB.rotation.angularDistance(scene.bodies[i].orientation)});
  }
  const double ours = SceneKineticEnergy(scene);
  const double energy_error = std::abs(world.KineticEnergy() - ours) / ours;
  if (pose_error < kTolerance && energy_error < kTolerance) return true;
  std::fprintf(stderr,
               "thesis_bullet: Bullet's start differs from the scene: pose %.3g, energy %.3g\n",
               pose_error, energy_error);
  return false;
}

RunResult RunBullet(const SceneDescription& scene, double duration, double dt) {
  BulletThesisWorld world(scene);
  ContactProbe probe(scene);
  std::vector<Pose> poses(world.BodyCount());
  RunResult run{.engine = "bullet", .dt = dt};
  if (!StartsFromTheScene(scene, world)) std::exit(1);
  const double energy = world.KineticEnergy();
  const auto steps = static_cast<std::uint64_t>(std::llround(duration / dt));
  for (std::uint64_t s = 0; s < steps; ++s) {
    const Clock::time_point start = Clock::now();
    const double cpu_start = ThreadCpuSeconds();
    world.Step(dt);
    run.cpu += ThreadCpuSeconds() - cpu_start;
    if (s == 0) {
      run.startup_cpu = run.cpu;
      run.startup_sim = dt;
    }
    run.wall += std::chrono::duration<double>(Clock::now() - start).count();

    // Untimed: energy and the contact probe.
    const double drift = (world.KineticEnergy() - energy) / energy;
    run.max_energy_drift = std::max(run.max_energy_drift, std::abs(drift));
    run.energy_drift = drift;
    for (std::size_t i = 0; i < poses.size(); ++i) poses[i] = world.PoseOf(i);
    probe.Measure(poses);
  }
  run.steps = steps;
  run.probe = probe.Finish();
  run.max_penetration = run.probe->max_penetration;
  return run;
}

void PrintHeader() {
  std::printf(
      "engine,n,packing,seed,dt,duration,steps,wall_seconds,sim_per_wall,cpu_seconds,sim_per_cpu,"
      "energy_drift,max_energy_drift,max_penetration,contacts,penetrating,deep_contacts,"
      "passed_through,escaped,missed,collisions,sparsedyn_speedup,startup_cpu_seconds,"
      "steady_sim_per_cpu,steady_speedup\n");
}

std::string Number(double value, const char* format = "%.6g") {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string Count(std::optional<std::uint64_t> value) {
  return value ? std::to_string(*value) : std::string();
}

void PrintRow(const Options& o, double duration, const RunResult& r,
              const std::optional<RunResult>& ours) {
  const double speed = r.wall > 0 ? duration / r.wall : 0;
  const double cpu_speed = r.cpu > 0 ? duration / r.cpu : 0;
  std::string speedup;  // by CPU time, which other processes on the machine do not inflate
  if (ours && r.engine != "sparsedyn" && ours->cpu > 0 && cpu_speed > 0) {
    speedup = Number((duration / ours->cpu) / cpu_speed, "%.4g");
  }
  // The same without the start-up (steady state: what a longer run tends to).
  auto steady = [duration](const RunResult& run) {
    const double cpu = run.cpu - run.startup_cpu;
    return cpu > 0 ? (duration - run.startup_sim) / cpu : 0.0;
  };
  std::string steady_speedup;
  if (ours && r.engine != "sparsedyn" && steady(*ours) > 0 && steady(r) > 0) {
    steady_speedup = Number(steady(*ours) / steady(r), "%.4g");
  }
  const ProbeTotals* p = r.probe ? &*r.probe : nullptr;
  auto probe = [p](std::uint64_t ProbeTotals::*field) {
    return p ? Count(p->*field) : std::string();
  };
  const std::vector<std::string> cells = {r.engine,
                                          std::to_string(o.scene.n),
                                          Number(o.scene.packing),
                                          std::to_string(o.scene.seed),
                                          r.dt ? Number(*r.dt) : "",
                                          Number(duration),
                                          std::to_string(r.steps),
                                          Number(r.wall),
                                          Number(speed),
                                          Number(r.cpu),
                                          Number(cpu_speed),
                                          Number(r.energy_drift, "%.3e"),
                                          Number(r.max_energy_drift, "%.3e"),
                                          Number(r.max_penetration, "%.4g"),
                                          probe(&ProbeTotals::contacts),
                                          probe(&ProbeTotals::penetrating),
                                          probe(&ProbeTotals::deep_contacts),
                                          probe(&ProbeTotals::passed_through),
                                          probe(&ProbeTotals::escaped),
                                          p ? Count(p->Missed()) : "",
                                          Count(r.collisions),
                                          speedup,
                                          Number(r.startup_cpu),
                                          Number(steady(r)),
                                          steady_speedup};
  std::string line;
  for (const std::string& cell : cells) line += (line.empty() ? "" : ",") + cell;
  std::printf("%s\n", line.c_str());
  std::fflush(stdout);
}

int Main(int argc, char** argv) {
  const Options o = Parse(argc, argv);
  const Clock::time_point start = Clock::now();
  Result<SceneDescription> scene = scenes::MakeThesisScene(o.scene);
  if (!scene) {
    std::fprintf(stderr, "thesis_bullet: %s\n", scene.error().message.c_str());
    return 2;
  }
  std::fprintf(stderr, "thesis scene: %u bodies, %zu shapes, set up in %.2f s\n", o.scene.n,
               scene->shapes.size(), std::chrono::duration<double>(Clock::now() - start).count());
  if (o.header) PrintHeader();

  const std::optional<RunResult> ours =
      o.sparsedyn ? RunSparsedyn(*scene, o.duration, kProbeStep) : std::nullopt;
  if (ours) PrintRow(o, o.duration, *ours, ours);
  if (!o.bullet) return 0;
  for (const double dt : o.steps) {
    const RunResult run = RunBullet(*scene, o.duration, dt);
    if (run.probe->iteration_caps > 0) {
      std::fprintf(stderr, "thesis_bullet: %llu closest-feature queries hit the cap\n",
                   static_cast<unsigned long long>(run.probe->iteration_caps));
    }
    PrintRow(o, o.duration, run, ours);
  }
  return 0;
}

}  // namespace
}  // namespace sparsedyn::bench

int main(int argc, char** argv) { return sparsedyn::bench::Main(argc, argv); }
