// SPDX-License-Identifier: MIT
// Finite but absurd values are refused before a run, naming the body and the field (issue #39
// part 4); WorldSettings are checked by the library (part 9); a refused polyhedron leaves no
// cached shape behind.
#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <string>

#include "scenes/presets.hpp"
#include "sparsedyn/geometry/generators.hpp"
#include "sparsedyn/io/scene_file.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {
namespace {

World BoxWorld() { return World({.container = Container::WalledBox({0, 0, 0}, {10, 10, 10})}); }

void ExpectRefused(const BodyDef& def, const std::string& fragment) {
  World world = BoxWorld();
  const Result<BodyId> added = world.AddBody(def);
  ASSERT_FALSE(added) << fragment;
  EXPECT_NE(added.error().message.find("body 0: " + fragment), std::string::npos)
      << added.error().message;
  EXPECT_EQ(world.BodyCount(), 0u);
}

TEST(HostileValues, AbsurdMagnitudesAreRefusedByField) {
  ExpectRefused({.radius = 0.5, .position = {5, 5, 5}, .velocity = {1e300, 0, 0}}, "velocity[0]");
  ExpectRefused({.radius = 0.5, .position = {5, 5, 5}, .thrust = {0, 0, -1e101}}, "thrust[2]");
  ExpectRefused({.radius = 0.5, .position = {5, 5, 5}, .angular_velocity = {0, 1e200, 0}},
                "angular_velocity[1]");
  ExpectRefused({.radius = 1e-300, .position = {5, 5, 5}}, "radius");
  ExpectRefused({.radius = 1e300, .position = {5, 5, 5}}, "radius");
  ExpectRefused({.radius = 0.5, .position = {5, 5, 5}, .mass = 1e-300}, "mass");
  ExpectRefused({.radius = 0.5, .position = {5, 5, 5}, .mass = 1e300}, "mass");
}

TEST(HostileValues, ARadiusLostInTheRoundOffOfItsCoordinatesIsRefused) {
  // 2^-40 of the box's largest coordinate (10) is 9.1e-12.
  ExpectRefused({.radius = 5e-12, .position = {5, 5, 5}}, "radius");
  World world = BoxWorld();
  EXPECT_TRUE(world.AddBody({.radius = 2e-11, .position = {5, 5, 5}}));
  // In an open world the body's own coordinates count.
  World open;
  EXPECT_FALSE(open.AddBody({.radius = 1e-3, .position = {1e10, 0, 0}}));
  EXPECT_TRUE(open.AddBody({.radius = 1e-3, .position = {1e6, 0, 0}}));
}

TEST(HostileValues, AnEndTimeWhoseClockStepExceedsTheMotionIsRefused) {
  World world = BoxWorld();
  ASSERT_TRUE(world.AddBody({.radius = 0.5, .position = {5, 5, 5}, .velocity = {1, 0, 0}}));
  EXPECT_TRUE(CheckClockResolution(world, 1e6));
  // ulp(1e300) is ~1e284 s; the body crosses its radius in 0.5 s.
  const Status far = CheckClockResolution(world, 1e300);
  ASSERT_FALSE(far);
  EXPECT_NE(far.error().message.find("end time 1.0000000000000001e+300"), std::string::npos)
      << far.error().message;
  const Status nan = CheckClockResolution(world, std::numeric_limits<double>::quiet_NaN());
  ASSERT_FALSE(nan);
  EXPECT_NE(nan.error().message.find("finite"), std::string::npos);
  // At rest nothing moves: any finite end time is fine.
  World still = BoxWorld();
  ASSERT_TRUE(still.AddBody({.radius = 0.5, .position = {5, 5, 5}}));
  EXPECT_TRUE(CheckClockResolution(still, 1e300));
}

TEST(SettingsValidation, EachBadSettingIsNamed) {
  EXPECT_TRUE(ValidateSettings({}));
  const auto expect_named = [](WorldSettings settings, const std::string& field) {
    const Status status = ValidateSettings(settings);
    ASSERT_FALSE(status) << field;
    EXPECT_NE(status.error().message.find("settings." + field), std::string::npos)
        << status.error().message;
  };
  expect_named({.container = Container::WalledBox({0, 0, 0}, {1, 0, 1})}, "container.hi[1]");
  expect_named({.container = Container::PeriodicBox({0, std::nan(""), 0}, {1, 1, 1})},
               "container.lo[1]");
  expect_named({.container = Container::WalledBox({0, 0, 0}, {1, 1, 1e200})}, "container.hi[2]");
  expect_named({.gravity = {0, 0, std::numeric_limits<double>::infinity()}}, "gravity[2]");
  expect_named({.contact_tolerance = -1e-9}, "contact_tolerance");
  expect_named({.elastic_below_speed = std::nan("")}, "elastic_below_speed");
  expect_named({.grid_cells_per_body = 0}, "grid_cells_per_body");
  expect_named({.stall_event_limit = 0}, "stall_event_limit");
  expect_named({.start_time = std::nan("")}, "start_time");
  expect_named({.start_time = std::numeric_limits<double>::infinity()}, "start_time");
  expect_named({.start_time = 1e300}, "start_time");
}

TEST(SettingsValidation, BuildWorldReturnsTheSettingsError) {
  SceneDescription scene;
  scene.settings.container = Container::WalledBox({0, 0, 0}, {1, 1, 1});
  scene.settings.grid_cells_per_body = -1;
  scene.AddShape(SphereShape(0.1));
  scene.bodies.push_back({.position = {0.5, 0.5, 0.5}});
  const Result<World> world = BuildWorld(scene);
  ASSERT_FALSE(world);
  EXPECT_NE(world.error().message.find("settings.grid_cells_per_body"), std::string::npos)
      << world.error().message;
}

TEST(SettingsValidation, ARefusedPolyhedronLeavesNoCachedShape) {
  auto cube = std::make_shared<const ConvexPolyhedron>(MakeSolid(PlatonicSolid::kCube));
  World world = BoxWorld();
  // Outside the box: refused after the World has looked at (and cached) its shape.
  ASSERT_FALSE(world.AddBody({.shape = cube, .position = {0.2, 5, 5}}));
  EXPECT_EQ(cube.use_count(), 1) << "the World still holds the refused body's shape";
  ASSERT_TRUE(world.AddBody({.shape = cube, .position = {5, 5, 5}}));
  EXPECT_GT(cube.use_count(), 1);
}

}  // namespace
}  // namespace sparsedyn
