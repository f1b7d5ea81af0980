// SPDX-License-Identifier: MIT
// Floating-point traps in the test binaries (issue #39 part 3, docs/reliability.md): invalid,
// division by zero and overflow raise SIGFPE in every test (test_main_support.cpp turns them on
// before main), so a NaN or an infinity born by accident fails the test where it is born. A
// test that feeds NaN or infinity on purpose (bad-input checks) pauses them for its scope.
#pragma once

namespace sparsedyn::testing {

/// Turns the traps on for the calling thread (threads started later inherit them). Returns
/// false where the CPU cannot trap (e.g. most aarch64 cores: feenableexcept fails there).
bool EnableFloatingPointTraps();

/// Pauses the traps for its lifetime and clears the flags raised meanwhile; restores them after.
class FloatingPointTrapsPaused {
 public:
  FloatingPointTrapsPaused();
  ~FloatingPointTrapsPaused();
  FloatingPointTrapsPaused(const FloatingPointTrapsPaused&) = delete;
  FloatingPointTrapsPaused& operator=(const FloatingPointTrapsPaused&) = delete;

 private:
  int enabled_;
};

}  // namespace sparsedyn::testing
