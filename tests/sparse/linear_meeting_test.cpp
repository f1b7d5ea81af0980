// SPDX-License-Identifier: MIT
// The straight-line meeting of the gas hot path (LinearMeetingRoot in plain doubles, its
// certification in doubles or long double) against exact gaps in 128-bit floats, on random
// pairs that mostly meet, and the branch-free verdict of the batch test against the root.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>

#include "scenes/random.hpp"
#include "sparse/meeting.hpp"

namespace {
// The oracle's quad precision: GCC's __float128 on x86-64, long double where that is IEEE quad
// (aarch64 Linux, scripts/aarch64.sh).
#if defined(__SIZEOF_FLOAT128__)
using Quad = __float128;
#else
using Quad = long double;
static_assert(std::numeric_limits<long double>::digits >= 113, "the oracle needs quad precision");
#endif
}  // namespace

namespace sparsedyn {
namespace {

// The gap of two spheres on straight lines, b's path shifted, and its slope at dt, in 128-bit
// floats (113-bit significands): the rounding of these few operations on doubles is far below
// the margins the certification keeps, so their signs are the exact ones.
struct QuadGap {
  Quad g, slope;
};
QuadGap QuadGapAt(const Vec3& pa, const Vec3& va, const Vec3& pb, const Vec3& vb, const Vec3& shift,
                  double reach, double dt) {
  Quad q2 = 0, qdv = 0;
  for (int k = 0; k < 3; ++k) {
    const Quad dp = static_cast<Quad>(pb[k]) + shift[k] - pa[k];
    const Quad dv = static_cast<Quad>(vb[k]) - va[k];
    const Quad q = dp + dv * static_cast<Quad>(dt);
    q2 += q * q;
    qdv += q * dv;
  }
  const Quad r = reach;
  return {q2 - r * r, 2 * qdv};
}

// The exact first meeting of the paths, to a double, by bisection on the 128-bit gap between
// `open` (a time at which the gap is open and closing) and a time a little after it.
double QuadRoot(const Vec3& pa, const Vec3& va, const Vec3& pb, const Vec3& vb, const Vec3& shift,
                double reach, double open) {
  double lo = open, hi = open * (1 + 1e-6) + 1e-300;
  for (int i = 0; i < 200 && lo < hi; ++i) {
    const double mid = lo + (hi - lo) / 2;
    if (mid == lo || mid == hi) break;
    const QuadGap at = QuadGapAt(pa, va, pb, vb, shift, reach, mid);
    if (at.g > 0 && at.slope < 0) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return lo;
}

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

// Spheres a few radii apart, aimed roughly at each other, on every scale of coordinates and
// far from the origin too (the error of the positions' differences then dominates).
struct RandomPair {
  Vec3 pa, va, pb, vb, shift;
  double reach;
};
RandomPair MakePair(scenes::Random& random, int trial) {
  const double scale = std::pow(10.0, random.Uniform(-3.0, 3.0));
  const Vec3 offset = trial % 4 == 0 ? Vec3::Constant(random.Uniform(-1e3, 1e3)) : Vec3::Zero();
  const Vec3 pa(random.Uniform(-1, 1), random.Uniform(-1, 1), random.Uniform(-1, 1));
  const Vec3 pb = pa + Vec3(random.Uniform(-3, 3), random.Uniform(-3, 3), random.Uniform(-3, 3));
  const Vec3 va(random.Uniform(-1, 1), random.Uniform(-1, 1), random.Uniform(-1, 1));
  const Vec3 vb = va + (pa - pb) * random.Uniform(0.0, 2.0) +
                  Vec3(random.Uniform(-1, 1), random.Uniform(-1, 1), random.Uniform(-1, 1));
  const Vec3 shift = trial % 3 == 0 ? Vec3(scale * 8, 0.0, -scale * 8) : Vec3::Zero();
  const double reach = random.Uniform(0.5, 1.5);
  return {(pa + offset) * scale, va, (pb + offset) * scale - shift, vb, shift, reach * scale};
}

// Every certified meeting is open and closing in exact terms (never late), and close to the
// exact first meeting: within 2^-30 of its time plus what the double positions allow.
TEST(LinearMeeting, CertifiedTimesAreNeverLateAndTight) {
  scenes::Random random(20261125);
  int meetings = 0, loose = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    const RandomPair p = MakePair(random, trial);
    const double got = PredictLinearMeeting(p.pa, p.va, p.pb, p.vb, p.shift, p.reach);
    if (got == kInfinity || got == 0.0) continue;
    ++meetings;
    const QuadGap at = QuadGapAt(p.pa, p.va, p.pb, p.vb, p.shift, p.reach, got);
    ASSERT_TRUE(at.g > 0 && at.slope < 0) << "trial " << trial << ": late at " << got;
    const double exact = QuadRoot(p.pa, p.va, p.pb, p.vb, p.shift, p.reach, got);
    ASSERT_LE(got, exact) << "trial " << trial;
    if (exact - got > 0x1p-30 * exact + 1e-12 * (p.pa.norm() + p.pb.norm())) ++loose;
  }
  EXPECT_GT(meetings, 20000) << "the sample should hold many certified meetings";
  EXPECT_LT(loose, meetings / 1000) << "certified times should hug the exact meeting";
}

// The certification in doubles alone: where it answers, never late; it answers for nearly all
// meetings of the sample and leaves grazing pairs (a slope near zero at the root) to the
// long-double loop.
TEST(LinearMeeting, DoublePathAnswersClearMeetingsAndLeavesGrazesToTheLoop) {
  scenes::Random random(20261127);
  int meetings = 0, answered = 0, at_root = 0;
  for (int trial = 0; trial < 100000; ++trial) {
    const RandomPair p = MakePair(random, trial);
    const Vec3 dp = p.pb + p.shift - p.pa, dv = p.vb - p.va;
    const double root =
        LinearMeetingRoot(dp.head<2>(), dp[2], dv.head<2>(), dv[2], [&p] { return p.reach; });
    if (root == kInfinity || root == 0.0) continue;
    ++meetings;
    const double got = CertifyLinearInDoubles(p.pa, p.va, p.pb, p.vb, p.shift, p.reach, root);
    if (got < 0) continue;
    ++answered;
    if (SameBits(got, root)) ++at_root;
    const QuadGap gap = QuadGapAt(p.pa, p.va, p.pb, p.vb, p.shift, p.reach, got);
    ASSERT_TRUE(gap.g > 0 && gap.slope < 0) << "trial " << trial << ": late at " << got;
  }
  EXPECT_GT(meetings, 10000);
  EXPECT_GT(answered, meetings * 99 / 100);
  EXPECT_GT(at_root, 0) << "a root whose gap is certainly open needs no step";

  // A graze: b passes a at exactly the reach, tangent; the slope at the root is ~0.
  const Vec3 pa(0, 0, 0), va(0, 0, 0), pb(-5, 1, 0), vb(1, 0, 0);
  EXPECT_LT(CertifyLinearInDoubles(pa, va, pb, vb, Vec3::Zero(), 1.0, 5.0), 0.0);
  EXPECT_LE(CertifyLinearMeeting(pa, va, pb, vb, Vec3::Zero(), 1.0, 5.0), 5.0);
}

// The gathered test's branch-free verdict (TestGathered) is LinearMeetingRoot's: both early
// exits (separating, passing wide), overlap by round-off (root 0) and real roots.
TEST(LinearMeeting, BranchFreeVerdictIsTheRootFinding) {
  scenes::Random random(20261126);
  int roots = 0, zeros = 0, separating = 0, wide = 0;
  for (int trial = 0; trial < 400000; ++trial) {
    const double scale = std::pow(10.0, random.Uniform(-3.0, 3.0));
    const Vec3 dp =
        scale * Vec3(random.Uniform(-3, 3), random.Uniform(-3, 3), random.Uniform(-3, 3));
    const Vec3 dv = Vec3(random.Uniform(-1, 1), random.Uniform(-1, 1), random.Uniform(-1, 1)) -
                    dp * random.Uniform(0.0, 2.0) / scale;
    // Some pairs overlap (reach beyond |dp|), some touch exactly, the rest are apart.
    double reach = scale * random.Uniform(0.2, 2.0);
    if (trial % 50 == 0) reach = dp.norm();
    if (trial % 97 == 0) reach = 0.0;
    const double expected =
        LinearMeetingRoot(dp.head<2>(), dp[2], dv.head<2>(), dv[2], [reach] { return reach; });
    const bool found = LinearMeetingFound(dp.head<2>(), dp[2], dv.head<2>(), dv[2], reach);
    ASSERT_EQ(found, expected != kInfinity) << "trial " << trial << ": " << expected;
    const double b = dp.dot(dv);
    if (b >= 0) {
      ++separating;
    } else if (expected == kInfinity) {
      ++wide;
    } else if (expected == 0.0) {
      ++zeros;
    } else {
      ++roots;
    }
  }
  EXPECT_GT(roots, 20000);
  EXPECT_GT(zeros, 2000);
  EXPECT_GT(separating, 10000);
  EXPECT_GT(wide, 20000);
}

}  // namespace
}  // namespace sparsedyn
