// SPDX-License-Identifier: MIT
// The straight-line meeting of the gas hot path (LinearMeetingRoot in plain doubles, the
// LinearGap certification) against its slow twin: the Eigen formula and the general gap
// evaluation it replaced, bit for bit, on random pairs that mostly meet.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>

#include "scenes/random.hpp"
#include "sparse/meeting.hpp"

namespace sparsedyn {
namespace {

// The general gap of meeting.cpp with zero acceleration and constant reach, written out as it
// was before the linear path had its own (all the terms that are zero kept).
long double ReferenceCertify(const Vec3& pa, const Vec3& va, const Vec3& pb, const Vec3& vb,
                             const Vec3& shift, double reach, double dt) {
  long double dp[3], dv[3], da[3];
  for (int k = 0; k < 3; ++k) {
    dp[k] = static_cast<long double>(pb[k]) + shift[k] - pa[k];
    dv[k] = static_cast<long double>(vb[k]) - va[k];
    da[k] = static_cast<long double>(0.0) - 0.0;
  }
  const long double r0 = static_cast<long double>(0.0) + reach, r1 = 0.0L, r2 = 0.0L;
  double step = std::max(std::abs(dt) * 4 * DBL_EPSILON, DBL_MIN);
  for (int i = 0; i < 90 && dt > 0; ++i) {
    const long double t = dt;
    long double q2 = 0, qdq = 0, scale = 0;
    for (int k = 0; k < 3; ++k) {
      const long double q = dp[k] + t * (dv[k] + 0.5L * t * da[k]);
      const long double dq = dv[k] + t * da[k];
      q2 += q * q;
      qdq += q * dq;
      scale += dp[k] * dp[k] + t * t * (dv[k] * dv[k] + 0.25L * t * t * da[k] * da[k]);
    }
    const long double r = r0 + t * (r1 + 0.5L * t * r2);
    const long double dr = r1 + t * r2;
    const long double g = q2 - r * r;
    const long double dg = 2 * (qdq - r * dr);
    const long double error =
        32 * LDBL_EPSILON * (scale + r0 * r0 + t * t * (r1 * r1 + 0.25L * t * t * r2 * r2));
    if (g > error && dg < 0) return dt;
    dt -= step;
    step *= 2;
  }
  return std::max(dt, 0.0);
}

// The Eigen formula PredictLinearMeeting had, certified by the general gap above.
double ReferenceLinearMeeting(const Vec3& pa, const Vec3& va, const Vec3& pb, const Vec3& vb,
                              const Vec3& shift, double reach) {
  const Vec3 dp = pb + shift - pa;
  const Vec3 dv = vb - va;
  const double b_half = dp.dot(dv);
  if (b_half >= 0) return kInfinity;
  const double c = dp.dot(dp) - reach * reach;
  if (c <= 0) return 0.0;
  const double disc = b_half * b_half - dv.dot(dv) * c;
  if (disc < 0) return kInfinity;
  const double dt = c / (-b_half + std::sqrt(disc));
  if (!(dt <= kPredictionHorizon)) return kInfinity;
  if (dt == 0.0) return 0.0;
  return static_cast<double>(ReferenceCertify(pa, va, pb, vb, shift, reach, dt));
}

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

TEST(LinearMeeting, BitIdenticalToTheEigenFormulaAndGeneralGap) {
  scenes::Random random(20261125);
  int meetings = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    // Spheres a few radii apart, aimed roughly at each other, on every scale of coordinates.
    const double scale = std::pow(10.0, random.Uniform(-3.0, 3.0));
    const Vec3 pa(random.Uniform(-1, 1), random.Uniform(-1, 1), random.Uniform(-1, 1));
    const Vec3 pb = pa + Vec3(random.Uniform(-3, 3), random.Uniform(-3, 3), random.Uniform(-3, 3));
    const Vec3 va(random.Uniform(-1, 1), random.Uniform(-1, 1), random.Uniform(-1, 1));
    const Vec3 vb = va + (pa - pb) * random.Uniform(0.0, 2.0) +
                    Vec3(random.Uniform(-1, 1), random.Uniform(-1, 1), random.Uniform(-1, 1));
    const Vec3 shift = trial % 3 == 0 ? Vec3(scale * 8, 0.0, -scale * 8) : Vec3::Zero();
    const double reach = random.Uniform(0.5, 1.5);
    const Vec3 sa = pa * scale, sb = pb * scale - shift;
    const double expected = ReferenceLinearMeeting(sa, va, sb, vb, shift, reach * scale);
    const double got = PredictLinearMeeting(sa, va, sb, vb, shift, reach * scale);
    ASSERT_TRUE(SameBits(got, expected)) << "trial " << trial << ": " << got << " vs " << expected;
    if (expected != kInfinity && expected > 0) ++meetings;
  }
  EXPECT_GT(meetings, 20000) << "the sample should hold many certified meetings";
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
