#include "app/cli.hpp"

#include <CLI/CLI.hpp>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <new>

#include "app/bench_command.hpp"
#include "app/compare_command.hpp"
#include "app/options.hpp"
#include "app/render_command.hpp"
#include "app/report_command.hpp"
#include "app/view_command.hpp"
#include "core/display_name.hpp"
#include "core/error.hpp"
#include "io/signal_cleanup.hpp"

namespace penumbra {

namespace {

void print_error(const std::string& message) {
  // One line: later lines of a multi-line message (a shader log) are kept
  // but indented under it. Other control characters (a terminal escape
  // sequence in a file name) are printed escaped.
  std::string text;
  std::size_t start = 0;
  for (std::size_t end; (end = message.find('\n', start)) != std::string::npos; start = end + 1) {
    text += escape_control(message.substr(start, end - start)) + "\n";
  }
  text += escape_control(message.substr(start));
  for (std::size_t pos = 0; (pos = text.find('\n', pos)) != std::string::npos; pos += 3) {
    if (pos + 1 == text.size()) {
      text.erase(pos);
      break;
    }
    text.replace(pos, 1, "\n  ");
  }
  std::fprintf(stderr, "penumbra: error: %s\n", text.c_str());
}

// An option given an empty value ("--model ''") is a usage error: every
// option's empty value would otherwise read as "not given".
void reject_empty_values(const CLI::App& command) {
  for (const CLI::Option* option : command.get_options()) {
    if (option->get_type_size() == 0) continue;  // a flag
    for (const std::string& value : option->results()) {
      if (value.empty()) throw UsageError(option->get_name() + ": the value is empty");
    }
  }
}

// Standard output is checked once the command is done: a full device or a
// reader that went away is an error, not a silent loss.
int check_standard_output(int status) {
  errno = 0;
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    const int error = errno;
    print_error(std::string("cannot write to standard output") +
                (error != 0 ? std::string(": ") + std::strerror(error) : std::string()));
    return status == 0 ? 1 : status;
  }
  return status;
}

// Runs the command; its errors become one line and the exit status.
int run_guarded(const std::function<int()>& command) {
  try {
    return command();
  } catch (const UsageError& e) {
    print_error(e.what());
    return 2;
  } catch (const RuntimeError& e) {
    print_error(e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    print_error("out of memory (a size, a scene or a model too large for this machine's memory)");
    return 1;
  } catch (const std::exception& e) {
    print_error(std::string("internal error: ") + e.what());
    return 1;
  }
}

}  // namespace

int run_cli(int argc, char** argv) {
  // A closed pipe or a file-size limit is a write error to report, not a
  // signal that ends the program silently.
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
  install_signal_cleanup();

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

  return check_standard_output(run_guarded([&] {
    for (const CLI::App* command : app.get_subcommands()) reject_empty_values(*command);
    if (render->parsed()) return run_render_command(render_args);
    if (compare->parsed()) return run_compare_command(compare_args);
    if (bench->parsed()) return run_bench_command(bench_args);
    if (report->parsed()) return run_report_command(report_args);
    if (view->parsed()) return run_view_command(view_args);
    return 0;
  }));
}

}  // namespace penumbra
