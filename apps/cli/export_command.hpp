// SPDX-License-Identifier: MIT
#pragma once

#include <CLI/CLI.hpp>

namespace sparsedyn::cli {

/// Registers `sparsedyn export-jsonl IN.sdrec [-o OUT.jsonl]` on `app`.
void AddExportCommand(CLI::App& app);

}  // namespace sparsedyn::cli
