#include "app/help_formatter.hpp"

#include <algorithm>

#include "app/option_style.hpp"
#include "penumbra/settings.hpp"

namespace penumbra {

namespace {

// Where descriptions start; a longer name and placeholder puts the
// description on the next line.
constexpr std::size_t kDescriptionColumn = 30;

std::string option_names(const CLI::App& app, const CLI::Option& option) {
  std::string names;
  for (const std::string& s : option.get_snames()) names += (names.empty() ? "-" : ", -") + s;
  for (const std::string& l : option.get_lnames()) names += (names.empty() ? "--" : ", --") + l;
  if (const CLI::Option* negation = negation_of(app, option)) {
    names += ", --" + negation->get_lnames().front();
  }
  const std::string placeholder = option_placeholder(option);
  return placeholder.empty() ? names : names + " " + placeholder;
}

// "[one of: a, b; default: a]"
std::string option_facts(const CLI::Option& option) {
  std::vector<std::string> facts;
  const std::vector<std::string> choices = option_choices(option);
  if (!choices.empty()) {
    std::string list;
    for (const std::string& c : choices) list += (list.empty() ? "" : ", ") + c;
    facts.push_back((option_placeholder(option) == "LIST" ? "all, or a comma-separated list of: "
                                                          : "one of: ") +
                    list);
  }
  const std::string range = option_range(option);
  if (!range.empty()) facts.push_back("range: " + range);
  if (option.get_required()) facts.push_back("required");
  if (!option.get_default_str().empty()) facts.push_back("default: " + option.get_default_str());
  if (facts.empty()) return {};
  std::string text;
  for (const std::string& f : facts) text += (text.empty() ? "" : "; ") + f;
  return "[" + text + "]";
}

std::string option_entry(const CLI::App& app, const CLI::Option& option) {
  std::string left = "  " + option_names(app, option);
  std::string description = option.get_description();
  const std::string facts = option_facts(option);
  if (!facts.empty()) description += (description.empty() ? "" : " ") + facts;
  if (left.size() + 2 > kDescriptionColumn) {
    left += "\n" + std::string(kDescriptionColumn, ' ');
  } else {
    left.append(kDescriptionColumn - left.size(), ' ');
  }
  return left + wrap_text(description, kDescriptionColumn) + "\n";
}

bool is_known_title(const std::string& group) {
  return std::any_of(kOptionGroupNames.begin(), kOptionGroupNames.end(),
                     [&](const auto& entry) { return entry.second == group; });
}

// The options in their sections: the known ones in their order, then
// "Other" for options of no known section (help, and any registered
// without a group).
std::string option_sections(const CLI::App& app) {
  std::vector<std::string> titles;
  for (const auto& [group, title] : kOptionGroupNames) titles.emplace_back(title);
  std::string out;
  for (const std::string& title : titles) {
    const std::vector<const CLI::Option*> options = app.get_options([&](const CLI::Option* o) {
      if (o->get_group().empty() || !o->nonpositional()) return false;
      const bool known = is_known_title(o->get_group());
      return known ? o->get_group() == title : title == "Other";
    });
    if (options.empty()) continue;
    out += "\n" + title + ":\n";
    for (const CLI::Option* option : options) out += option_entry(app, *option);
  }
  return out;
}

}  // namespace

HelpFormatter::HelpFormatter() {
  label("SUBCOMMAND", "COMMAND");
  label("SUBCOMMANDS", "COMMANDS");
}

std::string wrap_text(const std::string& text, std::size_t indent, std::size_t width) {
  // The first line continues a line that already holds `indent` columns.
  std::string out;
  std::size_t column = indent;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    start = end + 1;
    if (word.empty()) continue;
    const bool first_on_line = column == indent;
    if (!first_on_line && column + 1 + word.size() > width) {
      out += "\n" + std::string(indent, ' ');
      column = indent;
    } else if (!first_on_line) {
      out += ' ';
      ++column;
    }
    out += word;
    column += word.size();
  }
  return out;
}

std::string HelpFormatter::make_help(const CLI::App* app, std::string name,
                                     CLI::AppFormatMode mode) const {
  if (mode == CLI::AppFormatMode::Sub) return make_expanded(app);
  return make_description(app) + make_usage(app, std::move(name)) + option_sections(*app) +
         make_subcommands(app, mode) + "\n" + make_footer(app);
}

std::string HelpFormatter::make_description(const CLI::App* app) const {
  const std::string description = app->get_description();
  return description.empty() ? std::string() : wrap_text(description, 0) + "\n";
}

std::string HelpFormatter::make_subcommand(const CLI::App* sub) const {
  std::string left = "  " + sub->get_name();
  constexpr std::size_t kColumn = 14;
  left.append(left.size() < kColumn ? kColumn - left.size() : 1, ' ');
  return left + wrap_text(sub->get_description(), kColumn) + "\n";
}

std::string HelpFormatter::make_footer(const CLI::App* app) const {
  const std::string footer = app->get_footer();
  return footer.empty() ? std::string() : footer + "\n";
}

std::string examples_footer(const std::vector<Example>& examples, const std::string& note) {
  std::string out;
  if (!note.empty()) out += wrap_text(note, 0) + "\n\n";
  out += "Examples:";
  for (const Example& e : examples) {
    out += "\n  # " + wrap_text(e.what, 4) + "\n  " + e.command;
  }
  return out;
}

}  // namespace penumbra
