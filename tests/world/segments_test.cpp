// SPDX-License-Identifier: MIT
// OnSegment reports every path change: replaying the segments from the initial states gives the
// World's own state at any later time (what a recording relies on).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "scenes/gas.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {
namespace {

TEST(Segments, ReplayedSegmentsReproduceStateAt) {
  scenes::GasOptions options;
  options.n = 200;
  options.packing = 0.10;
  options.seed = 5;
  options.periodic = false;
  World world = *scenes::MakeGas(options);
  std::vector<MotionSegment> last(options.n);
  for (std::uint32_t i = 0; i < options.n; ++i) {
    const BodyState s = world.StateAt(world.IdOf(i), 0.0);
    last[i] = MotionSegment{0.0, world.IdOf(i), s.position, s.velocity, s.acceleration, 0};
  }
  std::uint64_t segments = 0;
  double previous_t0 = 0.0;
  world.OnSegment([&](const MotionSegment& s) {
    EXPECT_GE(s.t0, previous_t0) << "segments come in event order";
    previous_t0 = s.t0;
    EXPECT_EQ(s.version, last[s.body.index].version + 1) << "no path change is skipped";
    last[s.body.index] = s;
    ++segments;
  });
  ASSERT_TRUE(world.AdvanceTo(20.0));
  const Statistics& stats = world.Stats();
  EXPECT_EQ(segments, 2 * stats.collisions + stats.wall_collisions);
  EXPECT_GT(stats.collisions, 1000u);
  for (std::uint32_t i = 0; i < options.n; ++i) {
    const MotionSegment& s = last[i];
    const double dt = 20.0 - s.t0;
    const Vec3 replayed = s.position + dt * s.velocity + 0.5 * dt * dt * s.acceleration;
    const BodyState state = world.StateAt(world.IdOf(i), 20.0);
    EXPECT_LT((replayed - state.position).norm(), 1e-12) << "body " << i;
    EXPECT_EQ(s.version, state.version);
  }
}

}  // namespace
}  // namespace sparsedyn
