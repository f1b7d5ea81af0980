// SPDX-License-Identifier: MIT
// `sparsedyn run` when things go wrong (issue #39 parts 4 and 8): values it cannot run are
// refused naming the option before any work, and a run that fails keeps what it did — a valid
// recording up to the last processed event, the summary with its "error" — and exits non-zero.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli_runner.hpp"

namespace {

using sparsedyn::testing::RunCli;
using sparsedyn::testing::TempPath;

TEST(CliReliability, UntilNanAndUntilBeyondTheClocksResolutionNameTheOption) {
  // nan and 1e300 are refused by the option parser, 1e11 by the clock check (ulp 1.5e-5 s).
  for (const char* until : {"nan", "1e300", "1e11"}) {
    const auto result = RunCli(std::string("run --preset gas --n 50 --until ") + until, true);
    EXPECT_NE(result.status, 0) << until;
    EXPECT_NE(result.out.find("--until"), std::string::npos) << result.out;
  }
}

// A sphere as wide as its box, moving across it: it touches both walls at once, every wall
// event happens at the same time, and the event loop stalls after stall_event_limit events.
constexpr const char* kStallingScene = R"({
  "duration": 1.0,
  "stall_event_limit": 1000,
  "container": {"kind": "walled", "lo": [0, 0, 0], "hi": [1, 4, 4]},
  "bodies": [{"shape": {"sphere": {"radius": 0.5}}, "position": [0.5, 2, 2],
              "velocity": [1, 0.25, 0]}]
})";

TEST(CliReliability, AFailedRunKeepsItsRecordingAndPrintsItsSummaryWithTheError) {
  const std::filesystem::path scene = TempPath("stall.json");
  const std::filesystem::path recording = TempPath("stall.sdrec");
  std::ofstream(scene) << kStallingScene;
  const auto result =
      RunCli("run " + scene.string() + " --record " + recording.string() + " --json");
  EXPECT_EQ(result.status, 1) << result.out;
  const nlohmann::json summary = nlohmann::json::parse(result.out);
  ASSERT_TRUE(summary.contains("error")) << result.out;
  EXPECT_NE(summary["error"].get<std::string>().find("stall"), std::string::npos)
      << summary["error"];
  EXPECT_GE(summary["events"].get<double>(), 999);
  // The recording is complete up to where the run stopped: export-jsonl reads it to its end.
  ASSERT_GT(std::filesystem::file_size(recording), 0u);
  const auto exported = RunCli("export-jsonl " + recording.string(), true);
  EXPECT_EQ(exported.status, 0) << exported.out;
  EXPECT_NE(exported.out.find("\"record\":\"end\""), std::string::npos);
  std::filesystem::remove(scene);
  std::filesystem::remove(recording);
}

}  // namespace
