// SPDX-License-Identifier: MIT
#include "apps/cli/export_command.hpp"

#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "sparsedyn/io/recording.hpp"

namespace sparsedyn::cli {
namespace {

struct ExportOptions {
  std::string input;
  std::string output;
};

int Export(const ExportOptions& options) {
  Result<Recording> recording = ReadRecording(options.input);
  if (!recording) {
    std::cerr << "sparsedyn export-jsonl: " << recording.error().message << "\n";
    return 1;
  }
  if (options.output.empty() || options.output == "-") {
    WriteJsonLines(*recording, std::cout);
    std::cout.flush();
    return std::cout ? 0 : 1;
  }
  std::ofstream out(options.output);
  if (!out) {
    std::cerr << "sparsedyn export-jsonl: " << options.output << ": cannot open for writing\n";
    return 1;
  }
  WriteJsonLines(*recording, out);
  out.close();
  if (!out) {
    std::cerr << "sparsedyn export-jsonl: " << options.output << ": write failed\n";
    return 1;
  }
  return 0;
}

}  // namespace

void AddExportCommand(CLI::App& app) {
  auto options = std::make_shared<ExportOptions>();
  CLI::App* command = app.add_subcommand(
      "export-jsonl", "Write a recording (.sdrec) as JSON lines, one object per record");
  command->add_option("recording", options->input, "Recording file (.sdrec)")->required();
  command->add_option("-o,--output", options->output, "Output file (default: stdout)");
  command->callback([options] { throw CLI::RuntimeError(Export(*options)); });
}

}  // namespace sparsedyn::cli
