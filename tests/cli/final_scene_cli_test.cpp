// SPDX-License-Identifier: MIT
// Scenes that run on from a later time: a scene's "start_time" with `sparsedyn run`, and the
// scene `--write-final-scene` writes at a run's end.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "support/cli_runner.hpp"

namespace sparsedyn {
namespace {

using testing::CliOutput;
using testing::RunCli;
using testing::TempPath;

// One sphere at rest from t = 2, pushed along x by 1 m/s^2 from t = 3.
constexpr const char* kRocket = R"({"start_time": 2, "duration": 3, "bodies": [
    {"shape": {"sphere": {"radius": 0.5}},
     "thrust_schedule": [{"time": 3, "thrust": [1, 0, 0]}]}]})";

TEST(CliStartTime, ASceneRunsFromItsStartTimeForItsDuration) {
  const std::filesystem::path scene = TempPath("rocket.json");
  std::ofstream(scene) << kRocket;
  const CliOutput result = RunCli("run " + scene.string() + " --json --no-record");
  ASSERT_EQ(result.status, 0);
  const nlohmann::json summary = nlohmann::json::parse(result.out);
  EXPECT_EQ(summary["simulated_time"], 5.0);  // start_time + duration
  EXPECT_EQ(summary["events_by_kind"]["body_timer"], 1);
  // 1/2 * 1 m/s^2 * (5 - 3 s)^2 = 2 J for 1 kg.
  EXPECT_NEAR(summary["kinetic_energy_final"].get<double>(), 2.0, 1e-14);

  const CliOutput early = RunCli("run " + scene.string() + " --until 1", /*with_stderr=*/true);
  EXPECT_EQ(early.status, 2);
  EXPECT_NE(early.out.find("--until 1 is before the scene's start_time 2"), std::string::npos)
      << early.out;

  const CliOutput conventional =
      RunCli("run " + scene.string() + " --method conventional --dt 0.01", /*with_stderr=*/true);
  EXPECT_EQ(conventional.status, 2);
  EXPECT_NE(conventional.out.find("start_time must be 0"), std::string::npos) << conventional.out;
  std::filesystem::remove(scene);
}

// A folder of its own for each test, removed afterwards.
class CliFinalScene : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = TempPath(::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }

  std::filesystem::path dir_;
};

nlohmann::json ReadJson(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// Spheres and polyhedra far apart in open space, spinning under gravity, one with a thrust
// schedule with changes before and after t = 3: no collision ever.
constexpr const char* kApart = R"({"gravity": [0, 0, -1], "bodies": [
    {"shape": {"sphere": {"radius": 0.5}}, "velocity": [1, 0.25, 0], "mass": 2,
     "thrust_schedule": [{"time": 1.5, "thrust": [0.5, 0, 1]}, {"time": 6, "thrust": [0, 0, 0]}]},
    {"shape": {"generator": "cube", "scale": 0.5}, "position": [0, 20, 0],
     "velocity": [-0.3, 0.1, 2], "angular_velocity": [0.3, -1, 2], "density": 3},
    {"shape": {"sphere": {"radius": 1.5}}, "position": [-20, -20, 0], "velocity": [0, -1, 0]}]})";

// Written scenes hold positions of order 10 m and velocities of order 1 m/s to the last bit;
// the run on from t1 re-evaluates them about t1 (tests/io/final_scene_test.cpp says why 1e-12).
constexpr double kRoundOff = 1e-12;

void ExpectSameBodies(const nlohmann::json& a, const nlohmann::json& b) {
  ASSERT_EQ(a["bodies"].size(), b["bodies"].size());
  for (std::size_t i = 0; i < a["bodies"].size(); ++i) {
    SCOPED_TRACE("body " + std::to_string(i));
    const nlohmann::json& x = a["bodies"][i];
    const nlohmann::json& y = b["bodies"][i];
    for (const char* key : {"position", "velocity", "orientation", "angular_velocity"}) {
      for (std::size_t k = 0; k < x[key].size(); ++k) {
        EXPECT_NEAR(x[key][k].get<double>(), y[key][k].get<double>(), kRoundOff) << key;
      }
    }
    for (const char* key : {"shape", "thrust", "thrust_schedule", "mass", "density"}) {
      EXPECT_EQ(x.value(key, nlohmann::json()), y.value(key, nlohmann::json())) << key;
    }
  }
}

TEST_F(CliFinalScene, RunningOnFromTheFinalSceneIsOneRunToRoundOff) {
  std::ofstream(Path("apart.json")) << kApart;
  // 0 -> 3, then 3 -> 8 from the written scene, against 0 -> 8 in one run.
  ASSERT_EQ(
      RunCli("run " + Path("apart.json") + " --until 3 --write-final-scene " + Path("at3.json"))
          .status,
      0);
  const CliOutput on = RunCli("run " + Path("at3.json") + " --until 8 --json " +
                              "--write-final-scene " + Path("on8.json"));
  ASSERT_EQ(on.status, 0);
  ASSERT_EQ(
      RunCli("run " + Path("apart.json") + " --until 8 --write-final-scene " + Path("at8.json"))
          .status,
      0);
  const nlohmann::json at3 = ReadJson(Path("at3.json"));
  EXPECT_EQ(at3["start_time"], 3.0);
  EXPECT_EQ(at3["bodies"][0]["thrust"], nlohmann::json::array({0.5, 0.0, 1.0}));
  EXPECT_EQ(at3["bodies"][0]["thrust_schedule"].size(), 1u);  // the change at 6 is still ahead
  const nlohmann::json summary = nlohmann::json::parse(on.out);
  EXPECT_EQ(summary["simulated_time"], 8.0);
  EXPECT_EQ(summary["final_scene"], Path("on8.json"));
  EXPECT_EQ(summary["collisions"], 0);
  const nlohmann::json on8 = ReadJson(Path("on8.json"));
  const nlohmann::json at8 = ReadJson(Path("at8.json"));
  EXPECT_EQ(on8["start_time"], 8.0);
  EXPECT_EQ(at8["start_time"], 8.0);
  ExpectSameBodies(on8, at8);
}

// The first collision after `t1` in a recording's JSON lines: {a, b, time}.
nlohmann::json FirstCollisionAfter(const std::string& recording, double t1) {
  std::istringstream lines(RunCli("export-jsonl " + recording).out);
  for (std::string line; std::getline(lines, line);) {
    const nlohmann::json record = nlohmann::json::parse(line);
    if (record["record"] == "collision" && record["time"].get<double>() > t1) return record;
  }
  return nullptr;
}

TEST_F(CliFinalScene, WithCollisionsTheRunOnMeetsTheFirstCollisionAfterT1) {
  // A gas in a periodic box, colliding all the time: the run on from t1 = 2 meets the same
  // first pair at the same time as the run from 0 (later the chaos may tell the ulp apart).
  const std::string preset = "--preset gas --n 300 --density 0.2 --seed 3";
  ASSERT_EQ(RunCli("run " + preset + " --until 2 --write-final-scene " + Path("at2.json")).status,
            0);
  ASSERT_EQ(RunCli("run " + preset + " --until 3 --record " + Path("whole.sdrec")).status, 0);
  ASSERT_EQ(RunCli("run " + Path("at2.json") + " --until 3 --record " + Path("on.sdrec")).status,
            0);
  const nlohmann::json whole = FirstCollisionAfter(Path("whole.sdrec"), 2.0);
  const nlohmann::json on = FirstCollisionAfter(Path("on.sdrec"), 2.0);
  ASSERT_FALSE(whole.is_null());
  ASSERT_FALSE(on.is_null());
  // The same two bodies, in either order (which one predicted is not part of the collision).
  EXPECT_TRUE((on["a"] == whole["a"] && on["b"] == whole["b"]) ||
              (on["a"] == whole["b"] && on["b"] == whole["a"]))
      << on << " vs " << whole;
  // A root of paths that differ by round-off: it moves by that over the closing speed.
  EXPECT_NEAR(on["time"].get<double>(), whole["time"].get<double>(), 1e-9);
}

TEST_F(CliFinalScene, MeshPathsFollowTheWrittenFile) {
  std::filesystem::create_directories(dir_ / "in");
  std::filesystem::create_directories(dir_ / "out");
  std::filesystem::copy_file(std::filesystem::path(SPARSEDYN_SOURCE_DIR) / "data" / "cube.off",
                             dir_ / "in" / "cube.off");
  std::ofstream(Path("in/s.json"))
      << R"({"bodies": [{"shape": "cube.off", "velocity": [1, 0, 0]}]})";
  ASSERT_EQ(
      RunCli("run " + Path("in/s.json") + " --until 1 --write-final-scene " + Path("out/f.json"))
          .status,
      0);
  EXPECT_EQ(ReadJson(Path("out/f.json"))["bodies"][0]["shape"]["mesh"], "../in/cube.off");
  const CliOutput on = RunCli("run " + Path("out/f.json") + " --until 2 --json");
  ASSERT_EQ(on.status, 0);
  EXPECT_EQ(nlohmann::json::parse(on.out)["simulated_time"], 2.0);
}

TEST_F(CliFinalScene, BareFileNamesAreInTheCurrentFolder) {
  // The scene and the final scene named without a folder: both in the working directory.
  const std::filesystem::path cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir_);
  std::ofstream("apart.json") << kApart;
  const CliOutput first = RunCli("run apart.json --until 1 --write-final-scene at1.json", true);
  const CliOutput on = RunCli("run at1.json --until 2 --json");
  std::filesystem::current_path(cwd);
  ASSERT_EQ(first.status, 0) << first.out;
  ASSERT_EQ(on.status, 0);
  EXPECT_EQ(nlohmann::json::parse(on.out)["simulated_time"], 2.0);
}

TEST_F(CliFinalScene, BadPathsAndOptionsAreNamedBeforeTheRun) {
  std::ofstream(Path("apart.json")) << kApart;
  const std::string run = "run " + Path("apart.json") + " --until 1 ";
  const struct {
    std::string arguments;
    std::string expected;
  } cases[] = {
      {"--write-final-scene " + Path("no/such/folder/f.json"),
       "--write-final-scene: " + Path("no/such/folder/f.json") + ": the folder " +
           Path("no/such/folder") + " does not exist"},
      {"--write-final-scene " + dir_.string(),
       "--write-final-scene: " + dir_.string() + ": is a folder, not a file"},
      {"--write-scene " + Path("a.json") + " --write-final-scene " + Path("b.json"),
       "--write-scene runs nothing, --write-final-scene writes after a run: give one"},
      {"--write-final-scene " + Path("b.json") + " --method conventional --dt 0.1",
       "--write-final-scene and --broadphase apply to --method event"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.arguments);
    const CliOutput result = RunCli(run + c.arguments, /*with_stderr=*/true);
    EXPECT_EQ(result.status, 2);
    EXPECT_NE(result.out.find(c.expected), std::string::npos) << result.out;
  }
  EXPECT_FALSE(std::filesystem::exists(Path("b.json"))) << "nothing is written on bad options";
}

}  // namespace
}  // namespace sparsedyn
