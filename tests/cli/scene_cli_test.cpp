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

TEST_F(CliScene, JsonCountsTheBodiesByKind) {
  // data/scenes/floor_drop.json: a static floor slab and a static ramp (boxes), two spheres and
  // a cube; the statics are counted as static only, and the three kinds add up to "bodies".
  const Output drop = RunCli("run " + std::string(SPARSEDYN_SOURCE_DIR) +
                             "/data/scenes/floor_drop.json --until 0.5 --json --no-record");
  ASSERT_EQ(drop.status, 0) << drop.out;
  const nlohmann::json summary = nlohmann::json::parse(drop.out);
  EXPECT_EQ(summary["bodies"], 5);
  EXPECT_EQ(summary["bodies_by_kind"],
            nlohmann::json({{"spheres", 2}, {"polyhedra", 1}, {"static", 2}, {"god", 0}}));

  // A static sphere is static, a moving polyhedron among spheres a polyhedron.
  std::ofstream(Path("kinds.json")) << R"({"container": {"kind": "walled", "lo": [0, 0, 0],
      "hi": [10, 10, 10]}, "bodies": [
      {"shape": {"sphere": {"radius": 1}}, "position": [5, 5, 5], "static": true},
      {"shape": {"generator": "cube"}, "position": [2, 2, 2], "velocity": [1, 0, 0]},
      {"shape": {"sphere": {"radius": 0.5}}, "position": [8, 8, 8]},
      {"shape": {"sphere": {"radius": 0.5}}, "position": [8, 2, 8]},
      {"shape": {"sphere": {"radius": 0.5}}, "position": [2, 8, 8]}], "duration": 1})";
  const Output kinds = RunCli("run " + Path("kinds.json") + " --json --no-record");
  ASSERT_EQ(kinds.status, 0) << kinds.out;
  EXPECT_EQ(nlohmann::json::parse(kinds.out)["bodies_by_kind"],
            nlohmann::json({{"spheres", 3}, {"polyhedra", 1}, {"static", 1}, {"god", 0}}));

  // A god object is counted as one, whatever its shape (here a cube), and not as a polyhedron.
  std::ofstream(Path("gods.json")) << R"({"container": {"kind": "walled", "lo": [0, 0, 0],
      "hi": [10, 10, 10]}, "bodies": [
      {"shape": {"generator": "cube"}, "position": [2, 5, 5],
       "god": {"max_acceleration": 2, "track": [{"time": 1, "position": [3, 5, 5]}]}},
      {"shape": {"sphere": {"radius": 0.5}}, "position": [5, 5, 8],
       "god": {"max_acceleration": 1, "track": []}},
      {"shape": {"sphere": {"radius": 0.5}}, "position": [8, 8, 8]}], "duration": 1})";
  const Output gods = RunCli("run " + Path("gods.json") + " --json --no-record");
  ASSERT_EQ(gods.status, 0) << gods.out;
  EXPECT_EQ(nlohmann::json::parse(gods.out)["bodies_by_kind"],
            nlohmann::json({{"spheres", 1}, {"polyhedra", 0}, {"static", 0}, {"god", 2}}));
}

TEST_F(CliScene, EveryShippedSceneRunsToItsEnd) {
  // Each scene of data/scenes/ runs with `sparsedyn run SCENE` to start_time + duration, and its
  // bodies by kind add up to its bodies (god_sweep.json: one god object among 300 spheres).
  const std::filesystem::path folder = std::filesystem::path(SPARSEDYN_SOURCE_DIR) / "data/scenes";
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    ++scenes;
    std::ifstream in(entry.path());
    const nlohmann::json scene = nlohmann::json::parse(in);
    const Output run = RunCli("run " + entry.path().string() + " --json --no-record",
                              /*with_stderr=*/true);
    ASSERT_EQ(run.status, 0) << run.out;
    const nlohmann::json summary = nlohmann::json::parse(run.out);
    EXPECT_FALSE(summary.contains("error"));
    EXPECT_EQ(summary["simulated_time"].get<double>(),
              scene.value("start_time", 0.0) + scene.value("duration", 10.0));
    EXPECT_EQ(summary["bodies"], scene["bodies"].size());
    const nlohmann::json& kinds = summary["bodies_by_kind"];
    EXPECT_EQ(kinds["spheres"].get<int>() + kinds["polyhedra"].get<int>() +
                  kinds["static"].get<int>() + kinds["god"].get<int>(),
              summary["bodies"].get<int>());
    int gods = 0;
    for (const nlohmann::json& body : scene["bodies"]) gods += body.contains("god") ? 1 : 0;
    EXPECT_EQ(kinds["god"].get<int>(), gods);
  }
  EXPECT_GE(scenes, 4);
}

TEST_F(CliScene, MixedBoxKeepsItsEnergyWithSpheresAndPolyhedraTogether) {
  // data/scenes/mixed_box.json: 20 spheres and 20 rotating polyhedra in a walled box, elastic
  // and frictionless, so the kinetic energy is conserved through every kind of contact (the
  // spherical-top rotation model conserves it exactly between events too).
  const Output run = RunCli("run " + std::string(SPARSEDYN_SOURCE_DIR) +
                            "/data/scenes/mixed_box.json --json --no-record");
  ASSERT_EQ(run.status, 0);
  const nlohmann::json summary = nlohmann::json::parse(run.out);
  EXPECT_EQ(summary["bodies_by_kind"],
            nlohmann::json({{"spheres", 20}, {"polyhedra", 20}, {"static", 0}, {"god", 0}}));
  EXPECT_GT(summary["body_collisions"].get<int>(), 50);
  const double energy = summary["kinetic_energy_initial"].get<double>();
  EXPECT_NEAR(summary["kinetic_energy_final"].get<double>(), energy, 1e-12 * energy);
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
