#include "app/option_style.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

#include "app/suggestions.hpp"
#include "penumbra/enum_names.hpp"

namespace penumbra {

namespace {

// Validators carry what --help and the completion script show, in their
// names ("range:0 to 32", "choices:a,b"): their descriptions stay empty,
// as CLI11 adds those to the placeholder in its own messages.
constexpr std::string_view kRangeValidator = "range:";
constexpr std::string_view kChoicesValidator = "choices:";
constexpr std::string_view kSuggestionsValidator = "suggestions:";

std::string joined(const std::vector<std::string>& names, const char* separator) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : separator) + name;
  return out;
}

// Numbers as the user would write them: 1e-08, 0.5, 32768.
template <class T>
std::string number_text(T value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

template <class T>
CLI::Validator finite_range(T min, T max) {
  CLI::Validator validator(
      [min, max](std::string& input) -> std::string {
        T value{};
        if constexpr (std::is_integral_v<T>) {
          // Decimal digits only: CLI11 would read 0x10 as 16 and 010 as 8
          // (strtoll's base 0) but refuse 1e3. The input is rewritten in
          // plain decimal for CLI11's own conversion.
          const char* begin = input.data() + (input.starts_with('+') ? 1 : 0);
          const char* end = input.data() + input.size();
          const auto [next, error] = std::from_chars(begin, end, value, 10);
          if (error == std::errc::result_out_of_range) {
            return input + " is outside [" + number_text(min) + ", " + number_text(max) + "]";
          }
          if (error != std::errc() || next != end || begin == end) {
            return "'" + input + "' is not a whole number in decimal digits";
          }
          input = std::to_string(value);
        } else if (!CLI::detail::lexical_cast(input, value)) {
          return "'" + input + "' is not a number";
        }
        if constexpr (std::is_floating_point_v<T>) {
          if (!std::isfinite(value)) return "'" + input + "' is not a finite number";
        }
        if (value < min || value > max) {
          return input + " is outside [" + number_text(min) + ", " + number_text(max) + "]";
        }
        return {};
      },
      "", std::string(kRangeValidator) + number_text(min) + " to " + number_text(max));
  return validator;
}

CLI::Validator names_validator(const std::vector<std::string>& choices, bool list) {
  return CLI::Validator(
      [choices, list](std::string& input) -> std::string {
        if (list && names_equal(input, "all")) return {};
        std::stringstream in(input);
        for (std::string name; std::getline(in, name, list ? ',' : '\0');) {
          name.erase(0, name.find_first_not_of(" \t"));
          name.erase(name.find_last_not_of(" \t") + 1);
          if (std::any_of(choices.begin(), choices.end(),
                          [&](const std::string& c) { return names_equal(c, name); })) {
            continue;
          }
          return "unknown name '" + name + "' (" +
                 (list ? "all, or a comma-separated list of " : "one of ") + joined(choices, ", ") +
                 ")" + did_you_mean(name, choices);
        }
        return {};
      },
      "", std::string(kChoicesValidator) + joined(choices, ","));
}

bool parse_on_off(const std::string& value, bool& result) {
  if (value == "on" || value == "true") {
    result = true;
  } else if (value == "off" || value == "false") {
    result = false;
  } else {
    return false;
  }
  return true;
}

// What the validator whose name starts with `kind` carries; "" if none.
std::string validator_text(const CLI::Option& option, std::string_view kind) {
  // get_validator is not const in CLI11, though it changes nothing.
  CLI::Option& o = const_cast<CLI::Option&>(option);
  for (int i = 0;; ++i) {
    try {
      const std::string name = o.get_validator(i)->get_name();
      if (name.compare(0, kind.size(), kind) == 0) return name.substr(kind.size());
    } catch (const CLI::OptionNotFound&) {
      return {};
    }
  }
}

}  // namespace

std::string flag(std::string_view name) {
  return "--" + std::string(name);
}

CLI::Option* in_group(CLI::Option* option, OptionGroup group) {
  return option->group(group_title(group));
}

std::string group_title(OptionGroup group) {
  for (const auto& [g, title] : kOptionGroupNames) {
    if (g == group) return std::string(title);
  }
  return "Other";
}

template <class T>
CLI::Option* add_number(CLI::App& app, std::string_view name, T& value, std::string_view help,
                        T min, T max, OptionGroup group) {
  CLI::Option* option = app.add_option(flag(name), value, std::string(help))
                            ->capture_default_str()
                            ->transform(finite_range<T>(min, max))
                            ->type_name(std::is_floating_point_v<T> ? "X" : "N");
  return in_group(option, group);
}

template CLI::Option* add_number<int>(CLI::App&, std::string_view, int&, std::string_view, int, int,
                                      OptionGroup);
template CLI::Option* add_number<float>(CLI::App&, std::string_view, float&, std::string_view,
                                        float, float, OptionGroup);

CLI::Option* add_number_setter(CLI::App& app, std::string_view name, float shown_default,
                               std::function<void(float)> set, std::string_view help, float min,
                               float max, OptionGroup group) {
  CLI::Option* option =
      app.add_option_function<float>(
             flag(name), [set = std::move(set)](const float& value) { set(value); },
             std::string(help))
          ->default_str(number_text(shown_default))
          ->transform(finite_range<float>(min, max))
          ->type_name("X");
  return in_group(option, group);
}

CLI::Validator index_number() {
  return finite_range<int>(0, std::numeric_limits<int>::max()).name("");
}

CLI::Option* show_range(CLI::Option* option, float min, float max) {
  return option->check(
      CLI::Validator([](std::string&) { return std::string(); }, "",
                     std::string(kRangeValidator) + number_text(min) + " to " + number_text(max)));
}

CLI::Option* suggest_names(CLI::Option* option, const std::vector<std::string>& names) {
  return option->check(CLI::Validator([](std::string&) { return std::string(); }, "",
                                      std::string(kSuggestionsValidator) + joined(names, ",")));
}

CLI::Option* add_choice(CLI::App& app, std::string_view name, std::string& value,
                        std::string_view help, const std::vector<std::string>& choices,
                        OptionGroup group) {
  CLI::Option* option = app.add_option(flag(name), value, std::string(help))
                            ->capture_default_str()
                            ->check(names_validator(choices, false))
                            ->type_name("NAME");
  return in_group(option, group);
}

CLI::Option* add_list(CLI::App& app, std::string_view name, std::string& value,
                      std::string_view help, const std::vector<std::string>& choices,
                      OptionGroup group, std::string_view alias) {
  const std::string names = flag(name) + (alias.empty() ? "" : "," + flag(alias));
  CLI::Option* option = app.add_option(names, value, std::string(help))
                            ->capture_default_str()
                            ->check(names_validator(choices, true))
                            ->type_name("LIST");
  return in_group(option, group);
}

void add_switch(CLI::App& app, std::string_view name, std::string_view help, bool& value,
                OptionGroup group) {
  bool* target = &value;
  const std::string on = flag(name);
  // "--name" alone reads as "true": CLI11 gives that to a "flag-like"
  // option, which expected(0) makes it; expected(0, 1) then lets it take
  // a value ("on", "off") and keeps it flag-like.
  CLI::Option* positive =
      app.add_option_function<std::string>(
             on,
             [target, on](const std::string& text) {
               if (!parse_on_off(text, *target)) {
                 throw CLI::ValidationError(on, "'" + text + "': give " + on + " or --no-" +
                                                    on.substr(2) + " (or " + on + " on|off)");
               }
             },
             std::string(help))
          ->expected(0)
          ->expected(0, 1)
          ->default_str(*target ? "on" : "off")
          ->type_name("");
  in_group(positive, group);
  const std::string off = "--no-" + std::string(name);
  CLI::Option* negative = app.add_flag_callback(
      off,
      [target, positive, on, off] {
        if (positive->count() > 0) {
          throw CLI::ValidationError(off, "contradicts " + on + " (give one of them)");
        }
        *target = false;
      },
      "the opposite of " + on);
  negative->group("");  // shown beside --name
}

std::vector<std::string> option_choices(const CLI::Option& option) {
  std::vector<std::string> names;
  std::stringstream in(validator_text(option, kChoicesValidator));
  for (std::string name; std::getline(in, name, ',');) names.push_back(name);
  return names;
}

std::vector<std::string> option_suggestions(const CLI::Option& option) {
  std::vector<std::string> names;
  std::stringstream in(validator_text(option, kSuggestionsValidator));
  for (std::string name; std::getline(in, name, ',');) names.push_back(name);
  return names;
}

std::string option_range(const CLI::Option& option) {
  return validator_text(option, kRangeValidator);
}

const CLI::Option* negation_of(const CLI::App& app, const CLI::Option& option) {
  const std::vector<std::string>& names = option.get_lnames();
  if (names.empty()) return nullptr;
  const CLI::Option* negation = app.get_option_no_throw("--no-" + names.front());
  return negation != nullptr && negation->get_group().empty() ? negation : nullptr;
}

std::string option_placeholder(const CLI::Option& option) {
  // A flag, or a switch (whose value is optional).
  if (option.get_type_size() == 0 || option.get_expected_min() == 0) return {};
  // CLI11 adds validators' descriptions after a colon; those registered
  // elsewhere may have them. Its own type names read as ours.
  std::string type = option.get_type_name();
  const std::string head = type.substr(0, type.find(':'));
  if (std::all_of(head.begin(), head.end(), [](char c) { return c >= 'A' && c <= 'Z'; })) {
    type = head;
  }
  if (type == "INT" || type == "UINT") return "N";
  if (type == "FLOAT") return "X";
  if (type == "TEXT" || type.empty()) return "VALUE";
  return type;
}

}  // namespace penumbra
