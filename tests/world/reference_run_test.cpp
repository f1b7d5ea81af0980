// SPDX-License-Identifier: MIT
// The whole World against a brute-force reference, one stretch between path changes at a time.
// Random small worlds (walls, a periodic box or open space; gravity, thrusts of their own,
// envelopes, mixed radii, masses and restitutions; bodies added while the world runs) run with
// both broad phases. The reference keeps every body's path from the OnSegment reports and, over
// each stretch in which no path changes, samples every pair (every periodic image) and every
// body and wall in long double, independently of the engine's root finders: no overlap deeper
// than round-off means no collision missed and none handled late. Every reported collision
// must be a touching, approaching pair (or body and wall) whose new paths keep the momentum,
// obey Newton's law with the product of the restitutions, and keep the tangential velocities.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "sparsedyn/world.hpp"

namespace sparsedyn {
namespace {

using Real = long double;
using RealVec = Eigen::Matrix<Real, 3, 1>;

constexpr Real kDeepestOverlap = 1e-8;  // relative to the summed radii: round-off, no more
constexpr Real kTouching = 1e-8;        // a reported collision's gap, relative, at most
constexpr int kSamples = 48;            // per stretch, pair and image
constexpr double kElasticBelow = 1e-6;  // WorldSettings' default collapse guard

RealVec ToReal(const Vec3& v) { return v.cast<Real>(); }

// A body's current path as the reference knows it (its last reported segment).
struct ReferenceBody {
  Real radius = 0, mass = 0, restitution = 1;
  Real t0 = 0;
  RealVec p, v, a;
  RealVec free_a;  // gravity plus its thrust: its acceleration unless a wall holds it
  std::uint32_t version = 0;
  RealVec PositionAt(Real t) const { return p + v * (t - t0) + a * (0.5L * (t - t0) * (t - t0)); }
  RealVec VelocityAt(Real t) const { return v + a * (t - t0); }
};

// The smallest value of gap(tau) = |d0 + dv tau + da tau^2 / 2| - reach over [0, span]: dense
// samples, then a golden-section search around each sampled local minimum (the squared distance
// is a quartic in tau: at most two local minima).
Real SmallestGap(const RealVec& d0, const RealVec& dv, const RealVec& da, Real reach, Real span) {
  const auto gap = [&](Real tau) {
    return (d0 + dv * tau + da * (0.5L * tau * tau)).norm() - reach;
  };
  std::array<Real, kSamples + 1> at;
  for (int k = 0; k <= kSamples; ++k) at[k] = gap(span * k / kSamples);
  Real smallest = *std::min_element(at.begin(), at.end());
  // Between samples the gap changes by at most the largest relative speed times the spacing:
  // a local minimum above that bound cannot dip below zero, and needs no search.
  const Real reach_between = (dv.norm() + da.norm() * span) * span / kSamples;
  for (int k = 0; k <= kSamples; ++k) {
    if ((k > 0 && at[k - 1] < at[k]) || (k < kSamples && at[k + 1] < at[k])) continue;
    if (at[k] > reach_between) continue;
    Real lo = span * std::max(k - 1, 0) / kSamples,
         hi = span * std::min(k + 1, kSamples) / kSamples;
    constexpr Real kInverseGolden = 0.6180339887498948482L;
    for (int step = 0; step < 64; ++step) {
      const Real m1 = hi - kInverseGolden * (hi - lo), m2 = lo + kInverseGolden * (hi - lo);
      if (gap(m1) < gap(m2)) {
        hi = m2;
      } else {
        lo = m1;
      }
    }
    smallest = std::min(smallest, gap(0.5L * (lo + hi)));
  }
  return smallest;
}

// The smallest of x(tau) = x0 + v tau + a tau^2 / 2 over [0, span]: the ends and the vertex.
Real SmallestOfQuadratic(Real x0, Real v, Real a, Real span) {
  const auto x = [&](Real tau) { return x0 + v * tau + 0.5L * a * tau * tau; };
  Real smallest = std::min(x(0), x(span));
  if (a != 0) {
    const Real vertex = -v / a;
    if (vertex > 0 && vertex < span) smallest = std::min(smallest, x(vertex));
  }
  return smallest;
}

struct Scenario {
  Container::Kind kind = Container::Kind::kWalledBox;
  Broadphase broadphase = Broadphase::kGrid;
  std::uint32_t seed = 0;
  double side = 7.0;      // the box [0, side]^3 (where the first bodies are placed in open space)
  int first_bodies = 8;   // at least; up to 5 more
  int steps = 14;         // AdvanceTo calls, each followed by an AddBody half of the time
  bool envelopes = true;  // allowed (they take the World off the grid, to AllPairs)
  // Every body under a thrust of its own from the start (curved paths, elastic): in a small
  // periodic box, pairs then often meet through an image other than the one nearest when
  // they predict, which AllPairs' image skipping must not miss.
  bool curved = false;
  // Inelastic spheres falling onto the floor of a walled box, in columns of their own, which
  // come to rest there (held by the wall) and slide on it.
  bool settling = false;
  Container MakeContainer() const {
    const Vec3 lo = Vec3::Zero(), hi = Vec3::Constant(side);
    switch (kind) {
      case Container::Kind::kOpen:
        return Container::Open();
      case Container::Kind::kWalledBox:
        return Container::WalledBox(lo, hi);
      case Container::Kind::kPeriodicBox:
        return Container::PeriodicBox(lo, hi);
    }
    return {};
  }
};

std::string Describe(const Scenario& s) {
  const char* kind = s.kind == Container::Kind::kOpen        ? "open"
                     : s.kind == Container::Kind::kWalledBox ? "walled"
                                                             : "periodic";
  return std::string(kind) + (s.broadphase == Broadphase::kGrid ? " grid" : " all-pairs") +
         " seed " + std::to_string(s.seed);
}

// Runs one random world and checks it against the reference; returns the collisions checked.
class ReferenceRun {
 public:
  explicit ReferenceRun(const Scenario& scenario) : scenario_(scenario), rng_(scenario.seed) {
    WorldSettings settings;
    settings.container = scenario.MakeContainer();
    settings.broadphase = scenario.broadphase;
    // Gravity or thrusts only with elastic bodies: an inelastic ball settling on a floor bounces
    // ever faster (the collapse guard keeps it elastic below kElasticBelow, but at a huge rate).
    // Thrusts and envelopes from the start, or only on bodies added while the world runs: a
    // world that started on straight lines, or without envelopes, must change its ways then.
    forced_ = Chance(0.5) || scenario.curved;
    if (forced_ && Chance(0.5)) {
      settings.gravity = Chance(0.5) ? Vec3(0, 0, -Uniform(1, 5)) : RandomVec(3);
    }
    if (scenario.settling) settings.gravity = Vec3(0, 0, -Uniform(5, 10));
    thrusts_ = forced_ ? static_cast<Later>(rng_() % 3) : Later::kNever;
    if (scenario.curved) thrusts_ = Later::kAlways;
    envelopes_ =
        Chance(0.4) && scenario.envelopes ? static_cast<Later>(1 + rng_() % 2) : Later::kNever;
    gravity_ = settings.gravity;
    world_ = std::make_unique<World>(settings);
    world_->OnSegment([this](const MotionSegment& s) { pending_.push_back(s); });
    world_->OnCollision([this](const CollisionEvent& e) { CheckCollision(e); });
  }

  std::uint64_t Run() {
    const int first = scenario_.first_bodies + static_cast<int>(rng_() % 6);
    for (int k = 0; k < first; ++k) TryAdd();
    EXPECT_GE(bodies_.size(), 3u) << where_;
    double t = 0;
    for (int step = 0; step < scenario_.steps && !::testing::Test::HasFailure(); ++step) {
      t += Uniform(0.2, 1.0);
      running_ = true;
      const Status status = world_->AdvanceTo(t);
      EXPECT_TRUE(status) << where_ << ": " << (status ? "" : status.error().message);
      EXPECT_TRUE(pending_.empty()) << where_ << ": a segment without its collision";
      CheckStretch(t);
      if (Chance(0.5) && !scenario_.settling) TryAdd();
    }
    if (scenario_.settling) {
      // At rest on the floor: held there, at the height of the radius.
      for (std::uint32_t i = 0; i < bodies_.size(); ++i) {
        const BodyState state = world_->StateAt(world_->IdOf(i), t);
        EXPECT_EQ(state.velocity.z(), 0.0) << where_ << ", body " << i;
        EXPECT_EQ(state.acceleration.z(), 0.0) << where_ << ", body " << i;
        EXPECT_NEAR(state.position.z(), state.radius, 1e-8 * state.radius) << where_;
      }
      EXPECT_GE(holds_, bodies_.size()) << where_;
      EXPECT_EQ(world_->Stats().wall_holds, holds_) << where_;
    }
    // The World's own state agrees with the reported paths.
    for (std::uint32_t i = 0; i < bodies_.size(); ++i) {
      const BodyState state = world_->StateAt(world_->IdOf(i), t);
      RealVec d = ToReal(state.position) - bodies_[i].PositionAt(t);
      if (scenario_.kind == Container::Kind::kPeriodicBox) {
        for (int k = 0; k < 3; ++k) d[k] -= scenario_.side * std::round(d[k] / scenario_.side);
      }
      EXPECT_LT(d.norm(), 1e-9) << where_ << ", body " << i;
      EXPECT_EQ(state.version, bodies_[i].version) << where_ << ", body " << i;
    }
    EXPECT_TRUE(world_->Validate()) << where_;
    return collisions_;
  }
  // Pairs on curved paths that a distance bound settled without a root: the reference checks
  // those skips too.
  std::uint64_t PairsSkipped() const { return world_->Stats().pairs_skipped; }
  std::uint64_t StateHash() const { return world_->StateHash(); }

 private:
  bool Chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
  double Uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  Vec3 RandomVec(double scale) {
    return {Uniform(-scale, scale), Uniform(-scale, scale), Uniform(-scale, scale)};
  }

  // A random body at the current time; the World may refuse it (it overlaps another), and
  // then nothing changes.
  void TryAdd() {
    if (scenario_.settling) {
      AddInColumn();
      return;
    }
    BodyDef def;
    def.radius = Uniform(0.25, running_ ? 0.85 : 0.6);  // a bigger body added rebuilds the grid
    const double margin = scenario_.kind == Container::Kind::kWalledBox ? def.radius : 0;
    for (int k = 0; k < 3; ++k) def.position[k] = Uniform(margin, scenario_.side - margin);
    def.velocity = RandomVec(2.0);
    if (scenario_.kind == Container::Kind::kOpen) {
      // Towards the middle, or open space has the bodies fly apart after a few collisions.
      def.velocity = RandomVec(1.0) + 0.6 * (Vec3::Constant(scenario_.side / 2) - def.position);
    }
    def.mass = Uniform(0.3, 3.0);
    def.restitution = forced_ || Chance(0.5) ? 1.0 : Uniform(0.6, 1.0);
    if (Allowed(thrusts_) && (scenario_.curved || Chance(0.4))) def.thrust = RandomVec(1.5);
    if (Allowed(envelopes_) && Chance(0.4)) {
      def.envelope = {Uniform(0, 0.1), Uniform(0, 0.1), Uniform(0, 0.05)};
    }
    Add(def);
  }

  // A settling body: above the floor in a column of its own (up to 9), nearly straight down.
  void AddInColumn() {
    const auto k = static_cast<double>(bodies_.size() % 9);
    BodyDef def;
    def.radius = Uniform(0.25, 0.6);
    def.position = {1.2 + 2.3 * std::fmod(k, 3.0), 1.2 + 2.3 * std::floor(k / 3), Uniform(1, 6)};
    def.velocity = {Uniform(-0.2, 0.2), Uniform(-0.2, 0.2), Uniform(-1, 1)};
    def.mass = Uniform(0.3, 3.0);
    def.restitution = Uniform(0.2, 0.7);
    Add(def);
  }

  void Add(const BodyDef& def) {
    const std::size_t count = world_->BodyCount();
    const Result<BodyId> id = world_->AddBody(def);
    if (!id) {
      EXPECT_EQ(world_->BodyCount(), count) << where_ << ": a refused body changed the World";
      return;
    }
    EXPECT_EQ(id->index, bodies_.size()) << where_;
    ReferenceBody body;
    body.radius = def.radius;
    body.mass = def.mass;
    body.restitution = def.restitution;
    body.t0 = world_->Time();
    body.p = ToReal(def.position);
    body.v = ToReal(def.velocity);
    body.a = ToReal(Vec3(gravity_ + def.thrust));  // as the World adds them, in doubles
    body.free_a = body.a;
    bodies_.push_back(body);
  }

  // The periodic image of b - a nearest to zero (the difference itself elsewhere).
  RealVec NearestImage(RealVec d) const {
    if (scenario_.kind != Container::Kind::kPeriodicBox) return d;
    for (int k = 0; k < 3; ++k) d[k] -= scenario_.side * std::round(d[k] / scenario_.side);
    return d;
  }

  // No body overlaps another or a wall in (checked_until_, t): the paths do not change there.
  void CheckStretch(Real t) {
    const Real from = checked_until_;
    checked_until_ = std::max(checked_until_, t);
    if (!(t > from)) return;
    const Real span = t - from;
    const bool periodic = scenario_.kind == Container::Kind::kPeriodicBox;
    const Real side = scenario_.side;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const ReferenceBody& a = bodies_[i];
      for (std::size_t j = i + 1; j < bodies_.size(); ++j) {
        const ReferenceBody& b = bodies_[j];
        const RealVec d0 = NearestImage(b.PositionAt(from) - a.PositionAt(from));
        const RealVec dv = b.VelocityAt(from) - a.VelocityAt(from);
        const RealVec da = b.a - a.a;
        const Real reach = a.radius + b.radius;
        // The box d(tau) stays in over the stretch (each component a quadratic): an image whose
        // box is farther than the reach from the origin cannot touch in the stretch.
        RealVec low, high;
        for (int k = 0; k < 3; ++k) {
          low[k] = SmallestOfQuadratic(d0[k], dv[k], da[k], span);
          high[k] = -SmallestOfQuadratic(-d0[k], -dv[k], -da[k], span);
        }
        // In a periodic box, every image whose box comes within the reach of the origin along
        // each axis (fast bodies in a small box: beyond the 27 nearest).
        std::array<int, 3> first{}, last{};
        for (int k = 0; k < 3 && periodic; ++k) {
          first[k] = static_cast<int>(std::ceil((-reach - high[k]) / side));
          last[k] = static_cast<int>(std::floor((reach - low[k]) / side));
        }
        for (int x = first[0]; x <= last[0]; ++x) {
          for (int y = first[1]; y <= last[1]; ++y) {
            for (int z = first[2]; z <= last[2]; ++z) {
              const RealVec shift = RealVec(x, y, z) * side;
              Real outside = 0;  // squared distance from the origin to the image's box
              for (int k = 0; k < 3; ++k) {
                const Real below = std::max({Real{0}, low[k] + shift[k], -(high[k] + shift[k])});
                outside += below * below;
              }
              if (outside > reach * reach) continue;
              const RealVec image = d0 + shift;
              const Real gap = SmallestGap(image, dv, da, reach, span);
              EXPECT_GT(gap, -kDeepestOverlap * reach)
                  << where_ << ": bodies " << i << " and " << j << " overlap within ("
                  << static_cast<double>(from) << ", " << static_cast<double>(t)
                  << "): a collision missed or handled late";
            }
          }
        }
      }
      if (scenario_.kind != Container::Kind::kWalledBox) continue;
      const RealVec p = a.PositionAt(from), v = a.VelocityAt(from);
      for (int k = 0; k < 3; ++k) {
        const Real low = SmallestOfQuadratic(p[k] - a.radius, v[k], a.a[k], span);
        const Real high =
            SmallestOfQuadratic(scenario_.side - p[k] - a.radius, -v[k], -a.a[k], span);
        EXPECT_GT(std::min(low, high), -kDeepestOverlap * a.radius)
            << where_ << ": body " << i << " goes through a wall of axis " << k << " within ("
            << static_cast<double>(from) << ", " << static_cast<double>(t) << ")";
      }
    }
  }

  // A reported collision: the stretch before it, then the pair (or body and wall) touching and
  // approaching on the old paths, and the new paths (the segments reported just before it).
  void CheckCollision(const CollisionEvent& e) {
    ++collisions_;
    const Real t = e.time;
    CheckStretch(t);
    const bool wall = !e.b.valid();
    const std::size_t expected = wall ? 1 : 2;
    EXPECT_EQ(pending_.size(), expected) << where_ << ": segments of the collision at " << e.time;
    std::vector<ReferenceBody> after;
    for (const MotionSegment& s : pending_) {
      EXPECT_EQ(s.t0, e.time) << where_;
      if (s.body.index >= bodies_.size()) {
        ADD_FAILURE() << where_ << ": segment of an unknown body";
        continue;
      }
      ReferenceBody body = bodies_[s.body.index];
      EXPECT_EQ(s.version, body.version + 1) << where_;
      body.t0 = s.t0;
      body.p = ToReal(s.position);
      body.v = ToReal(s.velocity);
      body.a = ToReal(s.acceleration);
      body.version = s.version;
      after.push_back(body);
    }
    if (pending_.size() == expected && pending_[0].body.index < bodies_.size()) {
      if (wall) {
        CheckWallCollision(e, after[0]);
      } else if (pending_[1].body.index < bodies_.size()) {
        CheckPairCollision(e, after[0], after[1]);
      }
    }
    for (std::size_t k = 0; k < pending_.size() && k < after.size(); ++k) {
      if (pending_[k].body.index < bodies_.size()) bodies_[pending_[k].body.index] = after[k];
    }
    pending_.clear();
  }

  void CheckPairCollision(const CollisionEvent& e, const ReferenceBody& new_a,
                          const ReferenceBody& new_b) {
    const Real t = e.time;
    const ReferenceBody& a = bodies_[e.a.index];
    const ReferenceBody& b = bodies_[e.b.index];
    EXPECT_EQ(pending_[0].body.index, e.a.index) << where_;
    EXPECT_EQ(pending_[1].body.index, e.b.index) << where_;
    const RealVec d = NearestImage(b.PositionAt(t) - a.PositionAt(t));
    const Real reach = a.radius + b.radius;
    const Real gap = d.norm() - reach;
    EXPECT_LT(std::abs(gap), kTouching * reach)
        << where_ << ": bodies " << e.a.index << " and " << e.b.index << " collide at " << e.time
        << " with a gap of " << static_cast<double>(gap);
    const RealVec n = d / d.norm();
    const RealVec before = b.VelocityAt(t) - a.VelocityAt(t);
    const RealVec now = new_b.v - new_a.v;
    const Real u = before.dot(n);
    const Real scale = before.norm() + 1;
    EXPECT_LT(u, 0) << where_ << ": a collision of bodies moving apart at " << e.time;
    const Real e_pair = -u < kElasticBelow ? 1.0L : a.restitution * b.restitution;
    EXPECT_NEAR(static_cast<double>(now.dot(n)), static_cast<double>(-e_pair * u),
                1e-12 * static_cast<double>(scale))
        << where_ << ": Newton's law of restitution at " << e.time;
    EXPECT_LT((now - now.dot(n) * n - (before - u * n)).norm(), 1e-12L * scale)
        << where_ << ": the tangential velocity changed at " << e.time;
    const RealVec momentum_before = a.mass * a.VelocityAt(t) + b.mass * b.VelocityAt(t);
    const RealVec momentum_after = a.mass * new_a.v + b.mass * new_b.v;
    EXPECT_LT((momentum_after - momentum_before).norm(),
              1e-12L * (a.mass + b.mass) * (a.VelocityAt(t).norm() + b.VelocityAt(t).norm() + 1))
        << where_ << ": momentum at " << e.time;
    for (const ReferenceBody* body : {&new_a, &new_b}) {
      const ReferenceBody& old = body == &new_a ? a : b;
      // (A periodic box may report the position wrapped into the box.)
      EXPECT_LT(NearestImage(body->p - old.PositionAt(t)).norm(), 1e-9L)
          << where_ << ": a body jumped at its collision";
      // (A collision with another body ends any wall's hold.)
      EXPECT_EQ(body->a, old.free_a) << where_ << ": the acceleration after a collision";
    }
  }

  void CheckWallCollision(const CollisionEvent& e, const ReferenceBody& new_body) {
    EXPECT_EQ(scenario_.kind, Container::Kind::kWalledBox) << where_;
    const Real t = e.time;
    const ReferenceBody& body = bodies_[e.a.index];
    ASSERT_TRUE(e.wall >= 0 && e.wall < 6) << where_;
    const int axis = e.wall / 2;
    const bool upper = e.wall % 2 == 1;
    const RealVec p = body.PositionAt(t), v = body.VelocityAt(t);
    const Real gap = upper ? scenario_.side - p[axis] - body.radius : p[axis] - body.radius;
    EXPECT_LT(std::abs(gap), kTouching * body.radius)
        << where_ << ": body " << e.a.index << " meets wall " << e.wall << " at " << e.time
        << " with a gap of " << static_cast<double>(gap);
    const Real u = upper ? -v[axis] : v[axis];  // the velocity away from the wall
    const Real pressed = upper ? -body.free_a[axis] : body.free_a[axis];
    const Real u_after = upper ? -new_body.v[axis] : new_body.v[axis];
    if (std::abs(u) < kElasticBelow && pressed < 0) {
      // Coming to rest: the wall holds the body, without velocity or acceleration into it.
      ++holds_;
      EXPECT_EQ(new_body.v[axis], 0) << where_ << ": a held body moves at " << e.time;
      EXPECT_EQ(new_body.a[axis], 0) << where_ << ": a held body accelerates at " << e.time;
    } else {
      EXPECT_LT(u, 0) << where_ << ": a wall collision moving away at " << e.time;
      const Real restitution = -u < kElasticBelow ? 1.0L : body.restitution;
      EXPECT_NEAR(static_cast<double>(u_after), static_cast<double>(-restitution * u),
                  1e-12 * static_cast<double>(v.norm() + 1))
          << where_ << ": the wall's restitution at " << e.time;
      EXPECT_EQ(new_body.a[axis], body.a[axis]) << where_ << ": the acceleration changed";
    }
    for (int k = 0; k < 3; ++k) {
      if (k == axis) continue;
      EXPECT_NEAR(static_cast<double>(new_body.v[k]), static_cast<double>(v[k]),
                  1e-12 * static_cast<double>(v.norm() + 1))
          << where_ << ": a wall changed axis " << k;
      EXPECT_EQ(new_body.a[k], body.a[k]) << where_ << ": a wall changed the acceleration";
    }
  }

  enum class Later { kNever, kAlways, kOnlyWhileRunning };
  bool Allowed(Later when) const {
    return when == Later::kAlways || (when == Later::kOnlyWhileRunning && running_);
  }

  Scenario scenario_;
  std::mt19937 rng_;
  std::string where_ = Describe(scenario_);
  bool forced_ = false;   // gravity or thrusts: elastic bodies only
  bool running_ = false;  // the first AdvanceTo was called
  Later thrusts_ = Later::kNever, envelopes_ = Later::kNever;
  Vec3 gravity_ = Vec3::Zero();
  std::unique_ptr<World> world_;
  std::vector<ReferenceBody> bodies_;
  std::uint64_t holds_ = 0;
  std::vector<MotionSegment> pending_;
  Real checked_until_ = 0;
  std::uint64_t collisions_ = 0;
};

class ReferenceRuns : public ::testing::TestWithParam<Container::Kind> {};

// The collisions checked and the pairs on curved paths the distance bound skipped, over runs,
// and the worlds' final StateHash values combined in run order: a golden value pins every run's
// behaviour to the bit (tests/world/state_hash_test.cpp says when to change one).
struct Checked {
  std::uint64_t collisions = 0, skipped = 0, hash = 0;
  void AddHash(std::uint64_t world_hash) { hash = hash * 0x100000001b3ull ^ world_hash; }
  Checked& operator+=(const Checked& other) {
    collisions += other.collisions;
    skipped += other.skipped;
    AddHash(other.hash);
    return *this;
  }
  void Print() const {
    std::printf(
        "collisions checked against the reference: %llu (pairs skipped by the bound: %llu), "
        "hash 0x%016llx\n",
        static_cast<unsigned long long>(collisions), static_cast<unsigned long long>(skipped),
        static_cast<unsigned long long>(hash));
  }
};

// `scenario` run with each seed from `first` to `last`, until a failure.
Checked RunSeeds(Scenario scenario, std::uint32_t first, std::uint32_t last) {
  Checked checked;
  for (std::uint32_t seed = first; seed <= last && !::testing::Test::HasFailure(); ++seed) {
    scenario.seed = seed;
    ReferenceRun run(scenario);
    checked.collisions += run.Run();
    checked.skipped += run.PairsSkipped();
    checked.AddHash(run.StateHash());
  }
  return checked;
}

// Many small worlds: every feature, few bodies, the grid's outer layer (wrapped in a periodic
// box) and its rebuilds.
TEST_P(ReferenceRuns, NoCollisionMissedOrLateAndEveryResponseExact) {
  Checked checked;
  for (const Broadphase broadphase : {Broadphase::kAllPairs, Broadphase::kGrid}) {
    Scenario scenario;
    scenario.kind = GetParam();
    scenario.broadphase = broadphase;
    checked += RunSeeds(scenario, 1, 25);
  }
  checked.Print();
  EXPECT_EQ(checked.hash, GetParam() == Container::Kind::kOpen        ? 0x575d492074dbec84ull
                          : GetParam() == Container::Kind::kWalledBox ? 0xad1f3971e35bd7a0ull
                                                                      : 0x144174a8165fac0cull);
  EXPECT_GT(checked.collisions, GetParam() == Container::Kind::kOpen ? 200u : 1000u);
  EXPECT_GT(checked.skipped, 1000u);
}

// A few larger worlds, on the grid in the boxes: cells away from the box's faces (the interior
// paths, with fixed neighbour offsets) and more crossings per collision.
TEST_P(ReferenceRuns, LargerWorldsNeitherMissNorDelay) {
  Scenario scenario;
  scenario.kind = GetParam();
  scenario.side = 13.0;
  scenario.first_bodies = 60;
  scenario.steps = 20;
  scenario.envelopes = false;
  const Checked checked = RunSeeds(scenario, 101, 104);
  checked.Print();
  EXPECT_EQ(checked.hash, GetParam() == Container::Kind::kOpen        ? 0x65413c8f06840a4eull
                          : GetParam() == Container::Kind::kWalledBox ? 0xfaa8e1bcbf51fcbdull
                                                                      : 0xae749e350fcf2416ull);
  EXPECT_GT(checked.collisions, 400u);
}

// Bodies under thrusts of their own in a periodic box little more than twice the largest
// diameter, on AllPairs (too few cells for the grid): pairs separated by nearly half the box
// close it along curved paths, so that they meet through an image other than the nearest one
// at their prediction, and the image skipping (ApartBound's slab verdicts) is exercised across
// all 26 other images. The reference samples every image within reach.
TEST(ReferenceSmallPeriodicBox, CurvedPathsMeetThroughTheFartherImagesToo) {
  Scenario scenario;
  scenario.kind = Container::Kind::kPeriodicBox;
  scenario.broadphase = Broadphase::kAllPairs;
  scenario.side = 3.5;
  scenario.first_bodies = 4;
  scenario.envelopes = false;
  scenario.curved = true;
  const Checked checked = RunSeeds(scenario, 1, 30);
  checked.Print();
  EXPECT_EQ(checked.hash, 0x543a4d6dcc81fdd7ull);
  EXPECT_GT(checked.collisions, 1000u);
  EXPECT_GT(checked.skipped, 1000u);
}

// Inelastic spheres dropped onto the floor come to rest on it (bouncing ever lower until the
// approach is slower than the collapse guard, when the floor holds them) and slide, colliding
// with each other and the side walls, without the clock stalling.
TEST(ReferenceSettling, InelasticSpheresComeToRestOnTheFloor) {
  std::uint64_t collisions = 0;
  Checked checked;
  for (std::uint32_t seed = 1; seed <= 12 && !HasFailure(); ++seed) {
    Scenario scenario;
    scenario.seed = seed;
    scenario.first_bodies = 3;
    scenario.steps = 40;  // to t = 24 on average (at least 8): settled after 9 s at most
    scenario.settling = true;
    scenario.broadphase = seed % 2 == 0 ? Broadphase::kGrid : Broadphase::kAllPairs;
    ReferenceRun run(scenario);
    collisions += run.Run();
    checked.AddHash(run.StateHash());
  }
  std::printf("collisions checked against the reference: %llu, hash 0x%016llx\n",
              static_cast<unsigned long long>(collisions),
              static_cast<unsigned long long>(checked.hash));
  EXPECT_EQ(checked.hash, 0xd8b98f8d232c9fa9ull);
  EXPECT_GT(collisions, 500u);
}

INSTANTIATE_TEST_SUITE_P(World, ReferenceRuns,
                         ::testing::Values(Container::Kind::kOpen, Container::Kind::kWalledBox,
                                           Container::Kind::kPeriodicBox),
                         [](const ::testing::TestParamInfo<Container::Kind>& param_info) {
                           return param_info.param == Container::Kind::kOpen        ? "Open"
                                  : param_info.param == Container::Kind::kWalledBox ? "Walled"
                                                                                    : "Periodic";
                         });

}  // namespace
}  // namespace sparsedyn
