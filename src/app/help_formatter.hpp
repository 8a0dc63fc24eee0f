#pragma once
// Every --help in one layout: options in the sections of OptionGroup, in
// its order; each option's placeholder, then its description wrapped to
// 80 columns, ending in its choices or range and its default in one style:
// "[one of: a, b; default: a]", "[range: 0 to 32; default: 2]".
#include <CLI/CLI.hpp>
#include <string>
#include <utility>
#include <vector>

namespace penumbra {

inline constexpr std::size_t kHelpWidth = 80;

class HelpFormatter : public CLI::Formatter {
 public:
  HelpFormatter();
  std::string make_help(const CLI::App* app, std::string name,
                        CLI::AppFormatMode mode) const override;
  std::string make_description(const CLI::App* app) const override;
  std::string make_subcommand(const CLI::App* sub) const override;
  std::string make_footer(const CLI::App* app) const override;
};

// `text` broken into lines of at most `width` characters at spaces; lines
// after the first start with `indent` spaces (the first is not indented).
std::string wrap_text(const std::string& text, std::size_t indent, std::size_t width = kHelpWidth);

// A help footer of examples: each a comment line (what it shows) and the
// command, as tests/cli/help_test.cpp reads and runs them.
struct Example {
  std::string what;
  std::string command;  // "penumbra ..."
};
std::string examples_footer(const std::vector<Example>& examples, const std::string& note = {});

}  // namespace penumbra
