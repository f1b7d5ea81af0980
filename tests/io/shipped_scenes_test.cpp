// SPDX-License-Identifier: MIT
// Every scene shipped in data/scenes/ reads, builds and runs to its end time with no error,
// passes World::Validate there (no overlap beyond the tolerance, every body inside), and does
// not gain energy unless a god object or a thrust works on it. A scene added to the folder is
// tested without being listed here.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "sparsedyn/io/scene_file.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {
namespace {

std::vector<std::filesystem::path> ShippedScenes() {
  std::vector<std::filesystem::path> scenes;
  const std::filesystem::path dir = std::filesystem::path(SPARSEDYN_SOURCE_DIR) / "data/scenes";
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".json") scenes.push_back(entry.path());
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

TEST(ShippedScenes, EveryOneRunsToItsEndAndValidates) {
  const std::vector<std::filesystem::path> scenes = ShippedScenes();
  ASSERT_GE(scenes.size(), 5u);
  for (const std::filesystem::path& path : scenes) {
    SCOPED_TRACE(path.filename().string());
    Result<SceneDescription> scene = ReadScene(path);
    ASSERT_TRUE(scene) << scene.error().message;
    Result<World> built = BuildWorld(*scene);
    ASSERT_TRUE(built) << built.error().message;
    World& world = *built;
    bool driven = false;  // something does work on the bodies
    for (const SceneBody& body : scene->bodies) {
      driven = driven || body.god || !body.thrust.isZero(0.0) || !body.thrust_schedule.empty();
    }
    const double energy = world.KineticEnergy();
    const bool gravity = !scene->settings.gravity.isZero(0.0);
    const Status run = world.AdvanceTo(scene->EndTime());
    ASSERT_TRUE(run) << run.error().message;
    EXPECT_TRUE(world.Validate());
    // Something is hit: another body or a wall (dust_drag.json ends as its grains land).
    EXPECT_GT(world.Stats().collisions + world.Stats().wall_collisions, 0u);
    if (!driven && !gravity) {
      EXPECT_LE(world.KineticEnergy(), energy * (1 + 1e-9));
    }
  }
}

}  // namespace
}  // namespace sparsedyn
