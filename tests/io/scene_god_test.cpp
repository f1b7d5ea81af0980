// SPDX-License-Identifier: MIT
// God objects in scene files (docs/scene-format.md, "god"): read into BodyDef::god, written back
// to the bit, every bad entry refused by its JSON path, written by FinalScene with the targets
// still ahead, and recorded with the god flag.
#include <gtest/gtest.h>

#include <string>

#include "io/scene_test_util.hpp"
#include "sparsedyn/io/recording.hpp"
#include "sparsedyn/io/scene_file.hpp"

namespace sparsedyn {
namespace {

const auto ErrorOf = testing::SceneErrorOf;

// A scene with one god sphere whose "god" value is `god` (JSON text), and a ball.
std::string WithGod(const std::string& god, const std::string& top = "") {
  return "{" + top + (top.empty() ? "" : ", ") +
         R"("bodies": [{"shape": {"sphere": {"radius": 0.5}}, "god": )" + god +
         R"(}, {"shape": {"sphere": {"radius": 0.5}}, "position": [3, 0, 0]}]})";
}

const char* kTrack =
    R"({"max_acceleration": 2, "track": [{"time": 1, "position": [1, 0, 0]},)"
    R"( {"time": 4, "position": [6, 0, 0], "velocity": [1, 0, 0]}]})";

TEST(SceneGod, ReadBuiltAndWrittenBack) {
  Result<SceneDescription> scene = ParseScene(WithGod(kTrack), "s.json", testing::kSceneDataDir);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  ASSERT_TRUE(scene->bodies[0].god.has_value());
  const GodDef& god = *scene->bodies[0].god;
  EXPECT_EQ(god.max_acceleration, 2.0);
  ASSERT_EQ(god.track.size(), 2u);
  EXPECT_EQ(god.track[0].position, Vec3(1, 0, 0));
  EXPECT_FALSE(god.track[0].velocity.has_value());
  EXPECT_EQ(*god.track[1].velocity, Vec3(1, 0, 0));
  EXPECT_FALSE(scene->bodies[1].god.has_value());
  // Written back and read again: the same scene text.
  const std::string text = FormatScene(*scene);
  Result<SceneDescription> again = ParseScene(text, "s.json", testing::kSceneDataDir);
  ASSERT_TRUE(again.ok()) << again.error().message;
  EXPECT_EQ(FormatScene(*again), text);
  Result<World> world = BuildWorld(*scene);
  ASSERT_TRUE(world.ok()) << world.error().message;
  EXPECT_TRUE(world->IsGod(world->IdOf(0)));
  EXPECT_FALSE(world->IsGod(world->IdOf(1)));
}

TEST(SceneGod, TheFinalSceneKeepsTheTargetsAhead) {
  Result<SceneDescription> scene = ParseScene(WithGod(kTrack), "s.json", testing::kSceneDataDir);
  ASSERT_TRUE(scene.ok());
  Result<World> world = BuildWorld(*scene);
  ASSERT_TRUE(world.ok());
  const std::vector<BodyId> ids = world->Bodies();
  ASSERT_TRUE(world->AdvanceTo(2.0));
  const SceneDescription final_scene = FinalScene(*scene, *world, ids);
  ASSERT_TRUE(final_scene.bodies[0].god.has_value());
  ASSERT_EQ(final_scene.bodies[0].god->track.size(), 1u) << "the first target is behind";
  EXPECT_EQ(final_scene.bodies[0].god->track[0].time, 4.0);
  EXPECT_EQ(final_scene.bodies[0].position, world->StateAt(ids[0], 2.0).position);
  // Run on from the file: the object reaches the last target at its time and speed.
  Result<World> on = BuildWorld(final_scene);
  ASSERT_TRUE(on.ok()) << on.error().message;
  ASSERT_TRUE(on->AdvanceTo(4.0));
  const BodyState there = on->StateAt(on->IdOf(0), 4.0);
  EXPECT_LE((there.position - Vec3(6, 0, 0)).norm(), 1e-9);
  EXPECT_LE((there.velocity - Vec3(1, 0, 0)).norm(), 1e-9);
}

TEST(SceneGod, RecordedWithTheGodFlag) {
  Result<SceneDescription> scene = ParseScene(WithGod(kTrack), "s.json", testing::kSceneDataDir);
  ASSERT_TRUE(scene.ok());
  const auto [header, bodies] = DescribeForRecording(*scene, 5.0);
  ASSERT_EQ(bodies.size(), 2u);
  EXPECT_EQ(bodies[0].flags, kBodyGod);
  EXPECT_EQ(bodies[1].flags, 0u);
}

TEST(SceneGodErrors, EveryBadEntryIsNamedByItsPath) {
  EXPECT_EQ(ErrorOf(WithGod("3")), "s.json: bodies[0].god: must be an object, got number 3");
  EXPECT_EQ(ErrorOf(WithGod(R"({"track": []})")),
            "s.json: bodies[0].god.max_acceleration: is missing");
  EXPECT_EQ(ErrorOf(WithGod(R"({"max_acceleration": 0, "track": []})")),
            "s.json: bodies[0].god.max_acceleration: must be in (0.0, 1000000000000.0], got 0.0");
  EXPECT_EQ(ErrorOf(WithGod(R"({"max_acceleration": 1})")), "s.json: bodies[0].god.track: is missing");
  EXPECT_EQ(ErrorOf(WithGod(R"({"max_acceleration": 1, "track": {}})")),
            "s.json: bodies[0].god.track: must be an array of {\"time\": t, \"position\": "
            "[x, y, z]}, got object");
  EXPECT_EQ(ErrorOf(WithGod(R"({"max_acceleration": 1, "track": [{"time": 1}]})")),
            "s.json: bodies[0].god.track[0].position: is missing");
  EXPECT_EQ(ErrorOf(WithGod(R"({"max_acceleration": 1, "track": [{"time": 2, "position": [0, 0, 0]},)"
                            R"( {"time": 2, "position": [1, 0, 0]}]})")),
            "s.json: bodies[0].god.track[1].time: must be later than "
            "bodies[0].god.track[0].time (2.0), got 2.0");
  EXPECT_EQ(ErrorOf(WithGod(R"({"max_acceleration": 1, "track": [{"time": 1, "position": [0, 0, 0]}]})",
                            R"("start_time": 3)")),
            "s.json: bodies[0].god.track[0].time: must not be before start_time (3.0), got 1.0");
  EXPECT_EQ(ErrorOf(WithGod(R"({"max_acceleration": 1, "track": [{"time": 1, "position": [0, 0, 0],)"
                            R"( "speed": 2}]})")),
            "s.json: bodies[0].god.track[0].speed: unknown key (allowed here: time, position, velocity)");
  EXPECT_EQ(ErrorOf(WithGod(R"({"max_acceleration": 1, "track": [], "mass": 1})")),
            "s.json: bodies[0].god.mass: unknown key (allowed here: max_acceleration, track)");
}

}  // namespace
}  // namespace sparsedyn
