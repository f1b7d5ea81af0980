// SPDX-License-Identifier: MIT
// Running the `sparsedyn` tool from a test (SPARSEDYN_CLI_PATH, set by tests/CMakeLists.txt).
// The older CLI tests still carry their own copies of these helpers; new ones use this.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

namespace sparsedyn::testing {

struct CliOutput {
  int status;       // exit status
  std::string out;  // stdout, and stderr too when asked
};

/// Runs the CLI with `arguments` through the shell, capturing stdout (stderr folded in when
/// `with_stderr`, else discarded).
inline CliOutput RunCli(const std::string& arguments, bool with_stderr = false) {
  const std::string command =
      std::string(SPARSEDYN_CLI_PATH) + " " + arguments + (with_stderr ? " 2>&1" : " 2>/dev/null");
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) out += buffer.data();
  const int status = pclose(pipe);
  return {WEXITSTATUS(status), out};
}

/// A path in the temporary folder, unique to this process, for a file a test writes.
inline std::filesystem::path TempPath(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("sparsedyn_test_" + std::to_string(::getpid()) + "_" + name);
}

}  // namespace sparsedyn::testing
