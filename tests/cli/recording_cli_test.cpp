// SPDX-License-Identifier: MIT
// `sparsedyn run --record` and `sparsedyn export-jsonl` as a user runs them.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace {

struct Output {
  int status;
  std::string out;
};

// Runs the CLI with `arguments`, capturing stdout (stderr folded in when `with_stderr`).
Output RunCli(const std::string& arguments, bool with_stderr = false) {
  const std::string command =
      std::string(SPARSEDYN_CLI_PATH) + " " + arguments + (with_stderr ? " 2>&1" : " 2>/dev/null");
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) out += buffer.data();
  const int status = pclose(pipe);
  return {WEXITSTATUS(status), out};
}

std::filesystem::path TempPath(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("sparsedyn_cli_rec_" + std::to_string(::getpid()) + "_" + name);
}

TEST(CliRecord, RecordThenExportGivesOneJsonObjectPerRecord) {
  const std::filesystem::path recording = TempPath("gas.sdrec");
  const std::filesystem::path lines = TempPath("gas.jsonl");
  const Output run =
      RunCli("run --preset gas --n 300 --until 3 --json --record " + recording.string());
  ASSERT_EQ(run.status, 0);
  const nlohmann::json summary = nlohmann::json::parse(run.out);
  EXPECT_EQ(summary["recording_bytes"], std::filesystem::file_size(recording));

  ASSERT_EQ(RunCli("export-jsonl " + recording.string() + " -o " + lines.string()).status, 0);
  std::ifstream in(lines);
  std::size_t segments = 0, collisions = 0, count = 0;
  std::string last;
  for (std::string line; std::getline(in, line); ++count) {
    const nlohmann::json j = nlohmann::json::parse(line);  // every line is one object
    if (j["record"] == "segment") ++segments;
    if (j["record"] == "collision") ++collisions;
    last = j["record"];
  }
  EXPECT_EQ(last, "end");
  EXPECT_EQ(count, 1 + 300 + segments + collisions + 1);
  EXPECT_EQ(collisions, summary["collisions"].get<std::size_t>());
  EXPECT_EQ(segments, 300 + 2 * summary["body_collisions"].get<std::size_t>() +
                          summary["wall_collisions"].get<std::size_t>());
  std::filesystem::remove(recording);
  std::filesystem::remove(lines);
}

// FNV-1a of a file's bytes.
std::uint64_t FileHash(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::uint64_t hash = 1469598103934665603ull;
  for (char c; in.get(c);) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  return hash;
}

TEST(CliRecord, ThePolyhedraOfTheThesisPresetRecordTheSameBytesForTheSameSeed) {
  std::uint64_t hashes[2] = {};
  for (int k = 0; k < 2; ++k) {
    const std::filesystem::path recording = TempPath("thesis" + std::to_string(k) + ".sdrec");
    const Output run = RunCli("run --preset thesis --n 300 --seed 7 --until 3 --json --record " +
                              recording.string());
    ASSERT_EQ(run.status, 0) << run.out;
    EXPECT_GT(nlohmann::json::parse(run.out)["body_collisions"].get<int>(), 10);
    hashes[k] = FileHash(recording);
    std::filesystem::remove(recording);
  }
  EXPECT_EQ(hashes[0], hashes[1]);
}

TEST(CliRecord, BadFilesAreClearErrors) {
  const std::filesystem::path bogus = TempPath("bogus.sdrec");
  std::ofstream(bogus) << "hello, not a recording";
  Output result = RunCli("export-jsonl " + bogus.string(), /*with_stderr=*/true);
  EXPECT_EQ(result.status, 1);
  EXPECT_NE(result.out.find("bad magic"), std::string::npos) << result.out;
  std::filesystem::remove(bogus);

  result = RunCli("run --until 1 --record /nonexistent-dir/x.sdrec", /*with_stderr=*/true);
  EXPECT_NE(result.status, 0);
  EXPECT_NE(result.out.find("/nonexistent-dir/x.sdrec: cannot open for writing"), std::string::npos)
      << result.out;
}

}  // namespace
