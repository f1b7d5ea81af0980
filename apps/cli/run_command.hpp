// SPDX-License-Identifier: MIT
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace sparsedyn::cli {

/// Registers `sparsedyn run` (DESIGN.md "Command line") on `app`. `program` is how the user
/// invokes the tool (printed in the "view it with" hint).
void AddRunCommand(CLI::App& app, const std::string& program);

}  // namespace sparsedyn::cli
