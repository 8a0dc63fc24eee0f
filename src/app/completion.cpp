#include "app/completion.hpp"

#include "app/option_style.hpp"

namespace penumbra {

namespace {

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : " ") + w;
  return out;
}

std::vector<std::string> option_names(const CLI::Option& option) {
  std::vector<std::string> names;
  for (const std::string& s : option.get_snames()) names.push_back("-" + s);
  for (const std::string& l : option.get_lnames()) names.push_back("--" + l);
  return names;
}

std::string case_pattern(const CLI::Option& option) {
  std::string pattern;
  for (const std::string& name : option_names(option)) {
    pattern += (pattern.empty() ? "" : "|") + name;
  }
  return pattern;
}

// The `case "$prev"` arms for the options of `command` that take a value.
std::string value_cases(const CLI::App& command) {
  std::string out;
  for (const CLI::Option* option : command.get_options()) {
    if (!option->nonpositional() || option->get_type_size() == 0 ||
        option->get_expected_min() == 0) {
      continue;  // a flag or a switch: no value follows
    }
    const std::string placeholder = option_placeholder(*option);
    const std::vector<std::string> choices = option_choices(*option);
    std::string action;
    if (placeholder == "LIST") {
      action = "_penumbra_list \"all " + joined(choices) + "\"";
    } else if (!choices.empty()) {
      action = "COMPREPLY=($(compgen -W \"" + joined(choices) + "\" -- \"$cur\"))";
    } else if (placeholder == "FOLDER") {
      action = "COMPREPLY=($(compgen -d -- \"$cur\"))";
    } else if (placeholder.find("FILE") != std::string::npos) {
      const std::vector<std::string> names = option_suggestions(*option);
      action =
          "COMPREPLY=(" +
          (names.empty() ? std::string() : "$(compgen -W \"" + joined(names) + "\" -- \"$cur\") ") +
          "$(compgen -f -- \"$cur\"))";
    } else {
      action = "COMPREPLY=()";  // a number or a vector: nothing to offer
    }
    out += "        " + case_pattern(*option) + ") " + action + "; return ;;\n";
  }
  return out;
}

}  // namespace

std::string bash_completion_script(const CLI::App& app) {
  std::vector<std::string> commands;
  for (const CLI::App* command : app.get_subcommands({})) commands.push_back(command->get_name());
  std::vector<std::string> top_options;
  for (const CLI::Option* option : app.get_options()) {
    for (const std::string& name : option_names(*option)) top_options.push_back(name);
  }

  std::string s;
  s += "# bash completion for penumbra, written by 'penumbra completion'.\n";
  s += "# Source it, or install it as share/bash-completion/completions/penumbra.\n\n";
  s += "# Completes the last name of a comma-separated list.\n";
  s += "_penumbra_list() {\n";
  s += "  local last=\"${cur##*,}\"\n";
  s += "  local prefix=\"${cur%\"$last\"}\"\n";
  s += "  COMPREPLY=($(compgen -P \"$prefix\" -W \"$1\" -- \"$last\"))\n";
  s += "}\n\n";
  s += "_penumbra() {\n";
  s += "  local cur=\"${COMP_WORDS[COMP_CWORD]}\"\n";
  s += "  local prev=\"${COMP_WORDS[COMP_CWORD-1]}\"\n";
  s += "  local command=\"\" i\n";
  s += "  for ((i = 1; i < COMP_CWORD; i++)); do\n";
  s += "    case \"${COMP_WORDS[i]}\" in\n";
  std::string pattern;
  for (const std::string& c : commands) pattern += (pattern.empty() ? "" : "|") + c;
  s += "      " + pattern + ")\n";
  s += "        command=\"${COMP_WORDS[i]}\"\n";
  s += "        break ;;\n";
  s += "    esac\n";
  s += "  done\n";
  s += "  case \"$command\" in\n";
  s += "    \"\")\n";
  s += "      COMPREPLY=($(compgen -W \"" + joined(commands) + " " + joined(top_options) +
       "\" -- \"$cur\"))\n";
  s += "      return ;;\n";
  for (const CLI::App* command : app.get_subcommands({})) {
    std::vector<std::string> options;
    for (const CLI::Option* option : command->get_options()) {
      for (const std::string& name : option_names(*option)) options.push_back(name);
    }
    s += "    " + command->get_name() + ")\n";
    s += "      case \"$prev\" in\n";
    s += value_cases(*command);
    s += "      esac\n";
    s += "      COMPREPLY=($(compgen -W \"" + joined(options) + "\" -- \"$cur\"))\n";
    s += "      return ;;\n";
  }
  s += "  esac\n";
  s += "}\n\n";
  s += "complete -F _penumbra penumbra\n";
  return s;
}

}  // namespace penumbra
