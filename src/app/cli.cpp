#include "app/cli.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "app/bench_command.hpp"
#include "app/compare_command.hpp"
#include "app/options.hpp"
#include "app/render_command.hpp"
#include "app/report_command.hpp"
#include "app/view_command.hpp"
#include "core/error.hpp"

namespace penumbra {

namespace {

void print_error(const std::string& message) {
  // One line: later lines of a multi-line message (a shader log) are kept
  // but indented under it.
  std::string text = message;
  for (std::size_t pos = 0; (pos = text.find('\n', pos)) != std::string::npos; pos += 3) {
    if (pos + 1 == text.size()) {
      text.erase(pos);
      break;
    }
    text.replace(pos, 1, "\n  ");
  }
  std::fprintf(stderr, "penumbra: error: %s\n", text.c_str());
}

}  // namespace

int run_cli(int argc, char** argv) {
  CLI::App app{"penumbra: real-time shadow techniques, rendered headless and measured"};
  app.name("penumbra");
  app.require_subcommand(1);
  app.set_version_flag("--version", "penumbra 0.1.0");

  RenderArgs render_args;
  CLI::App* render = app.add_subcommand("render", "render one image of a scene (PNG or EXR)");
  add_render_command_options(*render, render_args);
  BenchArgs bench_args;
  CLI::App* bench = app.add_subcommand(
      "bench", "GPU time of every pass per technique, against a bandwidth yardstick");
  add_bench_command_options(*bench, bench_args);
  ReportArgs report_args;
  CLI::App* report = app.add_subcommand(
      "report", "the whole study (every technique, sweeps, errors, timings) as one HTML page");
  add_report_command_options(*report, report_args);

  CompareArgs compare_args;
  CLI::App* compare = app.add_subcommand(
      "compare",
      "measure every technique against a ray-traced reference: a table, JSON, error images");
  add_compare_command_options(*compare, compare_args);
  ViewArgs view_args;
  CLI::App* view = app.add_subcommand(
      "view", "interactive viewer: a window with a panel that edits every setting, live");
  add_view_command_options(*view, view_args);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string what = e.what();
    if (dynamic_cast<const CLI::RequiredError*>(&e) && app.get_subcommands().empty()) {
      what =
          "a command is required: render, view, compare, bench or report (see 'penumbra --help')";
    }
    print_error(what);
    return 2;
  }

  try {
    if (render->parsed()) return run_render_command(render_args);
    if (compare->parsed()) return run_compare_command(compare_args);
    if (bench->parsed()) return run_bench_command(bench_args);
    if (report->parsed()) return run_report_command(report_args);
    if (view->parsed()) return run_view_command(view_args);
  } catch (const UsageError& e) {
    print_error(e.what());
    return 2;
  } catch (const RuntimeError& e) {
    print_error(e.what());
    return 1;
  } catch (const std::exception& e) {
    print_error(std::string("internal error: ") + e.what());
    return 1;
  }
  return 0;
}

}  // namespace penumbra
