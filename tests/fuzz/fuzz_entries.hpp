// SPDX-License-Identifier: MIT
// The fuzz targets (issue #39 part 1): what each does with one input and which invariants it
// checks. Shared by the libFuzzer executables (fuzz_main.cpp) and the ordinary test that
// replays the seed corpora and every kept finding (fuzz_replay_test.cpp), so a finding stays
// a regression case that every build checks.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace sparsedyn::fuzz {

/// The target names, also the folders under tests/fuzz/corpus/ and tests/fuzz/regressions/:
/// off, obj, stl, ply, ohio, scene, recording, polyhedron.
std::span<const std::string_view> TargetNames();

/// Runs `bytes` through `target` (one of TargetNames()). Returns "" when every invariant
/// holds, otherwise what broke. A crash, a hang or a sanitizer report is a finding too.
std::string RunInput(std::string_view target, std::string_view bytes);

}  // namespace sparsedyn::fuzz
