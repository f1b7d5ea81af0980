// SPDX-License-Identifier: MIT
// 10^5 random drag bodies (random g, linear and quadratic drag, start, check time and
// allowance): the true motion, densely sampled, never leaves the path plus envelope of
// DragMotion::SegmentFor over its horizon (issue #36, part 10). Slow: ~10^7 evaluations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

#include "motion/drag_envelope_check.hpp"

namespace sparsedyn {
namespace {

TEST(DragEnvelopeSlow, HundredThousandRandomBodiesNeverLeaveTheirEnvelopes) {
  std::mt19937_64 rng(20261209);
  double worst = 0.0;
  std::vector<double> horizons;
  for (int trial = 0; trial < 100000; ++trial) {
    const testing::DragBody b = testing::RandomDragBody(rng);
    SCOPED_TRACE(b.Describe());
    double horizon = 0.0;
    const double ratio =
        testing::WorstEnvelopeRatio(b, 32, 1e3, trial % 100 == 0 ? 4 : 0, &horizon);
    ASSERT_LE(ratio, 1.0);
    worst = std::max(worst, ratio);
    horizons.push_back(horizon);
  }
  std::sort(horizons.begin(), horizons.end());
  std::printf("worst distance / envelope %.6f; horizons: 10%% %.3g s, median %.3g s, 90%% %.3g s\n",
              worst, horizons[horizons.size() / 10], horizons[horizons.size() / 2],
              horizons[horizons.size() * 9 / 10]);
}

}  // namespace
}  // namespace sparsedyn
