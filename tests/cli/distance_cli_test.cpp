// SPDX-License-Identifier: MIT
// `sparsedyn distance` as scripts use it: the JSON contract, every mesh format, bad input.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace {

struct Output {
  int status;
  std::string out;
};

Output RunCli(const std::string& arguments, bool with_stderr = false) {
  const std::string command =
      std::string(SPARSEDYN_CLI_PATH) + " " + arguments + (with_stderr ? " 2>&1" : " 2>/dev/null");
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) out += buffer.data();
  const int status = pclose(pipe);
  return {WEXITSTATUS(status), out};
}

std::string Data(const std::string& name) {
  return std::string(SPARSEDYN_SOURCE_DIR) + "/data/" + name;
}

TEST(CliDistance, JsonHasEveryContractKey) {
  // data/cube.* is [-1, 1]^3: B three units along x is one unit away, face to face.
  const Output r = RunCli("distance " + Data("cube.off") + " " + Data("cube.off") +
                          " --pose-b 3 0.5 0.25 1 0 0 0 --json");
  ASSERT_EQ(r.status, 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key :
       {"distance", "point_a", "point_b", "normal", "feature_a", "feature_b", "steps"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_NEAR(j["distance"].get<double>(), 1.0, 1e-15);
  EXPECT_NEAR(j["normal"][0].get<double>(), 1.0, 1e-15);
  EXPECT_NEAR(j["point_a"][0].get<double>(), 1.0, 1e-15);
  EXPECT_NEAR(j["point_b"][0].get<double>(), 2.0, 1e-15);
  const std::string feature = j["feature_a"];
  EXPECT_TRUE(feature.rfind("vertex ", 0) == 0 || feature.rfind("edge ", 0) == 0 ||
              feature.rfind("face ", 0) == 0)
      << feature;
}

TEST(CliDistance, EveryMeshFormatGivesTheSameDistance) {
  const std::string pose =
      " --pose-a 0 0 0 0.9238795325112867 0 0 0.3826834323650898"
      " --pose-b 2.5 2.5 0.3 1 0 0 0 --json";
  const double expected = nlohmann::json::parse(
      RunCli("distance " + Data("cube.off") + " " + Data("cube.off") + pose).out)["distance"];
  for (const char* extension : {"obj", "stl", "ply", "ohio"}) {
    SCOPED_TRACE(extension);
    const std::string file = Data(std::string("cube.") + extension);
    const Output r = RunCli("distance " + file + " " + file + pose);
    ASSERT_EQ(r.status, 0);
    EXPECT_NEAR(nlohmann::json::parse(r.out)["distance"].get<double>(), expected, 1e-6);
  }
}

TEST(CliDistance, OverlapIsANegativeDistance) {
  const Output r = RunCli("distance " + Data("cube.off") + " " + Data("cube.off") +
                          " --pose-b 1.75 0 0 1 0 0 0 --json");
  ASSERT_EQ(r.status, 0);
  EXPECT_NEAR(nlohmann::json::parse(r.out)["distance"].get<double>(), -0.25, 1e-15);
}

TEST(CliDistance, HumanReadableOutputNamesTheFeatures) {
  const Output r = RunCli("distance " + Data("cube.off") + " " + Data("tetrahedron.off") +
                          " --pose-b 0 0 5 1 0 0 0");
  ASSERT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("separated: distance"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("normal from A to B"), std::string::npos) << r.out;
}

TEST(CliDistance, QuaternionsWithinOneMillionthOfUnitAreNormalised) {
  const Output r = RunCli("distance " + Data("cube.off") + " " + Data("cube.off") +
                          " --pose-b 3 0 0 1.0000005 0 0 0 --json");
  ASSERT_EQ(r.status, 0);
  EXPECT_NEAR(nlohmann::json::parse(r.out)["distance"].get<double>(), 1.0, 1e-15);
}

TEST(CliDistance, BadInputFailsWithAMessageNamingIt) {
  const std::string malformed =
      (std::filesystem::temp_directory_path() / "sparsedyn_distance_malformed.off").string();
  std::ofstream(malformed) << "OFF\n8 6 0\n0 0 0\n";
  const std::string cube = Data("cube.off");
  const struct {
    std::string arguments;
    const char* expected;
  } cases[] = {
      {"distance " + cube + " nosuch.off", "nosuch.off"},
      {"distance " + cube + " " + malformed, "sparsedyn_distance_malformed.off"},
      {"distance " + cube + " " + cube + " --pose-b 3 0 0 0 0 0 0", "--pose-b"},
      {"distance " + cube + " " + cube + " --pose-a 0 0 0 2 0 0 0", "--pose-a"},
      {"distance " + cube + " " + cube + " --pose-a 0 0 0 1 0 0", "--pose-a"},
      {"distance " + cube + " " + cube + " --pose-b inf 0 0 1 0 0 0", "--pose-b"},
      {"distance " + cube, "B"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.arguments);
    const Output r = RunCli(c.arguments, /*with_stderr=*/true);
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.out.find(c.expected), std::string::npos) << r.out;
  }
  std::filesystem::remove(malformed);
}

}  // namespace
