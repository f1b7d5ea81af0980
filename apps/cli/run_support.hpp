// SPDX-License-Identifier: MIT
// What both methods of `sparsedyn run` report the same way.
#pragma once

#include <nlohmann/json.hpp>

#include "apps/cli/run_options.hpp"
#include "scenes/presets.hpp"
#include "sparsedyn/io/run_summary.hpp"
#include "sparsedyn/io/scene_file.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn::cli {

/// A vector as a JSON array [x, y, z].
inline nlohmann::json VectorJson(const Vec3& v) { return {v[0], v[1], v[2]}; }

/// The packing fraction reported as "density" (ReportedPacking, shared with Python).
inline double PackingOf(const SceneDescription& scene) { return ReportedPacking(scene); }

/// The preset the options ask for (--preset, --n, --density, --seed; "default" when none).
inline scenes::PresetRequest PresetRequestOf(const RunOptions& options) {
  scenes::PresetRequest request;
  request.name = options.preset.value_or("default");
  request.n = options.n;
  request.density = options.density;
  request.seed = options.seed;
  return request;
}

}  // namespace sparsedyn::cli
