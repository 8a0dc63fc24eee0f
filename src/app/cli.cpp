#include "app/cli.hpp"

#include <CLI/CLI.hpp>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <new>

#include "app/completion.hpp"
#include "app/help_formatter.hpp"
#include "app/option_style.hpp"
#include "app/suggestions.hpp"
#include "core/display_name.hpp"
#include "io/atomic_file.hpp"
#include "io/image.hpp"
#include "io/signal_cleanup.hpp"
#include "penumbra/error.hpp"

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
  // A command that failed has said why in its one line already (a write
  // to standard output that failed mid-run among the reasons).
  if (status != 0) return status;
  errno = 0;
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    const int error = errno;
    print_error(std::string("cannot write to standard output") +
                (error != 0 ? std::string(": ") + std::strerror(error) : std::string()));
    return 1;
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

std::vector<std::string> long_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
  }
  return names;
}

std::vector<std::string> command_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* command : app.get_subcommands({})) names.push_back(command->get_name());
  return names;
}

std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    out += (i == 0 ? "" : (i + 1 == names.size() ? " or " : ", ")) + names[i];
  }
  return out;
}

// The first argument that was not understood, and what it is about: an
// unknown command, an unknown option, or a stray value; "" if none.
std::string leftover_message(const CLI::App& app) {
  const std::vector<CLI::App*> parsed = app.get_subcommands();
  // What was left before the command (or with none) is read against the
  // program's own options and commands; what was left after it, against
  // the command's.
  const CLI::App* command = nullptr;
  std::vector<std::string> leftovers = app.remaining();
  if (leftovers.empty() && !parsed.empty()) {
    command = parsed.front();
    leftovers = command->remaining();
  }
  if (leftovers.empty()) return {};
  const std::string& arg = leftovers.front();
  if (arg.size() > 1 && arg[0] == '-') {
    const std::string name = arg.substr(0, arg.find('='));
    if (command != nullptr) {
      const std::string suggestion = did_you_mean(name, long_names(*command));
      return "unknown option '" + name + "' for '" + command->get_name() + "'" +
             (suggestion.empty() ? " (see 'penumbra " + command->get_name() + " --help')"
                                 : suggestion);
    }
    // A command's option given before the command.
    const CLI::App* owner = parsed.empty() ? nullptr : parsed.front();
    for (const CLI::App* sub : app.get_subcommands({})) {
      if (owner == nullptr && sub->get_option_no_throw(name) != nullptr) owner = sub;
    }
    if (owner != nullptr && owner->get_option_no_throw(name) != nullptr) {
      return "unknown option '" + name + "' (options follow the command: penumbra " +
             owner->get_name() + " " + name + " ...)";
    }
    const std::string suggestion = did_you_mean(name, long_names(app));
    return "unknown option '" + name + "'" +
           (suggestion.empty() ? " (see 'penumbra --help')" : suggestion);
  }
  if (command == nullptr) {
    const std::string suggestion = did_you_mean(arg, command_names(app));
    return "unknown command '" + arg + "'" +
           (suggestion.empty() ? " (choose " + listed(command_names(app)) + ")" : suggestion);
  }
  return "unexpected argument '" + arg + "' (see 'penumbra " + command->get_name() + " --help')";
}

int run_completion_command(const CLI::App& app, const CompletionArgs& args) {
  const std::string script = bash_completion_script(app);
  if (args.output.empty()) {
    std::fputs(script.c_str(), stdout);
  } else {
    check_output_path(args.output);
    write_file_atomically(args.output, script);
  }
  return 0;
}

}  // namespace

std::unique_ptr<CLI::App> make_cli(CliArgs& args) {
  auto app = std::make_unique<CLI::App>(
      "penumbra: real-time shadow techniques, rendered headless and measured", "penumbra");
  // Set before the commands are added: each takes its parent's.
  app->formatter(std::make_shared<HelpFormatter>());
  app->require_subcommand(1);
  app->set_help_flag("-h,--help", "print this help and exit");
  app->set_version_flag("--version", "penumbra " PENUMBRA_VERSION, "print the version and exit");
  app->footer(examples_footer({
      {"hard shadows of the default scene", "penumbra render -o hard.png"},
      {"every technique measured against a ray-traced reference", "penumbra compare"},
      {"the options of a command", "penumbra render --help"},
  }));

  const auto command = [&app](const char* name, const char* description) {
    CLI::App* sub = app->add_subcommand(name, description);
    sub->group("Commands");
    return sub;
  };
  add_render_command_options(*command("render", "render one image of a scene (PNG or EXR)"),
                             args.render);
  add_view_command_options(
      *command("view", "interactive viewer: a window with a panel that edits every setting, live"),
      args.view);
  add_compare_command_options(
      *command("compare",
               "measure every technique against a ray-traced reference: a table, JSON, error "
               "images"),
      args.compare);
  add_bench_command_options(
      *command("bench",
               "GPU time of every pass per technique, against a bandwidth yardstick; the "
               "texels PCSS and backprojection read per pixel"),
      args.bench);
  add_report_command_options(
      *command("report",
               "the whole study (every technique, sweeps, errors, timings) as one HTML page"),
      args.report);
  CLI::App* completion = command("completion", "print the bash completion script");
  in_group(completion
               ->add_option("-o,--output", args.completion.output,
                            "write it to this file instead of standard output")
               ->type_name("FILE"),
           OptionGroup::Output);
  completion->footer(examples_footer(
      {
          {"the script, to read", "penumbra completion"},
          {"where bash-completion finds it for this user",
           "penumbra completion -o ~/.local/share/bash-completion/completions/penumbra"},
      },
      "To complete in this shell: source <(penumbra completion)"));
  return app;
}

std::string parse_error_message(const CLI::App& app, const CLI::ParseError& error) {
  // CLI11 checks required options and values before it reports what it
  // did not understand; a mistyped option is the more useful news.
  if (std::string leftover = leftover_message(app); !leftover.empty()) return leftover;
  if (dynamic_cast<const CLI::RequiredError*>(&error) && app.get_subcommands().empty()) {
    return "a command is required: " + listed(command_names(app)) + " (see 'penumbra --help')";
  }
  // "--blur: 1 required N missing": the option came last, without its value.
  const std::string what = error.what();
  const std::size_t colon = what.find(": ");
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) && colon != std::string::npos &&
      what.find(" required ") != std::string::npos && what.ends_with(" missing")) {
    return what.substr(0, colon) + " needs a value";
  }
  return what;
}

int run_cli(int argc, char** argv) {
  // A closed pipe or a file-size limit is a write error to report, not a
  // signal that ends the program silently.
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
  install_signal_cleanup();

  CliArgs args;
  const std::unique_ptr<CLI::App> app = make_cli(args);
  try {
    app->parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app->exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app->exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app->exit(e);
  } catch (const CLI::ParseError& e) {
    print_error(parse_error_message(*app, e));
    return 2;
  }

  return check_standard_output(run_guarded([&] {
    for (const CLI::App* command : app->get_subcommands()) reject_empty_values(*command);
    const std::string name = app->get_subcommands().front()->get_name();
    if (name == "render") return run_render_command(args.render);
    if (name == "view") return run_view_command(args.view);
    if (name == "compare") return run_compare_command(args.compare);
    if (name == "bench") return run_bench_command(args.bench);
    if (name == "report") return run_report_command(args.report);
    if (name == "completion") return run_completion_command(*app, args.completion);
    return 0;
  }));
}

}  // namespace penumbra
