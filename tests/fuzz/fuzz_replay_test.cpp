// SPDX-License-Identifier: MIT
// Replays every seed of tests/fuzz/corpus/<target>/ and every kept finding of
// tests/fuzz/regressions/<target>/ through the fuzz targets' own checks (fuzz_entries.cpp), in
// every ordinary build: a fixed finding stays fixed without libFuzzer.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "fuzz/fuzz_entries.hpp"

namespace sparsedyn::fuzz {
namespace {

const std::filesystem::path kFuzzDir = std::filesystem::path(SPARSEDYN_SOURCE_DIR) / "tests/fuzz";

std::string ReadBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Replays one folder of inputs; returns how many there were.
int ReplayFolder(std::string_view target, const std::filesystem::path& folder) {
  int count = 0;
  if (!std::filesystem::is_directory(folder)) return 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    ++count;
    EXPECT_EQ(RunInput(target, ReadBytes(entry.path())), "") << entry.path();
  }
  return count;
}

TEST(FuzzReplay, EverySeedAndKeptFindingPassesItsTargetsChecks) {
  for (const std::string_view target : TargetNames()) {
    SCOPED_TRACE(std::string(target));
    const int seeds = ReplayFolder(target, kFuzzDir / "corpus" / target);
    ReplayFolder(target, kFuzzDir / "regressions" / target);
    EXPECT_GE(seeds, 2) << "each target needs a seed corpus";
  }
}

// The checks can fail: a mesh that the writer cannot write back is reported, not passed.
TEST(FuzzReplay, ABrokenInvariantIsReported) {
  EXPECT_NE(RunInput("nonexistent", "x"), "");
  EXPECT_EQ(RunInput("off", "OFF\n0 0 0\n"), "");  // an empty mesh: nothing to write, fine
}

}  // namespace
}  // namespace sparsedyn::fuzz
