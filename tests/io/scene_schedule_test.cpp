// SPDX-License-Identifier: MIT
// Scene files that run on in time (docs/scene-format.md): the top-level "start_time" and a
// body's "thrust_schedule", read into WorldSettings::start_time and BodyDef::thrust_schedule,
// each bad entry refused by its JSON path.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/scene_test_util.hpp"
#include "sparsedyn/io/scene_file.hpp"

namespace sparsedyn {
namespace {

const std::filesystem::path& kDataDir = testing::kSceneDataDir;
const auto ErrorOf = testing::SceneErrorOf;

// A scene with `top` members and one sphere whose schedule is `schedule` (JSON text).
std::string WithSchedule(const std::string& schedule, const std::string& top = "") {
  return "{" + top + (top.empty() ? "" : ", ") +
         R"("bodies": [{"shape": {"sphere": {"radius": 0.5}}, "thrust_schedule": )" + schedule +
         "}]}";
}

TEST(SceneSchedule, StartTimeAndScheduleAreRead) {
  Result<SceneDescription> scene = ParseScene(
      WithSchedule(R"([{"time": 3, "thrust": [1, 0, 0]}, {"time": 4.5, "thrust": [0, 0, 0]}])",
                   R"("start_time": 2.5, "duration": 4)"),
      "s.json", kDataDir);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->settings.start_time, 2.5);
  EXPECT_EQ(scene->EndTime(), 6.5);  // duration counts from the start
  const std::vector<ThrustChange>& schedule = scene->bodies[0].thrust_schedule;
  ASSERT_EQ(schedule.size(), 2u);
  EXPECT_EQ(schedule[0].time, 3.0);
  EXPECT_EQ(schedule[0].thrust, Vec3(1, 0, 0));
  EXPECT_EQ(schedule[1].time, 4.5);
  EXPECT_EQ(SceneBodyDef(*scene, 0).thrust_schedule.size(), 2u);
}

TEST(SceneSchedule, TheWorldStartsAtStartTimeAndFollowsTheSchedule) {
  // At rest from t = 2.5; pushed by 1 m/s^2 along x from t = 3 to 4.5: x(6.5) =
  // 1/2 * 1.5^2 + 1.5 * (6.5 - 4.5) = 1.125 + 3 = 4.125 m.
  Result<SceneDescription> scene = ParseScene(
      WithSchedule(R"([{"time": 3, "thrust": [1, 0, 0]}, {"time": 4.5, "thrust": [0, 0, 0]}])",
                   R"("start_time": 2.5)"),
      "s.json", kDataDir);
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  Result<World> world = BuildWorld(*scene);
  ASSERT_TRUE(world.ok()) << world.error().message;
  EXPECT_EQ(world->Time(), 2.5);
  ASSERT_TRUE(world->AdvanceTo(6.5));
  const BodyState s = world->StateAt(world->IdOf(0), 6.5);
  // Three segments of exact binary fractions: only the polynomial's rounding remains.
  EXPECT_NEAR(s.position.x(), 4.125, 1e-14);
  EXPECT_NEAR(s.velocity.x(), 1.5, 1e-15);
  EXPECT_EQ(s.acceleration, Vec3::Zero());
}

TEST(SceneSchedule, WrittenBackOnlyWhereGiven) {
  Result<SceneDescription> plain =
      ParseScene(R"({"bodies": [{"shape": "cube.off"}]})", "p.json", kDataDir);
  ASSERT_TRUE(plain.ok());
  const std::string text = FormatScene(*plain);
  EXPECT_EQ(text.find("start_time"), std::string::npos) << text;
  EXPECT_EQ(text.find("thrust_schedule"), std::string::npos) << text;
  plain->settings.start_time = 7;
  plain->bodies[0].thrust_schedule = {{8, Vec3(0, 0, 1)}};
  const std::string later = FormatScene(*plain);
  EXPECT_NE(later.find("\"start_time\": 7.0"), std::string::npos) << later;
  EXPECT_NE(later.find(R"("thrust_schedule":[{"time":8.0,"thrust":[0.0,0.0,1.0]}])"),
            std::string::npos)
      << later;
}

TEST(SceneScheduleErrors, StartTimeOutOfRange) {
  EXPECT_EQ(ErrorOf(WithSchedule("[]", R"("start_time": -1)")),
            "s.json: start_time: must be in [0.0, 1000000000000.0], got -1.0");
  EXPECT_EQ(ErrorOf(WithSchedule("[]", R"("start_time": "soon")")),
            "s.json: start_time: must be a number, got string \"soon\"");
}

TEST(SceneScheduleErrors, EachBadEntryIsNamedByItsPath) {
  const std::string prefix = "s.json: bodies[0].thrust_schedule";
  EXPECT_EQ(ErrorOf(WithSchedule(R"({"time": 1})")),
            prefix + ": must be an array of {\"time\": t, \"thrust\": [x, y, z]}, got object");
  EXPECT_EQ(ErrorOf(WithSchedule("[3]")), prefix + "[0]: must be an object, got number 3");
  EXPECT_EQ(ErrorOf(WithSchedule(R"([{"thrust": [0, 0, 1]}])")), prefix + "[0].time: is missing");
  EXPECT_EQ(ErrorOf(WithSchedule(R"([{"time": 1, "thrust": [0, 0, 1], "until": 2}])")),
            prefix + "[0].until: unknown key (allowed here: time, thrust)");
  EXPECT_EQ(ErrorOf(WithSchedule(R"([{"time": 1, "thrust": [0, 1]}])")),
            prefix + "[0].thrust: must be an array of 3 numbers, got an array of 2");
  EXPECT_EQ(ErrorOf(WithSchedule(R"([{"time": 1, "thrust": [0, "up", 1]}])")),
            prefix + "[0].thrust[1]: must be a number, got string \"up\"");
}

TEST(SceneScheduleErrors, TimesMustIncreaseFromTheStart) {
  const std::string prefix = "s.json: bodies[0].thrust_schedule";
  EXPECT_EQ(ErrorOf(WithSchedule(R"([{"time": 2, "thrust": [0, 0, 1]}])", R"("start_time": 3)")),
            prefix + "[0].time: must not be before start_time (3.0), got 2.0");
  EXPECT_EQ(ErrorOf(WithSchedule(R"([{"time": 2, "thrust": [0, 0, 1]},)"
                                 R"( {"time": 2, "thrust": [0, 0, 0]}])")),
            prefix +
                "[1].time: must be later than bodies[0].thrust_schedule[0].time (2.0), "
                "got 2.0");
  // A change at the start itself is allowed: it applies from the first instant.
  EXPECT_EQ(ErrorOf(WithSchedule(R"([{"time": 3, "thrust": [0, 0, 1]}])", R"("start_time": 3)")),
            "<parsed>");
}

}  // namespace
}  // namespace sparsedyn
