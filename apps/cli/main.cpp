// SPDX-License-Identifier: MIT
// `sparsedyn`: the command-line tool (DESIGN.md "Command line").
#include <CLI/CLI.hpp>

#include "apps/cli/run_command.hpp"
#include "apps/cli/view_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{"sparsedyn: event-driven collision detection and rigid-body simulation"};
  sparsedyn::cli::AddViewCommand(app);
  app.require_subcommand(1);
  sparsedyn::cli::AddRunCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // RuntimeError carries a subcommand's exit status; the rest are usage errors (exit 2+).
    return app.exit(e);
  }
  return 0;
}
