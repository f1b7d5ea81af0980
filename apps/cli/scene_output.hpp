// SPDX-License-Identifier: MIT
// The scene files `sparsedyn run` writes: the scene as it starts (--write-scene) and the World
// at the end of the run, to run on from there (--write-final-scene; FinalScene in
// docs/scene-format.md).
#pragma once

#include <string>
#include <vector>

#include "sparsedyn/io/scene_file.hpp"
#include "sparsedyn/result.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn::cli {

/// Checks before the run that `path` can be a scene file to write: not a folder, in a folder
/// that exists. The Error names the path and what is wrong.
Status CheckScenePath(const std::string& path);

/// Writes `scene`, read from `scene_file` (empty for a preset), to `path`, its mesh paths
/// rewritten to be relative to `path`'s folder.
Status WriteSceneFile(SceneDescription scene, const std::string& scene_file,
                      const std::string& path);

/// Writes the scene of `world` at its clock to `path`: `scene` is what the World was built from
/// (read from `scene_file`, or a preset when that is empty) and `ids` the handles of its bodies.
Status WriteFinalScene(const SceneDescription& scene, const std::string& scene_file,
                       const World& world, const std::vector<BodyId>& ids, const std::string& path);

}  // namespace sparsedyn::cli
