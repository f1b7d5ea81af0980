// SPDX-License-Identifier: MIT
#pragma once

#include <CLI/CLI.hpp>

namespace sparsedyn::cli {

/// Registers `sparsedyn distance A B [--pose-a x y z qw qx qy qz] [--pose-b ...] [--json]`
/// (DESIGN.md "Command line"): closest features of two convex polyhedra read from mesh files.
void AddDistanceCommand(CLI::App& app);

}  // namespace sparsedyn::cli
