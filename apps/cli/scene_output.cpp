// SPDX-License-Identifier: MIT
#include "apps/cli/scene_output.hpp"

#include <filesystem>

namespace sparsedyn::cli {

Status CheckScenePath(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (fs::is_directory(path, error)) return Error{path + ": is a folder, not a file"};
  const fs::path folder = fs::path(path).parent_path();
  if (!folder.empty() && !fs::is_directory(folder, error)) {
    return Error{path + ": the folder " + folder.string() + " does not exist"};
  }
  return Status::Ok();
}

Status WriteSceneFile(SceneDescription scene, const std::string& scene_file,
                      const std::string& path) {
  namespace fs = std::filesystem;
  // Mesh paths were read relative to the scene file; the new file may live elsewhere.
  if (!scene_file.empty()) {
    RebaseMeshPaths(scene, fs::path(scene_file).parent_path(), fs::path(path).parent_path());
  }
  return WriteScene(scene, path);
}

Status WriteFinalScene(const SceneDescription& scene, const std::string& scene_file,
                       const World& world, const std::vector<BodyId>& ids,
                       const std::string& path) {
  return WriteSceneFile(FinalScene(scene, world, ids), scene_file, path);
}

}  // namespace sparsedyn::cli
