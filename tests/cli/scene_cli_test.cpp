// SPDX-License-Identifier: MIT
// `sparsedyn run SCENE.json`, `--write-scene` and the main job (`sparsedyn run` with no
// arguments writes a recording and says how to view it).
#include <gtest/gtest.h>
#include <unistd.h>

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

// Runs the CLI with `arguments` in the folder `cwd`, capturing stdout (and stderr if asked).
Output RunCli(const std::string& arguments, bool with_stderr = false,
              const std::filesystem::path& cwd = ".") {
  const std::string command = "cd '" + cwd.string() + "' && " + SPARSEDYN_CLI_PATH + " " +
                              arguments + (with_stderr ? " 2>&1" : " 2>/dev/null");
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) out += buffer.data();
  const int status = pclose(pipe);
  return {WEXITSTATUS(status), out};
}

class CliScene : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("sparsedyn_cli_scene_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string Path(const std::string& name) const { return (dir_ / name).string(); }

  std::filesystem::path dir_;
};

// The summary without the wall-clock figures, which are the only ones allowed to differ.
std::string Deterministic(const std::string& json_text) {
  nlohmann::json j = nlohmann::json::parse(json_text);
  j.erase("wall_seconds");
  j.erase("collisions_per_second");
  j.erase("events_per_second");
  return j.dump();
}

TEST_F(CliScene, WrittenPresetRunsBitForBitTheSame) {
  const std::string scene = Path("gas.json");
  ASSERT_EQ(RunCli("run --preset gas --n 500 --write-scene " + scene).status, 0);
  ASSERT_TRUE(std::filesystem::exists(scene));
  const Output preset = RunCli("run --preset gas --n 500 --json");
  const Output file = RunCli("run " + scene + " --json");
  ASSERT_EQ(preset.status, 0);
  ASSERT_EQ(file.status, 0);
  EXPECT_EQ(Deterministic(preset.out), Deterministic(file.out));
  EXPECT_GT(nlohmann::json::parse(file.out)["collisions"].get<int>(), 100);

  // --until is written into the scene as its duration.
  ASSERT_EQ(RunCli("run --preset gas --n 200 --seed 4 --until 2.5 --write-scene " + scene).status,
            0);
  EXPECT_EQ(Deterministic(RunCli("run --preset gas --n 200 --seed 4 --until 2.5 --json").out),
            Deterministic(RunCli("run " + scene + " --json").out));
}

TEST_F(CliScene, BadSceneFileFailsNamingThePathAndRunsNothing) {
  std::ofstream(Path("bad.json"))
      << R"({"bodies": [{"shape": {"sphere": {"radius": 0.5}}, "velocity": [1, "x", 0]}]})";
  const Output result =
      RunCli("run " + Path("bad.json") + " --record " + Path("r.sdrec"), /*with_stderr=*/true);
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.out.find("bad.json: bodies[0].velocity[1]: must be a number, got string \"x\""),
            std::string::npos)
      << result.out;
  EXPECT_FALSE(std::filesystem::exists(Path("r.sdrec"))) << "nothing runs on a bad file";

  const Output missing = RunCli("run " + Path("none.json"), /*with_stderr=*/true);
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.out.find("none.json: cannot open"), std::string::npos) << missing.out;

  const Output mixed = RunCli("run " + Path("bad.json") + " --n 5", /*with_stderr=*/true);
  EXPECT_EQ(mixed.status, 2);
  EXPECT_NE(mixed.out.find("--n applies to presets, not to a scene file"), std::string::npos);
}

TEST_F(CliScene, PolyhedralScenesRun) {
  std::ofstream(Path("poly.json")) << R"({"bodies": [
      {"shape": {"generator": "dodecahedron"}, "velocity": [1, 0, 0]},
      {"shape": {"generator": "cube"}, "position": [4, 0.3, 0], "angular_velocity": [0, 1, 0]}],
      "duration": 5})";
  const Output result = RunCli("run " + Path("poly.json") + " --json --no-record",
                               /*with_stderr=*/true);
  ASSERT_EQ(result.status, 0) << result.out;
  const nlohmann::json summary = nlohmann::json::parse(result.out);
  EXPECT_GE(summary["collisions"].get<int>(), 1) << result.out;
  EXPECT_NEAR(summary["kinetic_energy_final"].get<double>(),
              summary["kinetic_energy_initial"].get<double>(),
              1e-12 * summary["kinetic_energy_initial"].get<double>());
}

TEST_F(CliScene, MainJobRecordsTheDefaultSceneAndPrintsTheViewCommand) {
  const Output result = RunCli("run --until 1", /*with_stderr=*/false, dir_);
  ASSERT_EQ(result.status, 0);
  EXPECT_TRUE(std::filesystem::exists(dir_ / "sparsedyn-default.sdrec"));
  EXPECT_NE(result.out.find(" view sparsedyn-default.sdrec\n"), std::string::npos) << result.out;
  const Output lines = RunCli("export-jsonl sparsedyn-default.sdrec", false, dir_);
  ASSERT_EQ(lines.status, 0);
  EXPECT_NE(lines.out.find(R"("scene":"default")"), std::string::npos);

  // --record overrides the default path, --no-record writes nothing.
  ASSERT_EQ(RunCli("run --until 0.5 --record other.sdrec", false, dir_).status, 0);
  EXPECT_TRUE(std::filesystem::exists(dir_ / "other.sdrec"));
  std::filesystem::remove(dir_ / "sparsedyn-default.sdrec");
  ASSERT_EQ(RunCli("run --until 0.5 --no-record", false, dir_).status, 0);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "sparsedyn-default.sdrec"));
}

}  // namespace
