#pragma once
// The `penumbra` command line. run_cli returns the process exit status: 0
// on success, 2 for usage errors, 1 for run-time failures; every error is
// one line "penumbra: error: ..." on stderr.
#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "app/bench_command.hpp"
#include "app/compare_command.hpp"
#include "app/render_command.hpp"
#include "app/report_command.hpp"
#include "app/view_command.hpp"

namespace penumbra {

// `penumbra completion`: the bash completion script.
struct CompletionArgs {
  std::string output;  // empty: standard output
};

// What every command reads from the command line.
struct CliArgs {
  RenderArgs render;
  ViewArgs view;
  CompareArgs compare;
  BenchArgs bench;
  ReportArgs report;
  CompletionArgs completion;
};

// Every command with its options, filling `args` when parsed; `args` must
// outlive the app.
std::unique_ptr<CLI::App> make_cli(CliArgs& args);

// The one line that says why parsing failed: an unknown command or option
// first (with the nearest known name), then CLI11's own message.
std::string parse_error_message(const CLI::App& app, const CLI::ParseError& error);

int run_cli(int argc, char** argv);

}  // namespace penumbra
