// SPDX-License-Identifier: MIT
// Drag in the World (App. H.2, issue #36 part 5): bodies whose true motion is a DragMotion,
// followed by their elements on Taylor paths within envelopes, renewed by check events. Each
// test has an oracle of its own: the closed form of linear drag, its head-on meeting time by
// bisection in long double, a long-double RK4 of x'' = g - c1 v - c2 |v| v (dense sampling,
// brute-force first contacts), and energy that drag can only take away.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "sparsedyn/world.hpp"
#include "world/element_paths.hpp"

namespace sparsedyn {
namespace {

using Real = long double;

// Linear drag with gravity, 1D closed form: v_inf = g / c1,
// x(t) = x0 + v_inf t + (v0 - v_inf) (1 - e^(-c1 t)) / c1.
Real ClosedFormPosition(Real x0, Real v0, Real g, Real c1, Real t) {
  const Real v_inf = g / c1;
  return x0 + v_inf * t + (v0 - v_inf) * (-std::expm1(-c1 * t)) / c1;
}
Real ClosedFormVelocity(Real v0, Real g, Real c1, Real t) {
  const Real v_inf = g / c1;
  return v_inf + (v0 - v_inf) * std::exp(-c1 * t);
}

TEST(DragWorld, LinearDragWithGravityFollowsTheClosedFormToTerminalVelocity) {
  const Vec3 g(0, 0, -9.81);
  const double c1 = 0.7;
  WorldSettings settings;
  settings.gravity = g;
  World world(settings);
  const Vec3 p0(1, -2, 30), v0(3, -1, 5);
  const BodyId a =
      *world.AddBody({.radius = 0.5, .position = p0, .velocity = v0, .drag = Drag{c1, 0}});
  for (double t : {0.01, 0.3, 1.0, 2.5, 7.0, 20.0, 60.0}) {
    ASSERT_TRUE(world.AdvanceTo(t));
    const BodyState s = world.StateAt(a, t);
    for (int k = 0; k < 3; ++k) {
      const Real x = ClosedFormPosition(p0[k], v0[k], g[k], c1, t);
      const Real v = ClosedFormVelocity(v0[k], g[k], c1, t);
      // The closed form of the World (through its check events: new segments from the true
      // state) against the textbook one: a few roundings of |x| per segment.
      EXPECT_NEAR(s.position[k], static_cast<double>(x), 1e-12 * (1 + std::abs(x))) << t;
      EXPECT_NEAR(s.velocity[k], static_cast<double>(v), 1e-12 * (1 + std::abs(v))) << t;
    }
  }
  // Terminal velocity g / c1 (e^-42 of the start's difference left).
  const BodyState end = world.StateAt(a, 60.0);
  EXPECT_TRUE(end.velocity.isApprox(g / c1, 1e-12)) << end.velocity.transpose();
  EXPECT_GT(world.Stats().drag_checks, 0u);
  EXPECT_TRUE(world.Validate());
}

TEST(DragWorld, HeadOnMeetingTimeWithLinearDragMatchesTheClosedFormRoot) {
  // Two spheres of radius 0.5 at x = 0 and x = 10 at +-v0 with linear drag c1: the gap
  // 10 - 1 - 2 v0 (1 - e^(-c1 t)) / c1 reaches 0 at the root found by bisection.
  for (const double c1 : {0.05, 0.2, 0.6}) {
    const double v0 = 3.0;
    World world;
    std::vector<CollisionEvent> events;
    world.OnCollision([&](const CollisionEvent& e) { events.push_back(e); });
    ASSERT_TRUE(world.AddBody({.radius = 0.5, .position = {0, 0, 0}, .velocity = {v0, 0, 0},
                               .drag = Drag{c1, 0}}));
    ASSERT_TRUE(world.AddBody({.radius = 0.5, .position = {10, 0, 0}, .velocity = {-v0, 0, 0},
                               .drag = Drag{c1, 0}}));
    ASSERT_TRUE(world.AdvanceTo(20.0));
    ASSERT_FALSE(events.empty()) << c1;
    const auto gap = [&](Real t) {
      return 9.0L - 2.0L * static_cast<Real>(v0) * (-std::expm1(-c1 * t)) / c1;
    };
    Real lo = 0, hi = 20;
    ASSERT_LT(gap(hi), 0);
    for (int k = 0; k < 200; ++k) {
      const Real mid = (lo + hi) / 2;
      (gap(mid) > 0 ? lo : hi) = mid;
    }
    const double root = static_cast<double>(lo);
    SCOPED_TRACE(testing::Message() << "c1 = " << c1 << ", root " << root);
    EXPECT_NEAR(events[0].time, root, 1e-9);
    EXPECT_LE(events[0].time, root + 1e-15);  // never late
    EXPECT_EQ(world.Stats().collisions, 1u);
  }
}

TEST(DragWorld, FallingOntoTheFloorWithLinearDragMeetsItAtTheClosedFormTime) {
  // Dropped from rest at height 5 (centre), radius 0.5: z(t) - 0.5 = 0 on the closed form.
  const double c1 = 0.4, g = -9.81;
  WorldSettings settings;
  settings.gravity = Vec3(0, 0, g);
  settings.container = Container::WalledBox(Vec3(-5, -5, 0), Vec3(5, 5, 10));
  World world(settings);
  std::vector<CollisionEvent> events;
  world.OnCollision([&](const CollisionEvent& e) { events.push_back(e); });
  ASSERT_TRUE(world.AddBody({.radius = 0.5, .position = {0, 0, 5}, .drag = Drag{c1, 0}}));
  ASSERT_TRUE(world.AdvanceTo(3.0));
  ASSERT_FALSE(events.empty());
  Real lo = 0, hi = 3;
  for (int k = 0; k < 200; ++k) {
    const Real mid = (lo + hi) / 2;
    (ClosedFormPosition(5, 0, g, c1, mid) - 0.5L > 0 ? lo : hi) = mid;
  }
  EXPECT_EQ(events[0].wall, 4);
  EXPECT_NEAR(events[0].time, static_cast<double>(lo), 1e-9);
  EXPECT_LE(events[0].time, static_cast<double>(lo) + 1e-15);
}

// --- A long-double oracle of the true motion: RK4 of x'' = g - c1 v - c2 |v| v. ---

struct TrueState {
  Real x[3], v[3];
};

void Accel(const Real v[3], const Real g[3], Real c1, Real c2, Real a[3]) {
  const Real speed = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int k = 0; k < 3; ++k) a[k] = g[k] - c1 * v[k] - c2 * speed * v[k];
}

void Rk4Step(TrueState& s, const Real g[3], Real c1, Real c2, Real h) {
  Real k1v[3], k2v[3], k3v[3], k4v[3], k1x[3], k2x[3], k3x[3], k4x[3], v[3];
  Accel(s.v, g, c1, c2, k1v);
  for (int k = 0; k < 3; ++k) k1x[k] = s.v[k], v[k] = s.v[k] + h / 2 * k1v[k];
  Accel(v, g, c1, c2, k2v);
  for (int k = 0; k < 3; ++k) k2x[k] = v[k], v[k] = s.v[k] + h / 2 * k2v[k];
  Accel(v, g, c1, c2, k3v);
  for (int k = 0; k < 3; ++k) k3x[k] = v[k], v[k] = s.v[k] + h * k3v[k];
  Accel(v, g, c1, c2, k4v);
  for (int k = 0; k < 3; ++k) {
    k4x[k] = v[k];
    s.x[k] += h / 6 * (k1x[k] + 2 * k2x[k] + 2 * k3x[k] + k4x[k]);
    s.v[k] += h / 6 * (k1v[k] + 2 * k2v[k] + 2 * k3v[k] + k4v[k]);
  }
}

struct Body {
  TrueState s;
  Real c1, c2, r;
};

TEST(DragWorld, ElementsHoldTheTrueMotionOfRandomBodies) {
  // 3000 random bodies (half linear, half quadratic drag, with gravity and without), each
  // element's Taylor path and envelope as the World starts them (ElementPaths::StartDrag),
  // sampled densely over the horizon against the long-double RK4 of the true motion.
  std::mt19937_64 rng(20261202);
  std::uniform_real_distribution<double> unit(-1, 1), positive(0, 1);
  constexpr int kBodies = 3000, kSamples = 64;
  double worst = 0;  // the largest |true - path| / envelope seen
  for (int trial = 0; trial < kBodies; ++trial) {
    const Vec3 g = trial % 4 < 2 ? Vec3(0, 0, -9.81) : Vec3::Zero();
    const Drag drag = trial % 2 == 0 ? Drag{2 * positive(rng), 0}
                                     : Drag{0.3 * positive(rng), 2 * positive(rng)};
    const Vec3 p(10 * unit(rng), 10 * unit(rng), 10 * unit(rng));
    const Vec3 v = 8 * positive(rng) * Vec3(unit(rng), unit(rng), unit(rng));
    const double radius = 0.05 + positive(rng);
    const double t0 = 3 * positive(rng);
    ElementPaths paths(g);
    paths.Append(PathStart{p, v, t0}, g);
    paths.drags().Append(0, drag, 0.1 * radius);
    const Envelope envelope = paths.StartDrag(0);
    const Path path = paths.PathOf(0);
    const double horizon = paths.drags().CheckTime(0) - t0;
    SCOPED_TRACE(testing::Message() << "trial " << trial << " drag " << drag.linear << ", "
                                    << drag.quadratic << " horizon " << horizon);
    ASSERT_GT(horizon, 0);
    ASSERT_LT(horizon, kInfinity);
    TrueState s{{p[0], p[1], p[2]}, {v[0], v[1], v[2]}};
    const Real gl[3] = {g[0], g[1], g[2]};
    constexpr int kSubsteps = 16;
    for (int k = 1; k <= kSamples; ++k) {
      const Real h = static_cast<Real>(horizon) / (kSamples * kSubsteps);
      for (int m = 0; m < kSubsteps; ++m) Rk4Step(s, gl, drag.linear, drag.quadratic, h);
      const double dt = horizon * k / kSamples;
      const Vec3 on_path = path.PositionAt(t0 + dt);
      Real off2 = 0;
      for (int c = 0; c < 3; ++c) off2 += (s.x[c] - on_path[c]) * (s.x[c] - on_path[c]);
      const double off = static_cast<double>(std::sqrt(off2));
      const double allowed = envelope.At(dt);
      ASSERT_LE(off, allowed * (1 + 1e-9) + 1e-13) << "at dt " << dt;
      worst = std::max(worst, off / allowed);
      // The World's true position (the DragMotion) agrees with the oracle far inside that
      // (every 8th sample: an evaluation walks the integrator from the segment start).
      if (k % 8 != 0) continue;
      const Vec3 true_p = paths.TruePositionAt(0, t0 + dt);
      for (int c = 0; c < 3; ++c) {
        ASSERT_NEAR(true_p[c], static_cast<double>(s.x[c]), 1e-9 * (1 + std::abs(true_p[c])));
      }
    }
    // The envelope stays below the limit the grid's cells allow for.
    ASSERT_LE(envelope.At(horizon), 0.1 * radius * (1 + 1e-12));
  }
  std::printf("worst |true - path| / envelope over %d bodies: %.4f\n", kBodies, worst);
}

TEST(DragWorld, EveryElementHoldsItsBodyThroughARunWithCollisions) {
  // Validate checks each body with drag against its element's envelope (and no overlap beyond
  // the band): after every tenth of a second (3 s) of a walled box of drag bodies under gravity.
  WorldSettings settings;
  settings.gravity = Vec3(0, 0, -9.81);
  settings.container = Container::WalledBox(Vec3(0, 0, 0), Vec3(8, 8, 8));
  settings.drag = Drag{0.1, 0.2};
  World world(settings);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  int added = 0;
  for (int k = 0; k < 400 && added < 60; ++k) {
    const Vec3 p(4 + 3.3 * unit(rng), 4 + 3.3 * unit(rng), 4 + 3.3 * unit(rng));
    const Vec3 v(4 * unit(rng), 4 * unit(rng), 4 * unit(rng));
    const BodyDef def{.radius = 0.3, .position = p, .velocity = v, .restitution = 0.9};
    if (world.AddBody(def)) ++added;
  }
  ASSERT_EQ(added, 60);
  for (int step = 1; step <= 30; ++step) {
    ASSERT_TRUE(world.AdvanceTo(0.1 * step));
    ASSERT_TRUE(world.Validate()) << world.Validate().error().message;
  }
  EXPECT_GT(world.Stats().collisions, 10u);
  EXPECT_GT(world.Stats().wall_collisions, 10u);
  EXPECT_GT(world.Stats().drag_checks, 10u);
  std::printf("60 bodies, 3 s: %llu collisions, %llu wall collisions, %llu checks, %llu steps\n",
              static_cast<unsigned long long>(world.Stats().collisions),
              static_cast<unsigned long long>(world.Stats().wall_collisions),
              static_cast<unsigned long long>(world.Stats().drag_checks),
              static_cast<unsigned long long>(world.Stats().drag_steps));
}

// The brute-force reference of first contacts: every body's true motion stepped finely by the
// RK4 from a snapshot of the World's states, the first time some pair's gap (or a body's gap to
// a wall) is <= 0 refined by bisection on the step.
struct Contact {
  double time = kInfinity;
  int a = -1, b = -1;  // b = -1 - wall for a wall
};

class BruteForce {
 public:
  BruteForce(std::vector<Body> bodies, const Vec3& g, const Container& box)
      : bodies_(std::move(bodies)), box_(box) {
    for (int k = 0; k < 3; ++k) g_[k] = g[k];
  }

  // The first contact after `t0` (the snapshot's time), up to t_end.
  Contact First(double t0, double t_end, Real step) const {
    std::vector<Body> now = bodies_;
    Real t = t0;
    while (t < t_end) {
      std::vector<Body> next = now;
      for (Body& b : next) Rk4Step(b.s, g_, b.c1, b.c2, step);
      const Contact c = Touching(next);
      if (c.a >= 0) {
        // Bisection of the step: the gap of that pair (or wall) from `now`.
        Real lo = 0, hi = step;
        for (int k = 0; k < 60; ++k) {
          const Real mid = (lo + hi) / 2;
          std::vector<Body> probe = now;
          for (Body& b : probe) Rk4Step(b.s, g_, b.c1, b.c2, mid);
          (GapOf(probe, c) > 0 ? lo : hi) = mid;
        }
        return Contact{static_cast<double>(t + hi), c.a, c.b};
      }
      now.swap(next);
      t += step;
    }
    return Contact{};
  }

  // The gap of contact c's pair (or wall) at time t after the snapshot.
  Real GapAt(const Contact& c, Real dt, Real step) const {
    std::vector<Body> now = bodies_;
    const int n = static_cast<int>(std::ceil(dt / step));
    for (int k = 0; k < n; ++k) {
      for (Body& b : now) Rk4Step(b.s, g_, b.c1, b.c2, dt / n);
    }
    return GapOf(now, c);
  }

 private:
  Real GapOf(const std::vector<Body>& bodies, const Contact& c) const {
    const Body& a = bodies[static_cast<std::size_t>(c.a)];
    if (c.b >= 0) {
      const Body& b = bodies[static_cast<std::size_t>(c.b)];
      Real d2 = 0;
      for (int k = 0; k < 3; ++k) d2 += (a.s.x[k] - b.s.x[k]) * (a.s.x[k] - b.s.x[k]);
      return std::sqrt(d2) - a.r - b.r;
    }
    const int wall = -1 - c.b, axis = wall / 2;
    return wall % 2 == 0 ? a.s.x[axis] - box_.lo[axis] - a.r : box_.hi[axis] - a.s.x[axis] - a.r;
  }
  Contact Touching(const std::vector<Body>& bodies) const {
    Contact found;
    Real deepest = 0;
    for (int i = 0; i < static_cast<int>(bodies.size()); ++i) {
      for (int j = i + 1; j < static_cast<int>(bodies.size()); ++j) {
        const Real gap = GapOf(bodies, Contact{0, i, j});
        if (gap <= deepest) deepest = gap, found = Contact{0, i, j};
      }
      for (int w = 0; w < 6; ++w) {
        const Real gap = GapOf(bodies, Contact{0, i, -1 - w});
        if (gap <= deepest) deepest = gap, found = Contact{0, i, -1 - w};
      }
    }
    return found;
  }

  std::vector<Body> bodies_;
  Real g_[3];
  Container box_;
};

TEST(DragWorld, NoMeetingIsMissedOrLateAgainstTheBruteForceReference) {
  // Random drag spheres (linear and quadratic) in a walled box under gravity, restitution 1:
  // from the World's states after each collision (and at the start) the brute-force reference
  // finds the next first contact. The World's next collision is never later than it (1e-9 s,
  // the reference's resolution) and is real: the reference's gap of that pair (or wall) there
  // is within the contact band.
  const Vec3 g(0, 0, -4);
  const Container box = Container::WalledBox(Vec3(0, 0, 0), Vec3(5, 5, 5));
  constexpr Real kStep = 1e-3L;
  constexpr double kTimeResolution = 1e-9;
  int compared = 0;
  double worst_early = 0, worst_gap = 0;
  for (int trial = 0; trial < 12; ++trial) {
    WorldSettings settings;
    settings.gravity = g;
    settings.container = box;
    World world(settings);
    std::mt19937_64 rng(100 + trial);
    std::uniform_real_distribution<double> unit(-1, 1), positive(0, 1);
    std::vector<BodyId> ids;
    std::vector<BodyDef> defs;
    for (int k = 0; k < 200 && ids.size() < 7; ++k) {
      const Drag drag =
          k % 2 == 0 ? Drag{positive(rng), 0} : Drag{0.2 * positive(rng), positive(rng)};
      const BodyDef def{.radius = 0.3 + 0.3 * positive(rng),
                        .position = Vec3(2.5 + 2 * unit(rng), 2.5 + 2 * unit(rng),
                                         2.5 + 2 * unit(rng)),
                        .velocity = Vec3(4 * unit(rng), 4 * unit(rng), 4 * unit(rng)),
                        .drag = drag};
      if (Result<BodyId> id = world.AddBody(def)) {
        ids.push_back(*id);
        defs.push_back(def);
      }
    }
    // The World's states at the start and after each collision.
    const auto snapshot = [&](double t) {
      std::vector<Body> bodies;
      for (std::size_t k = 0; k < ids.size(); ++k) {
        const BodyState s = world.StateAt(ids[k], t);
        Body b{};
        for (int c = 0; c < 3; ++c) b.s.x[c] = s.position[c], b.s.v[c] = s.velocity[c];
        b.c1 = defs[k].drag->linear;
        b.c2 = defs[k].drag->quadratic;
        b.r = defs[k].radius;
        bodies.push_back(b);
      }
      return bodies;
    };
    std::vector<std::vector<Body>> snapshots = {snapshot(0.0)};
    std::vector<double> times = {0.0};
    std::vector<CollisionEvent> events;
    world.OnCollision([&](const CollisionEvent& e) {
      events.push_back(e);
      snapshots.push_back(snapshot(e.time));
      times.push_back(e.time);
    });
    ASSERT_TRUE(world.AdvanceTo(2.0));
    const auto index_of = [&](BodyId id) {
      return static_cast<int>(std::find(ids.begin(), ids.end(), id) - ids.begin());
    };
    for (std::size_t k = 0; k < events.size() && k < 30; ++k) {
      SCOPED_TRACE(testing::Message() << "trial " << trial << ", collision " << k << " at t = "
                                      << events[k].time);
      const BruteForce reference(snapshots[k], g, box);
      const Contact next = reference.First(times[k], events[k].time + 0.05, kStep);
      // Not late, nothing missed: the reference's first contact is not before the World's.
      ASSERT_LE(events[k].time, next.time + kTimeResolution)
          << "the reference finds bodies " << next.a << ", " << next.b << " first";
      worst_early = std::max(worst_early, next.time - events[k].time);
      // Real: the World's pair touches there, within the band.
      const Contact world_pair{events[k].time, index_of(events[k].a),
                               events[k].b.valid() ? index_of(events[k].b) : -1 - events[k].wall};
      const double reach = defs[static_cast<std::size_t>(world_pair.a)].radius +
                           (world_pair.b >= 0 ? defs[static_cast<std::size_t>(world_pair.b)].radius
                                              : 0.0);
      const double gap =
          static_cast<double>(reference.GapAt(world_pair, events[k].time - times[k], kStep / 4));
      EXPECT_LE(gap, 1e-9 * reach + 1e-9);
      EXPECT_GE(gap, -1e-9 * reach - 1e-9);
      worst_gap = std::max(worst_gap, std::abs(gap));
      ++compared;
    }
  }
  EXPECT_GT(compared, 100);
  std::printf("%d collisions against the reference: the World's never later; earliest by "
              "%.3g s of real touching only; worst |gap| there %.3g m\n",
              compared, worst_early, worst_gap);
}

TEST(DragWorld, KineticEnergyNeverGrowsWithoutGravity) {
  // A periodic gas with drag on every body: collisions keep the energy (restitution 1), drag
  // takes it away; never gained beyond the round-off of the collisions.
  WorldSettings settings;
  settings.container = Container::PeriodicBox(Vec3(0, 0, 0), Vec3(12, 12, 12));
  settings.drag = Drag{0.05, 0.1};
  World world(settings);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(-1, 1), positive(0, 1);
  int added = 0;
  for (int k = 0; k < 2000 && added < 200; ++k) {
    const BodyDef def{.radius = 0.5,
                      .position = Vec3(12 * positive(rng), 12 * positive(rng), 12 * positive(rng)),
                      .velocity = Vec3(2 * unit(rng), 2 * unit(rng), 2 * unit(rng))};
    if (world.AddBody(def)) ++added;
  }
  ASSERT_EQ(added, 200);
  double energy = world.KineticEnergy();
  const double start = energy;
  for (int step = 1; step <= 100; ++step) {
    ASSERT_TRUE(world.AdvanceTo(0.05 * step));
    const double now = world.KineticEnergy();
    ASSERT_LE(now, energy * (1 + 1e-13)) << "at t = " << world.Time();
    energy = now;
  }
  EXPECT_LT(energy, 0.9 * start);
  EXPECT_GT(world.Stats().collisions, 50u);
  ASSERT_TRUE(world.Validate());
}

}  // namespace
}  // namespace sparsedyn
