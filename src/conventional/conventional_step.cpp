// SPDX-License-Identifier: MIT
// One step of the conventional method (thesis §2.4, App. I.2): detect touching pairs at the step
// end, locate each by bisection, resolve them in time order, re-check the bodies that changed.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "conventional/bisection.hpp"
#include "conventional/conventional_impl.hpp"
#include "conventional/overlap_certificate.hpp"

namespace sparsedyn {
namespace {

// Collisions one body may take part in during one step before the step is declared stuck
// (a body wedged between others): far above any physical rate, finite so that nothing hangs.
constexpr std::uint64_t kCollisionsPerBodyPerStep = 64;

bool Involves(const ConventionalCandidate& c, std::uint32_t i) { return c.a == i || c.b == i; }

}  // namespace

Status ConventionalWorld::Impl::Step(double t0, double t1) {
  std::vector<Candidate> found;
  DetectAtStepEnd(t0, t1, found);
  std::uint64_t budget = kCollisionsPerBodyPerStep * (bodies_.size() + 1);
  while (!found.empty()) {
    // The earliest located collision first; ties in a fixed order (determinism).
    const auto earliest =
        std::min_element(found.begin(), found.end(), [](const Candidate& p, const Candidate& q) {
          return std::tie(p.time, p.a, p.b, p.wall) < std::tie(q.time, q.a, q.b, q.wall);
        });
    const Candidate c = *earliest;
    found.erase(earliest);
    const bool changed =
        c.b == kNoIndex ? ResolveWall(c.a, c.wall, c.time) : ResolvePair(c.a, c.b, c.time);
    if (!changed) continue;  // touching, but no point approaches
    if (--budget == 0) {
      return Error{"conventional step at t = " + std::to_string(t0) +
                   " needs unboundedly many collisions (bodies wedged together)"};
    }
    // The bodies on new paths: their other candidates are void; look again for the rest of
    // the step from the collision time on.
    std::erase_if(found, [&](const Candidate& k) {
      return Involves(k, c.a) || (c.b != kNoIndex && Involves(k, c.b));
    });
    RecheckBody(c.a, kNoIndex, t0, t1, found);
    if (c.b != kNoIndex) RecheckBody(c.b, c.a, t0, t1, found);
  }
  return Status::Ok();
}

void ConventionalWorld::Impl::DetectAtStepEnd(double t0, double t1, std::vector<Candidate>& found) {
  // Advance every body: its centre at the step end bounds it by its sphere's box.
  std::vector<Aabb> boxes(bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const Vec3 c = bodies_[i].path.centre.PositionAt(t1);
    const Vec3 r = Vec3::Constant(bodies_[i].radius);
    boxes[i] = Aabb{c - r, c + r};
  }
  sweep_.Update(boxes);

  // Overlapping boxes -> overlapping spheres -> closest features at the step end.
  sweep_.ForEachOverlap([&](std::uint32_t a, std::uint32_t b) {
    ++stats_.pair_tests;
    const Vec3 d = bodies_[b].path.centre.PositionAt(t1) - bodies_[a].path.centre.PositionAt(t1);
    const double reach = bodies_[a].radius + bodies_[b].radius + PairTolerance(a, b);
    if (d.squaredNorm() > reach * reach) return;
    ++stats_.narrow_queries;
    const ClosestFeatures f = PairFeatures(a, b, t1);
    if (f.distance > PairTolerance(a, b)) return;
    NotePenetration(f.distance);
    if (std::optional<Candidate> c = LocatePair(a, b, t0, t1)) found.push_back(*c);
  });

  // Walls, by each body's nearest vertex once its sphere reaches the wall.
  const Container& box = settings_.container;
  for (std::uint32_t i = 0; i < bodies_.size() && Walled(); ++i) {
    // Most bodies' boxes are clear of every wall: one test instead of six.
    const Aabb& b = boxes[i];
    if ((b.lo.array() > box.lo.array()).all() && (b.hi.array() < box.hi.array()).all()) continue;
    for (int w = 0; w < 6; ++w) {
      if (std::optional<Candidate> c = LocateWall(i, w, t0, t1)) found.push_back(*c);
    }
  }
}

void ConventionalWorld::Impl::RecheckBody(std::uint32_t i, std::uint32_t other, double t0,
                                          double t1, std::vector<Candidate>& found) {
  // After a collision (rare next to steps) body i is compared with every body: O(N) spheres,
  // simpler than re-sorting the sweep for one body.
  const Vec3 c = bodies_[i].path.centre.PositionAt(t1);
  for (std::uint32_t j = 0; j < bodies_.size(); ++j) {
    if (j == i || j == other) continue;
    const Vec3 d = bodies_[j].path.centre.PositionAt(t1) - c;
    const double reach = bodies_[i].radius + bodies_[j].radius + PairTolerance(i, j);
    if (d.squaredNorm() > reach * reach) continue;
    ++stats_.pair_tests;
    const std::uint32_t a = std::min(i, j);
    const std::uint32_t b = std::max(i, j);
    ++stats_.narrow_queries;
    const ClosestFeatures f = PairFeatures(a, b, t1);
    if (f.distance > PairTolerance(a, b)) continue;
    if (std::optional<Candidate> k = LocatePair(a, b, t0, t1)) found.push_back(*k);
  }
  for (int w = 0; w < 6 && Walled(); ++w) {
    if (std::optional<Candidate> k = LocateWall(i, w, t0, t1)) found.push_back(*k);
  }
}

std::optional<ConventionalWorld::Impl::Candidate> ConventionalWorld::Impl::LocatePair(
    std::uint32_t a, std::uint32_t b, double t0, double t1) {
  // The interval where both paths hold: from the step start or a body's last collision.
  const double lo = std::max({t0, bodies_[a].path.t0(), bodies_[b].path.t0()});
  const double tolerance = PairTolerance(a, b);
  auto touching = [&](double t) {
    // Overlapping midpoints are certified by GJK: a penetration depth would cost far more.
    if (CertainlyOverlap(*ShapeOf(a).polyhedron, bodies_[a].path.PoseAt(t), *ShapeOf(b).polyhedron,
                         bodies_[b].path.PoseAt(t))) {
      return true;
    }
    return PairFeatures(a, b, t).distance <= tolerance;
  };
  ++stats_.bisection_evaluations;
  // Touching already at the interval start (a resting or just-resolved contact): nothing to
  // bisect; the contact is looked at where it was found, the step end.
  if (lo >= t1 || touching(lo)) return Candidate{t1, a, b, -1};
  const double resolution = conventional_.dt * std::pow(10.0, -conventional_.digits);
  const double t = BisectToTouch(lo, t1, resolution, touching, stats_.bisection_evaluations);
  return Candidate{t, a, b, -1};
}

std::optional<ConventionalWorld::Impl::Candidate> ConventionalWorld::Impl::LocateWall(
    std::uint32_t i, int wall, double t0, double t1) {
  const WallPlane plane = BoxWall(settings_.container, wall);
  const Vec3& n = plane.normal;
  const double offset = plane.offset;
  if (n.dot(bodies_[i].path.centre.PositionAt(t1)) - offset > bodies_[i].radius) {
    return std::nullopt;  // the bounding sphere is clear of the wall
  }
  const double tolerance = WallTolerance(i);
  const double gap = WallGap(i, wall, t1);
  if (gap > tolerance) return std::nullopt;
  NotePenetration(gap);
  const double lo = std::max(t0, bodies_[i].path.t0());
  auto touching = [&](double t) { return WallGap(i, wall, t) <= tolerance; };
  ++stats_.bisection_evaluations;
  if (lo >= t1 || touching(lo)) return Candidate{t1, i, kNoIndex, wall};
  const double resolution = conventional_.dt * std::pow(10.0, -conventional_.digits);
  const double t = BisectToTouch(lo, t1, resolution, touching, stats_.bisection_evaluations);
  return Candidate{t, i, kNoIndex, wall};
}

}  // namespace sparsedyn
