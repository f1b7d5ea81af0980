// SPDX-License-Identifier: MIT
// Progress of a long `sparsedyn run` on the terminal (stderr only).
#pragma once

#include <cstdint>
#include <string>

#include "sparsedyn/result.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn::cli {

/// One progress line: the simulated time reached of `until`, the events so far and, from the
/// wall time `elapsed` spent on the `fraction` done, an estimate of the wall time left.
std::string FormatProgress(double t, double until, std::uint64_t events, double elapsed,
                           double fraction);

/// Advances `world` to `until` in slices (the slices do not change the result: AdvanceTo(t)
/// processes the same events whatever the intermediate stops). When stderr is a terminal and
/// the run has taken longer than half a second, each slice rewrites one progress line there;
/// stdout (the `--json` object) is never touched.
Status AdvanceWithProgress(World& world, double until);

}  // namespace sparsedyn::cli
