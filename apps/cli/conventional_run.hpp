// SPDX-License-Identifier: MIT
#pragma once

#include "apps/cli/run_options.hpp"

namespace sparsedyn::cli {

/// `sparsedyn run --method conventional --dt DT [--digits A]`: the scene or preset run by the
/// ConventionalWorld (docs/conventional.md); prints the same summary as the event-driven run plus
/// "method", "dt" and "steps". Returns the exit status (2 for bad options or input).
int RunConventional(const RunOptions& options);

}  // namespace sparsedyn::cli
