// SPDX-License-Identifier: MIT
#include "support/meeting_oracle.hpp"

namespace sparsedyn::testing {
namespace {

constexpr int kBisections = 200;

// g(dt) = |dp(dt)|^2 - R(dt)^2 and its derivative, in long double.
void GapAndSlope(const Mover& a, const Mover& b, long double t, long double& g,
                 long double& dg) {
  long double q2 = 0, qdq = 0;
  for (int k = 0; k < 3; ++k) {
    const long double dp = static_cast<long double>(b.p[k]) - a.p[k];
    const long double dv = static_cast<long double>(b.v[k]) - a.v[k];
    const long double da = static_cast<long double>(b.a[k]) - a.a[k];
    const long double q = dp + t * (dv + 0.5L * t * da);
    q2 += q * q;
    qdq += q * (dv + t * da);
  }
  const long double r0 = static_cast<long double>(a.r0) + b.r0;
  const long double r1 = static_cast<long double>(a.r1) + b.r1;
  const long double r2 = static_cast<long double>(a.r2) + b.r2;
  const long double r = r0 + t * (r1 + 0.5L * t * r2);
  g = q2 - r * r;
  dg = 2 * (qdq - r * (r1 + t * r2));
}

long double GapDerivative(const Mover& a, const Mover& b, long double t) {
  long double g, dg;
  GapAndSlope(a, b, t, g, dg);
  return dg;
}

// The first point of [lo, hi] where g <= 0, given g(lo) > 0 >= g(hi).
long double BisectRoot(const Mover& a, const Mover& b, long double lo, long double hi) {
  for (int i = 0; i < kBisections && hi - lo > 0; ++i) {
    const long double mid = 0.5L * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (OracleGap(a, b, mid) <= 0 ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace

long double OracleGap(const Mover& a, const Mover& b, long double t) {
  long double g, dg;
  GapAndSlope(a, b, t, g, dg);
  return g;
}

std::pair<Mover, Mover> RandomMoverPair(scenes::Random& random, bool accelerated, bool envelope) {
  // The draws are sequenced (scenes::DrawVector) in the order GCC on x86-64 took them when
  // they were function arguments and operands, so that clang draws the same pairs.
  auto vec = [&](double s) { return scenes::DrawVector([&] { return random.Uniform(-s, s); }); };
  Mover a{vec(5), vec(2), Vec3::Zero(), random.Uniform(0.1, 1), 0, 0};
  Mover b{vec(5), vec(2), Vec3::Zero(), random.Uniform(0.1, 1), 0, 0};
  const Vec3 aside = vec(0.5);
  b.v = a.v + (a.p - b.p).normalized() * random.Uniform(0.5, 2) + aside;
  if (accelerated) {
    a.a = vec(1);
    b.a = vec(1);
  }
  if (envelope) {
    a.r1 = random.Uniform(0, 0.2);
    b.r2 = random.Uniform(0, 0.1);
  }
  return {a, b};
}

std::optional<long double> OracleMeeting(const Mover& a, const Mover& b, long double horizon,
                                         int samples) {
  if (OracleGap(a, b, 0) <= 0) return 0.0L;
  long double previous = 0;
  for (int k = 1; k <= samples; ++k) {
    const long double t = horizon * k / samples;
    if (OracleGap(a, b, t) <= 0) return BisectRoot(a, b, previous, t);
    if (GapDerivative(a, b, previous) < 0 && GapDerivative(a, b, t) > 0) {
      // A local minimum inside: find it, and the root before it if the minimum dips below 0.
      long double lo = previous, hi = t;
      for (int i = 0; i < kBisections; ++i) {
        const long double mid = 0.5L * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (GapDerivative(a, b, mid) < 0 ? lo : hi) = mid;
      }
      if (OracleGap(a, b, lo) <= 0) return BisectRoot(a, b, previous, lo);
    }
    previous = t;
  }
  return std::nullopt;
}

}  // namespace sparsedyn::testing
