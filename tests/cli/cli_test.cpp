// SPDX-License-Identifier: MIT
// `sparsedyn run` as scripts use it: the JSON contract, determinism and bad options.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

namespace {

struct Output {
  int status;
  std::string out;
};

// Runs the CLI with `arguments`, capturing stdout (stderr folded in when `with_stderr`).
Output RunCli(const std::string& arguments, bool with_stderr = false) {
  const std::string command = std::string(SPARSEDYN_CLI_PATH) + " " + arguments +
                              (with_stderr ? " 2>&1" : " 2>/dev/null");
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) out += buffer.data();
  const int status = pclose(pipe);
  return {WEXITSTATUS(status), out};
}

TEST(CliRun, JsonHasEveryContractKey) {
  const Output result = RunCli("run --preset gas --n 300 --until 2 --json");
  ASSERT_EQ(result.status, 0);
  const nlohmann::json j = nlohmann::json::parse(result.out);
  for (const char* key :
       {"bodies", "simulated_time", "wall_seconds", "events", "events_by_kind", "stale_events",
        "meetings", "collisions", "kinetic_energy_initial", "kinetic_energy_final",
        "momentum_initial", "momentum_final", "max_penetration"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["bodies"], 300);
  EXPECT_EQ(j["simulated_time"], 2.0);
  EXPECT_GT(j["collisions"].get<int>(), 0);
  EXPECT_EQ(j["momentum_final"].size(), 3u);
}

TEST(CliRun, SameSeedGivesTheSameSummaryBitForBit) {
  auto summary = [] {
    nlohmann::json j =
        nlohmann::json::parse(RunCli("run --preset gas --n 500 --seed 9 --until 5 --json").out);
    // Wall-clock figures are the only ones allowed to differ.
    j.erase("wall_seconds");
    j.erase("collisions_per_second");
    j.erase("events_per_second");
    return j.dump();
  };
  const std::string first = summary();
  EXPECT_EQ(first, summary());
  const std::string other_seed =
      RunCli("run --preset gas --n 500 --seed 10 --until 5 --json").out;
  EXPECT_NE(first, other_seed);
}

TEST(CliRun, BadOptionsFailWithAMessageNamingThem) {
  const struct {
    const char* arguments;
    const char* expected;
  } cases[] = {
      {"run --preset nosuch", "--preset"},
      {"run --n 0", "--n"},
      {"run --density 2", "--density"},
      {"run --broadphase octree", "--broadphase"},
      {"run --until -1", "--until"},
      {"run --bogus", "--bogus"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.arguments);
    const Output result = RunCli(c.arguments, /*with_stderr=*/true);
    EXPECT_NE(result.status, 0);
    EXPECT_NE(result.out.find(c.expected), std::string::npos) << result.out;
  }
}

TEST(CliRun, DefaultSceneRunsAndPrintsASummary) {
  const Output result = RunCli("run --until 1 --no-record");
  ASSERT_EQ(result.status, 0);
  EXPECT_NE(result.out.find("collisions"), std::string::npos);
}

}  // namespace
