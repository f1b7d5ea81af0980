// SPDX-License-Identifier: MIT
#pragma once

#include <CLI/CLI.hpp>

namespace sparsedyn::cli {

/// Registers `sparsedyn run` (DESIGN.md "Command line") on `app`.
void AddRunCommand(CLI::App& app);

}  // namespace sparsedyn::cli
