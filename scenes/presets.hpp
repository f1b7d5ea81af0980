// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sparsedyn/io/scene_file.hpp"
#include "sparsedyn/result.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn::scenes {

/// What a preset can be asked for (the CLI's --n --density --seed, and the broad phase).
/// Unset values take the preset's defaults.
struct PresetRequest {
  std::string name = "default";
  std::optional<std::uint32_t> n;
  std::optional<double> density;
  std::optional<std::uint64_t> seed;
  std::optional<Broadphase> broadphase;
};

/// A ready World, the fully expanded scene it was built from (what `--write-scene` writes; the
/// World is BuildWorld(scene)) and what the preset chose.
struct Preset {
  World world;
  SceneDescription scene;
  std::string name;
  std::uint32_t n = 0;
  double density = 0;
  std::uint64_t seed = 0;
  double default_duration = 0;  // simulated seconds the preset is meant to run
};

/// The names of every preset ("default", "gas", ...).
std::vector<std::string> PresetNames();

/// Builds a preset; an unknown name or an out-of-range value is an Error naming it.
Result<Preset> MakePreset(const PresetRequest& request);

}  // namespace sparsedyn::scenes
