// SPDX-License-Identifier: MIT
// Slow twins of BoxCrossing, in long double: the inflated-box test's six functions of dt
// sampled densely (rigorously, through a Lipschitz bound) with the crossings bisected, and for
// straight lines the closed form; and random movers and boxes of very different sizes.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>

#include "broadphase/box_crossing.hpp"
#include "sparse/mover.hpp"

namespace sparsedyn::testing {

/// min over the six constraints x_k - lo_k + R >= 0, hi_k + R - x_k >= 0 at dt: >= 0 exactly
/// when the centre is within the inflated box.
inline long double Margin(const Mover& m, const Aabb& box, long double dt) {
  const long double R = m.r0 + dt * (m.r1 + 0.5L * m.r2 * dt);
  long double margin = std::numeric_limits<long double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const long double x = m.p[k] + dt * (m.v[k] + 0.5L * m.a[k] * dt);
    margin = std::min({margin, x - box.lo[k] + R, box.hi[k] + R - x});
  }
  return margin;
}

/// A bound on |d Margin / d dt| over [0, T].
inline long double MarginLipschitz(const Mover& m, long double T) {
  return m.v.cwiseAbs().maxCoeff() + std::abs(m.r1) +
         (m.a.cwiseAbs().maxCoeff() + std::abs(m.r2)) * T;
}

/// The first dt in [from, T] at which Margin changes sign from `inside` (false: the first
/// entry, Margin >= 0; true: the first exit, Margin < 0), by steps the Lipschitz bound makes
/// rigorous down to min_step, then bisected to 1e-16 relative. nullopt when none.
inline std::optional<long double> SampledCrossing(const Mover& m, const Aabb& box, long double T,
                                                  bool inside, long double min_step,
                                                  long double from = 0.0L) {
  const long double L = std::max(MarginLipschitz(m, T), 1e-300L);
  auto crossed = [&](long double dt) {
    return inside ? Margin(m, box, dt) < 0 : Margin(m, box, dt) >= 0;
  };
  long double t = from;
  if (crossed(t)) return t;
  while (t < T) {
    const long double step = std::max(std::abs(Margin(m, box, t)) / L, min_step);
    const long double next = std::min(T, t + step);
    if (crossed(next)) {
      long double lo = t, hi = next;
      while (hi - lo > 1e-16L * std::max(1.0L, hi)) {
        const long double mid = 0.5L * (lo + hi);
        (crossed(mid) ? hi : lo) = mid;
      }
      return hi;
    }
    t = next;
  }
  return std::nullopt;
}

/// Straight lines and a radius growing linearly: each constraint is c + b dt, so the test holds
/// on one interval, [max of the rising ones' roots, min of the falling ones' roots] (and a
/// constraint with b = 0 holds always or never). The entry, or nullopt; `exit` gets its end.
inline std::optional<long double> LinearEntry(const Mover& m, const Aabb& box,
                                              long double* exit = nullptr) {
  long double lo = 0.0L, hi = std::numeric_limits<long double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const long double cs[2] = {static_cast<long double>(m.p[k]) - box.lo[k] + m.r0,
                               static_cast<long double>(box.hi[k]) - m.p[k] + m.r0};
    const long double bs[2] = {static_cast<long double>(m.v[k]) + m.r1,
                               static_cast<long double>(m.r1) - m.v[k]};
    for (int j = 0; j < 2; ++j) {
      if (bs[j] == 0) {
        if (cs[j] < 0) return std::nullopt;
      } else if (bs[j] > 0) {
        lo = std::max(lo, -cs[j] / bs[j]);
      } else {
        hi = std::min(hi, -cs[j] / bs[j]);
      }
    }
  }
  if (lo > hi) return std::nullopt;
  if (exit != nullptr) *exit = hi;
  return lo;
}

/// Random movers and boxes: half sizes log-uniform over 1e-2..1e2 (or less), positions within 30 m,
/// speeds up to 3 m/s, accelerations up to 2 m/s^2 and radius growth (envelopes) on demand.
class BoxCases {
 public:
  explicit BoxCases(std::uint64_t seed) : rng_(seed) {}

  double Uniform() { return static_cast<double>(rng_() >> 11) * 0x1.0p-53; }
  double Signed() { return 2.0 * Uniform() - 1.0; }
  Vec3 Random(double scale) { return {scale * Signed(), scale * Signed(), scale * Signed()}; }
  double LogUniform(double lo, double hi) { return lo * std::pow(hi / lo, Uniform()); }

  Aabb Box(double region = 30.0, double max_half = 1e2) {
    const Vec3 c = Random(region);
    const Vec3 half(LogUniform(1e-2, max_half), LogUniform(1e-2, max_half),
                    LogUniform(1e-2, max_half));
    return {c - half, c + half};
  }
  // curved: acceleration and a growing (or shrinking) radius; else straight lines, constant radius.
  Mover Next(bool curved, double region = 30.0) {
    Mover m;
    m.p = Random(region);
    m.v = Random(3.0);
    m.r0 = LogUniform(1e-2, 1.0);
    if (curved) {
      m.a = Random(2.0);
      m.r1 = 0.05 * Uniform();
      m.r2 = 0.02 * Signed();
    }
    return m;
  }
  std::mt19937_64& rng() { return rng_; }

 private:
  std::mt19937_64 rng_;
};

}  // namespace sparsedyn::testing
