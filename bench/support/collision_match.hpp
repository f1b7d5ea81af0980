// SPDX-License-Identifier: MIT
// Do two runs of one scene find the same collisions? The equal-accuracy test of the thesis's
// §7.0 comparison (bench/scenes/thesis_figures.cpp): the conventional method at a step dt is as
// accurate as the event-driven World when it finds every collision the World finds (same
// bodies or body and wall, a time within a tolerance) and no other.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <vector>

namespace sparsedyn::bench {

/// One resolved collision: bodies `a` < `b`, or body `a` and wall `b` (then `wall` is set).
struct CollisionRecord {
  double t = 0;
  std::uint32_t a = 0;
  std::uint32_t b = 0;
  bool wall = false;
};

/// A body-body collision with its indices ordered, so that (a, b) and (b, a) are one pair.
inline CollisionRecord PairCollision(double t, std::uint32_t i, std::uint32_t j) {
  return {t, std::min(i, j), std::max(i, j), false};
}

/// Collisions of `reference` that `other` has not (missing) and those of `other` that
/// `reference` has not (spurious).
struct CollisionMatch {
  std::uint64_t matched = 0;
  std::uint64_t missing = 0;
  std::uint64_t spurious = 0;
  bool Same() const { return missing == 0 && spurious == 0; }
};

/// Matches the two lists pair by pair in time order: the k-th collision of a pair (or of a body
/// with a wall) in one list is the k-th in the other when their times differ by at most
/// `time_tolerance`. Near-simultaneous collisions of different pairs may come in either order.
inline CollisionMatch MatchCollisions(std::vector<CollisionRecord> reference,
                                      std::vector<CollisionRecord> other, double time_tolerance) {
  const auto by_pair = [](const CollisionRecord& x, const CollisionRecord& y) {
    return std::tie(x.wall, x.a, x.b, x.t) < std::tie(y.wall, y.a, y.b, y.t);
  };
  const auto pair_less = [](const CollisionRecord& x, const CollisionRecord& y) {
    return std::tie(x.wall, x.a, x.b) < std::tie(y.wall, y.a, y.b);
  };
  std::sort(reference.begin(), reference.end(), by_pair);
  std::sort(other.begin(), other.end(), by_pair);

  // Merge by pair; within a pair, collisions in order, unmatched ones counted on their side.
  CollisionMatch match;
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < reference.size() || j < other.size()) {
    if (j == other.size() || (i < reference.size() && pair_less(reference[i], other[j]))) {
      ++match.missing, ++i;
    } else if (i == reference.size() || pair_less(other[j], reference[i])) {
      ++match.spurious, ++j;
    } else if (std::abs(reference[i].t - other[j].t) <= time_tolerance) {
      ++match.matched, ++i, ++j;
    } else if (reference[i].t < other[j].t) {
      ++match.missing, ++i;
    } else {
      ++match.spurious, ++j;
    }
  }
  return match;
}

/// Body-body collisions that begin an encounter: the pair had not collided within the `gap`
/// before. Rotating polyhedra may strike twice or more while their spheres overlap; this counts
/// such a run of strikes once, as kinetic theory counts a collision of two spheres.
inline std::uint64_t CountEncounters(std::vector<CollisionRecord> collisions, double gap) {
  std::sort(collisions.begin(), collisions.end(), [](const auto& x, const auto& y) {
    return std::tie(x.wall, x.a, x.b, x.t) < std::tie(y.wall, y.a, y.b, y.t);
  });
  std::uint64_t encounters = 0;
  for (std::size_t i = 0; i < collisions.size(); ++i) {
    const CollisionRecord& c = collisions[i];
    if (c.wall) continue;
    const bool same_pair = i > 0 && !collisions[i - 1].wall && collisions[i - 1].a == c.a &&
                           collisions[i - 1].b == c.b;
    if (!same_pair || c.t - collisions[i - 1].t > gap) ++encounters;
  }
  return encounters;
}

}  // namespace sparsedyn::bench
