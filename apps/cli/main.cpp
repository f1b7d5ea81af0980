// SPDX-License-Identifier: MIT
// `sparsedyn`: the command-line tool (DESIGN.md "Command line").
#include <CLI/CLI.hpp>
#include <cstdlib>

#include "apps/cli/distance_command.hpp"
#include "apps/cli/export_command.hpp"
#include "apps/cli/run_command.hpp"
#include "apps/cli/view_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{"sparsedyn: event-driven collision detection and rigid-body simulation"};
  app.require_subcommand(1);
  // scripts/run.sh sets SPARSEDYN_PROGRAM so that hints name the command the user typed.
  const char* program = std::getenv("SPARSEDYN_PROGRAM");
  sparsedyn::cli::AddRunCommand(app, program != nullptr && *program != '\0' ? program : argv[0]);
  sparsedyn::cli::AddDistanceCommand(app);
  sparsedyn::cli::AddExportCommand(app);
  sparsedyn::cli::AddViewCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // RuntimeError carries a subcommand's exit status; the rest are usage errors (exit 2+).
    return app.exit(e);
  }
  return 0;
}
