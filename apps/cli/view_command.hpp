// SPDX-License-Identifier: MIT
#pragma once

#include <CLI/CLI.hpp>

namespace sparsedyn::cli {

/// Registers `sparsedyn view FILE.sdrec [--port P] [--html OUT.html]` on `app`: serves the web
/// viewer (docs/viewer.md) and the recording on localhost, or writes one self-contained page.
void AddViewCommand(CLI::App& app);

}  // namespace sparsedyn::cli
