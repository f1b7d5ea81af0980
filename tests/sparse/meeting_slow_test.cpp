// SPDX-License-Identifier: MIT
// The 10^5 random pairs (linear, accelerated, with envelopes) against the oracle.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "scenes/random.hpp"
#include "sparse/meeting.hpp"
#include "support/meeting_oracle.hpp"

namespace sparsedyn {
namespace {

TEST(MeetingTimeSlow, HundredThousandRandomPairsNeverLateNeverMissed) {
  constexpr double kHorizon = 10.0;
  constexpr long double kLateSlack = 4e-15L;  // double rounding of the time itself
  scenes::Random random(77);
  int met = 0, late = 0, missed = 0;
  for (int trial = 0; trial < 100000; ++trial) {
    const auto [a, b] = testing::RandomMoverPair(random, trial % 2 == 1, trial % 3 == 2);
    if (testing::OracleGap(a, b, 0) <= 0) continue;
    const double predicted = PredictMeeting(a, b, Vec3::Zero(), kHorizon);
    const std::optional<long double> truth = testing::OracleMeeting(a, b, kHorizon, 1000);
    if (!truth) continue;
    ++met;
    if (predicted == kInfinity) {
      ++missed;
      ADD_FAILURE() << "missed meeting, trial " << trial;
    } else if (predicted > *truth + kLateSlack * (1 + *truth)) {
      ++late;
      ADD_FAILURE() << "late by " << static_cast<double>(predicted - *truth) << ", trial " << trial;
    }
  }
  EXPECT_EQ(late, 0);
  EXPECT_EQ(missed, 0);
  EXPECT_GT(met, 10000);
  std::printf("random pairs: 100000, meetings %d, late %d, missed %d\n", met, late, missed);
}

}  // namespace
}  // namespace sparsedyn
