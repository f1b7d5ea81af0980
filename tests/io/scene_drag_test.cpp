// SPDX-License-Identifier: MIT
// Drag in scene files (docs/scene-format.md): "drag": {"linear": c1, "quadratic": c2} at the
// top level (WorldSettings::drag) and on a body (BodyDef::drag), written back only where
// given, each bad value refused by its JSON path.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "io/scene_test_util.hpp"
#include "support/fp_traps.hpp"
#include "sparsedyn/io/scene_file.hpp"

namespace sparsedyn {
namespace {

const std::filesystem::path& kDataDir = testing::kSceneDataDir;
const auto ErrorOf = testing::SceneErrorOf;

// A scene with `top` members and one sphere with body members `body`.
std::string Scene(const std::string& top, const std::string& body = "") {
  return "{" + top + (top.empty() ? "" : ", ") +
         R"("bodies": [{"shape": {"sphere": {"radius": 0.5}})" + (body.empty() ? "" : ", ") +
         body + "}]}";
}

TEST(SceneDrag, TopLevelAndBodyDragAreRead) {
  Result<SceneDescription> scene =
      ParseScene(Scene(R"("drag": {"linear": 0.25})", R"("drag": {"quadratic": 0.5})"),
                 "s.json", kDataDir);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->settings.drag.linear, 0.25);
  EXPECT_EQ(scene->settings.drag.quadratic, 0.0);
  ASSERT_TRUE(scene->bodies[0].drag.has_value());
  EXPECT_EQ(scene->bodies[0].drag->linear, 0.0);
  EXPECT_EQ(scene->bodies[0].drag->quadratic, 0.5);
  EXPECT_EQ(SceneBodyDef(*scene, 0).drag->quadratic, 0.5);
  // A body without "drag" takes the top level's.
  Result<SceneDescription> plain = ParseScene(Scene(R"("drag": {"linear": 0.25})"), "s.json",
                                              kDataDir);
  ASSERT_TRUE(plain.ok());
  EXPECT_FALSE(plain->bodies[0].drag.has_value());
  Result<World> world = BuildWorld(*plain);
  ASSERT_TRUE(world.ok()) << world.error().message;
  EXPECT_EQ(world->Settings().drag.linear, 0.25);
}

TEST(SceneDrag, WrittenBackOnlyWhereGivenAndReadAgainToTheBit) {
  Result<SceneDescription> plain = ParseScene(Scene(""), "p.json", kDataDir);
  ASSERT_TRUE(plain.ok());
  EXPECT_EQ(FormatScene(*plain).find("drag"), std::string::npos) << FormatScene(*plain);
  plain->settings.drag = Drag{0.1, 0.30000000000000004};
  plain->bodies[0].drag = Drag{0.7, 0};
  const std::string text = FormatScene(*plain);
  Result<SceneDescription> again = ParseScene(text, "q.json", kDataDir);
  ASSERT_TRUE(again.ok()) << again.error().message << "\n" << text;
  EXPECT_EQ(again->settings.drag.quadratic, 0.30000000000000004);
  EXPECT_EQ(again->settings.drag.linear, 0.1);
  EXPECT_EQ(again->bodies[0].drag->linear, 0.7);
  EXPECT_EQ(FormatScene(*again), text);
}

TEST(SceneDragErrors, BadValuesAreNamedByTheirJsonPath) {
  EXPECT_EQ(ErrorOf(Scene(R"("drag": {"linear": -1})")),
            "s.json: drag.linear: must be in [0.0, 1e+100], got -1.0");
  EXPECT_EQ(ErrorOf(Scene("", R"("drag": {"quadratic": -0.5})")),
            "s.json: bodies[0].drag.quadratic: must be in [0.0, 1e+100], got -0.5");
  EXPECT_NE(ErrorOf(Scene("", R"("drag": {"linear": "fast"})")).find("bodies[0].drag.linear"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Scene("", R"("drag": {"cubic": 1})")).find(
                "bodies[0].drag.cubic: unknown key (allowed here: linear, quadratic)"),
            std::string::npos)
      << ErrorOf(Scene("", R"("drag": {"cubic": 1})"));
  EXPECT_NE(ErrorOf(Scene(R"("drag": 0.5)")).find("drag: must be an object"), std::string::npos)
      << ErrorOf(Scene(R"("drag": 0.5)"));
}

TEST(SceneDragErrors, OutOfRangeForADoubleIsNotValidJson) {
  // Floating-point traps paused (docs/reliability.md): nlohmann-json reads 1e999 as +infinity
  // (an overflow in strtod) before it refuses the number.
  const sparsedyn::testing::FloatingPointTrapsPaused traps_paused;
  EXPECT_EQ(ErrorOf(Scene("", R"("drag": {"linear": 1e999})")),
            "s.json: not valid JSON: number overflow parsing '1e999'");
}

TEST(SceneDrag, DragOnAPolyhedronIsTakenFromTheScene) {
  Result<SceneDescription> scene = ParseScene(
      R"({"bodies": [{"shape": "cube.off", "velocity": [1, 0, 0], "drag": {"linear": 0.1}}]})",
      "c.json", kDataDir);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  Result<World> world = BuildWorld(*scene);
  ASSERT_TRUE(world.ok()) << world.error().message;
  ASSERT_TRUE(world->AdvanceTo(1.0));
  // Linear drag alone: v = v0 e^(-c1 t).
  EXPECT_NEAR(world->StateAt(world->IdOf(0), 1.0).velocity.x(), std::exp(-0.1), 1e-12);
}

TEST(SceneDragErrors, DragOnAGodObjectIsRefusedByTheWorld) {
  Result<SceneDescription> scene = ParseScene(
      Scene("", R"("drag": {"linear": 0.1}, "god": {"max_acceleration": 1, "track": []})"),
      "g.json", kDataDir);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  Result<World> world = BuildWorld(*scene);
  ASSERT_FALSE(world.ok());
  EXPECT_NE(world.error().message.find("drag on a god object is not supported"),
            std::string::npos)
      << world.error().message;
  // The top level's drag is not a god object's own: it builds alone.
  Result<SceneDescription> top = ParseScene(
      Scene(R"("drag": {"linear": 0.1})", R"("god": {"max_acceleration": 1, "track": []})"),
      "h.json", kDataDir);
  ASSERT_TRUE(top.ok()) << top.error().message;
  EXPECT_TRUE(BuildWorld(*top).ok());
}

}  // namespace
}  // namespace sparsedyn
