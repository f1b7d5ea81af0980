// SPDX-License-Identifier: MIT
#pragma once

// What the scene-file tests share: the data folder the scenes' mesh paths are read from, and
// the error a scene text gives.

#include <filesystem>
#include <string>

#include "sparsedyn/io/scene_file.hpp"

namespace sparsedyn::testing {

/// data/ of the source tree: mesh paths of the test scenes are relative to it.
inline const std::filesystem::path kSceneDataDir =
    std::filesystem::path(SPARSEDYN_SOURCE_DIR) / "data";

/// The error of parsing scene text `json` as the file "s.json", or "<parsed>".
inline std::string SceneErrorOf(const std::string& json) {
  Result<SceneDescription> scene = ParseScene(json, "s.json", kSceneDataDir);
  return scene ? std::string("<parsed>") : scene.error().message;
}

}  // namespace sparsedyn::testing
