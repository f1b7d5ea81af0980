// SPDX-License-Identifier: MIT
// Scenes that run on from a later time: a scene's "start_time" with `sparsedyn run`.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
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

}  // namespace
}  // namespace sparsedyn
