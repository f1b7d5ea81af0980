// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace sparsedyn::cli {

/// The options of `sparsedyn run` as parsed (DESIGN.md "Command line").
struct RunOptions {
  std::string scene_file;
  std::optional<std::string> preset;
  std::optional<std::uint32_t> n;
  std::optional<double> density;
  std::optional<std::uint64_t> seed;
  std::optional<double> until;
  std::optional<std::string> broadphase;
  bool json = false;
  std::string record_file;
  bool no_record = false;
  std::string write_scene;
  std::string write_final_scene;  // the scene of the World at the end of the run
  std::string program;            // how to invoke this tool again, for the "view it with" hint
  std::string method = "event";   // event (the World) | conventional (docs/conventional.md)
  std::optional<double> dt;       // the conventional method's step, s
  std::optional<int> digits;      // the conventional method's bisection digits (A2; 4)
};

}  // namespace sparsedyn::cli
