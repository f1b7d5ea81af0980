// SPDX-License-Identifier: MIT
#pragma once

// Shape specs of scene files (docs/scene-format.md "Shapes"): checked in two steps so that
// bodies with equal specs share one built shape: first the spec's form (keys, types, ranges)
// into a canonical JSON, then the geometry (mesh file, generator) from the canonical spec.

#include <filesystem>
#include <optional>
#include <string>

#include "io/json_checker.hpp"
#include "sparsedyn/io/scene_file.hpp"

namespace sparsedyn::json_input {

/// The canonical spec of a shape value: a string becomes {"mesh": path}, a random generator
/// without a seed gets `default_seed`. Nullopt (with errors in `checker`) if the form is wrong.
std::optional<json> CanonicalShapeSpec(const json& value, const std::string& path,
                                       std::uint64_t default_seed, Checker& checker);

/// The shape a canonical spec describes, with mesh paths relative to `base_dir`; errors (an
/// unreadable or non-convex mesh, a generator that refuses its parameters) go to `checker`.
std::optional<SceneShape> BuildShape(const json& spec, const std::string& path,
                                     const std::filesystem::path& base_dir, Checker& checker);

}  // namespace sparsedyn::json_input
