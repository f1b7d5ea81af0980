// SPDX-License-Identifier: MIT
// Bad input is refused with an error naming the body and the field; the World is unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "sparsedyn/world.hpp"

namespace sparsedyn {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Case {
  const char* name;
  BodyDef def;
  const char* expected;  // a fragment the message must contain
};

World MakeWorld() {
  WorldSettings settings;
  settings.container = Container::WalledBox({0, 0, 0}, {10, 10, 10});
  World world(settings);
  EXPECT_TRUE(world.AddBody({.radius = 0.5, .position = {2, 2, 2}, .velocity = {1, 0, 0}}));
  EXPECT_TRUE(world.AddBody({.radius = 0.5, .position = {8, 2, 2}, .velocity = {-1, 0, 0}}));
  return world;
}

TEST(BadInput, EachBadBodyIsRefusedByNameAndFieldAndChangesNothing) {
  const Case cases[] = {
      {"nan position", {.radius = 0.5, .position = {5, kNaN, 5}}, "body 2: position[1]"},
      {"inf velocity", {.radius = 0.5, .position = {5, 5, 5}, .velocity = {INFINITY, 0, 0}},
       "body 2: velocity[0]"},
      {"zero radius", {.radius = 0, .position = {5, 5, 5}}, "body 2: radius"},
      {"negative radius", {.radius = -1, .position = {5, 5, 5}}, "body 2: radius"},
      {"nan radius", {.radius = kNaN, .position = {5, 5, 5}}, "body 2: radius"},
      {"zero mass", {.radius = 0.5, .position = {5, 5, 5}, .mass = 0}, "body 2: mass"},
      {"negative mass", {.radius = 0.5, .position = {5, 5, 5}, .mass = -2}, "body 2: mass"},
      {"restitution > 1", {.radius = 0.5, .position = {5, 5, 5}, .restitution = 1.5},
       "body 2: restitution"},
      {"restitution < 0", {.radius = 0.5, .position = {5, 5, 5}, .restitution = -0.1},
       "body 2: restitution"},
      {"negative envelope",
       {.radius = 0.5, .position = {5, 5, 5}, .envelope = {.e0 = 0, .e1 = -1, .e2 = 0}},
       "body 2: envelope.e1"},
      {"overlap at start", {.radius = 0.5, .position = {2.5, 2, 2}}, "body 2: overlaps body 0"},
      {"outside container", {.radius = 0.5, .position = {9.8, 5, 5}}, "body 2: position[0]"},
  };
  // The reference run: the same world with no refused body in between.
  World reference = MakeWorld();
  ASSERT_TRUE(reference.AdvanceTo(10));

  World world = MakeWorld();
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    Result<BodyId> result = world.AddBody(c.def);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.error().message.find(c.expected), std::string::npos)
        << "message: " << result.error().message;
    EXPECT_EQ(world.BodyCount(), 2u);
  }
  ASSERT_TRUE(world.AdvanceTo(10));
  EXPECT_EQ(world.Stats().events, reference.Stats().events);
  EXPECT_EQ(world.StateAt(world.IdOf(0), 10).position, reference.StateAt(reference.IdOf(0), 10).position);
}

TEST(BadInput, PeriodicBoxRefusesPositionsOutsideAndHugeSpheres) {
  WorldSettings settings;
  settings.container = Container::PeriodicBox({0, 0, 0}, {10, 10, 10});
  World world(settings);
  Result<BodyId> outside = world.AddBody({.radius = 0.5, .position = {10, 5, 5}});
  ASSERT_FALSE(outside.ok());
  EXPECT_NE(outside.error().message.find("periodic box"), std::string::npos);
  Result<BodyId> huge = world.AddBody({.radius = 3, .position = {5, 5, 5}});
  ASSERT_FALSE(huge.ok());
  EXPECT_NE(huge.error().message.find("too large"), std::string::npos);
  EXPECT_EQ(world.BodyCount(), 0u);
}

TEST(BadInput, OverlapAcrossThePeriodicBoundaryIsFound) {
  WorldSettings settings;
  settings.container = Container::PeriodicBox({0, 0, 0}, {10, 10, 10});
  World world(settings);
  ASSERT_TRUE(world.AddBody({.radius = 0.5, .position = {0.2, 5, 5}}));
  Result<BodyId> across = world.AddBody({.radius = 0.5, .position = {9.7, 5, 5}});
  ASSERT_FALSE(across.ok());
  EXPECT_NE(across.error().message.find("overlaps body 0"), std::string::npos);
}

TEST(BadInput, NonFiniteAdvanceTimeIsAnError) {
  World world;
  EXPECT_FALSE(world.AdvanceTo(kNaN).ok());
  EXPECT_EQ(world.Time(), 0.0);
}

}  // namespace
}  // namespace sparsedyn
