// SPDX-License-Identifier: MIT
// Bad drag input (issue #36 part 11): NaN/Inf or negative coefficients, drag where it is not
// supported yet, a World default that is bad, each refused by name with the World unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "sparsedyn/geometry/generators.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

World MakeWorld(const Drag& default_drag = {}) {
  WorldSettings settings;
  settings.container = Container::WalledBox({0, 0, 0}, {10, 10, 10});
  settings.gravity = Vec3(0, 0, -9.81);
  settings.drag = default_drag;
  World world(settings);
  EXPECT_TRUE(world.AddBody({.radius = 0.5, .position = {2, 2, 2}, .velocity = {1, 0, 0},
                             .drag = Drag{0.1, 0.2}}));
  EXPECT_TRUE(world.AddBody({.radius = 0.5, .position = {8, 2, 2}, .velocity = {-1, 0, 0}}));
  return world;
}

TEST(DragBadInput, EachBadDragIsRefusedByNameAndChangesNothing) {
  const std::shared_ptr<const ConvexPolyhedron> cube =
      std::make_shared<const ConvexPolyhedron>(MakeBox(Vec3::Constant(0.5)).value());
  const struct {
    const char* name;
    BodyDef def;
    const char* expected;
  } cases[] = {
      {"nan linear", {.position = {5, 5, 5}, .drag = Drag{kNaN, 0}}, "body 2: drag.linear"},
      {"inf quadratic", {.position = {5, 5, 5}, .drag = Drag{0, INFINITY}},
       "body 2: drag.quadratic must be finite and >= 0, got inf"},
      {"negative linear", {.position = {5, 5, 5}, .drag = Drag{-0.1, 0}},
       "body 2: drag.linear must be finite and >= 0, got -0.1"},
      {"negative quadratic", {.position = {5, 5, 5}, .drag = Drag{0, -1e-300}},
       "body 2: drag.quadratic"},
      {"a polyhedron with nan drag", {.shape = cube, .position = {5, 5, 5}, .drag = Drag{0, kNaN}},
       "body 2: drag.quadratic"},
      {"with an envelope",
       {.position = {5, 5, 5}, .envelope = {.e0 = 0.1}, .drag = Drag{0.1, 0}},
       "body 2: drag and an envelope together are not supported"},
      {"a static body", {.position = {5, 5, 5}, .drag = Drag{0.1, 0}, .is_static = true},
       "body 2: a static body has no drag"},
      {"a god object", {.position = {5, 5, 5}, .drag = Drag{0.1, 0}, .god = GodDef{1.0, {}}},
       "body 2: drag on a god object is not supported (its track drives it)"},
      {"a polyhedral god object with drag",
       {.shape = cube, .position = {5, 5, 5}, .drag = Drag{0.1, 0}, .god = GodDef{1.0, {}}},
       "body 2: drag on a god object is not supported (its track drives it)"},
  };
  World reference = MakeWorld();
  ASSERT_TRUE(reference.AdvanceTo(3));
  World world = MakeWorld();
  const std::uint64_t hash = world.StateHash();
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    Result<BodyId> result = world.AddBody(c.def);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.error().message.find(c.expected), std::string::npos)
        << "message: " << result.error().message;
    EXPECT_EQ(world.BodyCount(), 2u);
    EXPECT_EQ(world.StateHash(), hash);
  }
  ASSERT_TRUE(world.AdvanceTo(3));
  EXPECT_EQ(world.StateHash(), reference.StateHash());
}

TEST(DragBadInput, DragIsTakenOnAPolyhedronAndNextToOne) {
  // Once refused (drag beside polyhedra was not supported): now any mix, with the World's
  // default drag on every body but one that says Drag{}.
  const std::shared_ptr<const ConvexPolyhedron> cube =
      std::make_shared<const ConvexPolyhedron>(MakeBox(Vec3::Constant(0.5)).value());
  WorldSettings settings;
  settings.drag = Drag{0.2, 0.1};
  World world(settings);
  const BodyId polyhedron = *world.AddBody({.shape = cube, .velocity = {1, 0, 0}});
  const BodyId sphere = *world.AddBody({.position = {5, 0, 0}, .velocity = {-1, 0, 0}});
  const BodyId plain = *world.AddBody({.position = {0, 5, 0}, .velocity = {1, 0, 0}, .drag = Drag{}});
  ASSERT_TRUE(world.AdvanceTo(1.0));
  EXPECT_LT(world.StateAt(polyhedron, 1.0).velocity.x(), 1.0);
  EXPECT_GT(world.StateAt(sphere, 1.0).velocity.x(), -1.0);
  EXPECT_EQ(world.StateAt(plain, 1.0).velocity.x(), 1.0);
  EXPECT_TRUE(world.Validate());
}

TEST(DragBadInput, AGodObjectTakesNoDragButTheBodiesBesideItDo) {
  // A god object goes where its track drives it: the World's default drag is not its own, a
  // drag of its own is refused, and a sphere beside it feels the default.
  WorldSettings settings;
  settings.container = Container::WalledBox({0, 0, 0}, {10, 10, 10});
  settings.gravity = Vec3(0, 0, -9.81);
  settings.drag = Drag{2.0, 0};
  World world(settings);
  const BodyId god = *world.AddBody(
      {.position = {5, 5, 5}, .god = GodDef{1.0, {GodTarget{1.0, {5, 5, 5}, Vec3(0, 0, 0)}}}});
  Result<BodyId> god_drag = world.AddBody(
      {.position = {8, 8, 8}, .drag = Drag{0.1, 0}, .god = GodDef{1.0, {}}});
  ASSERT_FALSE(god_drag.ok());
  EXPECT_EQ(god_drag.error().message,
            "body 1: drag on a god object is not supported (its track drives it)");
  const BodyId dragged = *world.AddBody({.position = {2, 2, 8}});
  const BodyId plain = *world.AddBody({.position = {8, 2, 8}, .drag = Drag{}});
  ASSERT_TRUE(world.AdvanceTo(0.5));
  // Linear drag with gravity: v_z(t) = -(g / c1) (1 - exp(-c1 t)).
  EXPECT_NEAR(world.StateAt(dragged, 0.5).velocity.z(), -9.81 / 2.0 * (1.0 - std::exp(-1.0)),
              1e-9);
  EXPECT_NEAR(world.StateAt(plain, 0.5).velocity.z(), -9.81 * 0.5, 1e-12);
  EXPECT_NEAR((world.StateAt(god, 0.5).position - Vec3(5, 5, 5)).norm(), 0.0, 1e-12);
  EXPECT_TRUE(world.Validate());
}

TEST(DragBadInput, TheWorldDefaultAppliesWhereTheBodySaysNothing) {
  World world = MakeWorld(Drag{2.0, 0});
  const BodyId plain = *world.AddBody({.position = {5, 5, 8}});
  const BodyId none = *world.AddBody({.position = {5, 8, 8}, .drag = Drag{}});
  ASSERT_TRUE(world.AdvanceTo(0.5));
  // Under linear drag 2/s the fall from rest is slower than free fall's g t.
  EXPECT_NEAR(world.StateAt(plain, 0.5).velocity.z(), -9.81 / 2 * (1 - std::exp(-1.0)), 1e-12);
  EXPECT_NEAR(world.StateAt(none, 0.5).velocity.z(), -9.81 * 0.5, 1e-12);
}

TEST(DragBadInput, SettingsWithBadDragAreRefusedByName) {
  WorldSettings settings;
  settings.drag = Drag{kNaN, 0};
  EXPECT_EQ(ValidateSettings(settings).error().message,
            "settings.drag.linear must be finite and >= 0, got nan");
  settings.drag = Drag{0, -2};
  EXPECT_EQ(ValidateSettings(settings).error().message,
            "settings.drag.quadratic must be finite and >= 0, got -2");
  settings.drag = Drag{0.5, 0};
  settings.contact_tolerance = 0;
  EXPECT_NE(ValidateSettings(settings).error().message.find(
                "settings.contact_tolerance must be >= 1e-12 with drag"),
            std::string::npos)
      << ValidateSettings(settings).error().message;
  // A body's own drag with a zero contact band.
  WorldSettings exact;
  exact.contact_tolerance = 0;
  World world(exact);
  Result<BodyId> body = world.AddBody({.drag = Drag{0.5, 0}});
  ASSERT_FALSE(body.ok());
  EXPECT_NE(body.error().message.find("body 0: drag needs settings.contact_tolerance >= "),
            std::string::npos)
      << body.error().message;
}

}  // namespace
}  // namespace sparsedyn
