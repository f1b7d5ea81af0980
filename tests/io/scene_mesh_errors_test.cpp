// SPDX-License-Identifier: MIT
// A bad mesh named by a scene is reported with the mesh file (and its line when the file is
// malformed), after the JSON path of the shape (issue #39 part 4).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "sparsedyn/io/scene_file.hpp"

namespace sparsedyn {
namespace {

std::string ErrorOfSceneWith(const std::string& file, const std::string& content) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "sparsedyn_scene_mesh";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / file) << content;
  const std::string json = R"({"bodies": [{"shape": ")" + file + R"(", "position": [0, 0, 0]}]})";
  const Result<SceneDescription> scene = ParseScene(json, "s.json", dir);
  std::filesystem::remove(dir / file);
  return scene ? "<parsed>" : scene.error().message;
}

TEST(SceneMeshErrors, AMalformedMeshIsNamedWithItsLine) {
  const std::string error =
      ErrorOfSceneWith("bad.off", "OFF\n4 4 6\n0 0 0\n1 0 0\n0 one 0\n0 0 1\n");
  EXPECT_EQ(error.rfind("s.json: bodies[0].shape.mesh: ", 0), 0u) << error;
  EXPECT_NE(error.find("bad.off:5:"), std::string::npos) << error;
}

TEST(SceneMeshErrors, ANonConvexMeshIsNamedWithItsFile) {
  // An open surface (one face missing): read fine, refused as a polyhedron.
  const std::string error = ErrorOfSceneWith("open.off",
                                             "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                             "3 0 2 1\n3 0 1 3\n3 0 3 2\n");
  EXPECT_EQ(error.rfind("s.json: bodies[0].shape.mesh: ", 0), 0u) << error;
  EXPECT_NE(error.find("open.off: "), std::string::npos) << error;
}

TEST(SceneMeshErrors, ARefusedPolyhedronLeavesNoCachedShapeBehind) {
  // Two bodies name one degenerate mesh (every vertex the same point): the shape built once per
  // spec must not be cached when refused, so the second body is refused too, not given a shape.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "sparsedyn_scene_mesh";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "point.off") << "OFF\n4 4 6\n1 1 1\n1 1 1\n1 1 1\n1 1 1\n"
                                      "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const std::string body = R"({"shape": "point.off", "position": [0, 0, 0]})";
  const Result<SceneDescription> scene =
      ParseScene(R"({"bodies": [)" + body + ", " + body + "]}", "s.json", dir);
  std::filesystem::remove(dir / "point.off");
  ASSERT_FALSE(scene.ok());
  const std::string& error = scene.error().message;
  EXPECT_NE(error.find("bodies[0].shape.mesh: "), std::string::npos) << error;
  EXPECT_NE(error.find("bodies[1].shape.mesh: "), std::string::npos) << error;
  EXPECT_NE(error.find("all 4 vertices coincide"), std::string::npos) << error;
}

}  // namespace
}  // namespace sparsedyn
