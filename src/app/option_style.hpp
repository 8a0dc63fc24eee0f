#pragma once
// How every option is registered, so that each kind reads the same in
// --help and in the completion script: a placeholder for its value (N, X,
// NAME, LIST, FILE), its description, its choices or range, its default,
// and its --help section (OptionGroup, from penumbra/settings.hpp).
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/settings.hpp"

namespace penumbra {

// The option's flag as typed: "--name".
std::string flag(std::string_view name);

// Puts the option in a --help section; returns it.
CLI::Option* in_group(CLI::Option* option, OptionGroup group);

// The section's title ("Scene and camera"); "Other" for Unset.
std::string group_title(OptionGroup group);

// "--name N" (integers) or "--name X" (floats): a finite number in
// [min, max]. The default shown is the value's current one.
template <class T>
CLI::Option* add_number(CLI::App& app, std::string_view name, T& value, std::string_view help,
                        T min, T max, OptionGroup group);

// "--name X" as add_number<float>, the value handed to `set` only when
// the option is given (a setting that records being set:
// SourceSizeOverride); `shown_default` is the default --help shows.
CLI::Option* add_number_setter(CLI::App& app, std::string_view name, float shown_default,
                               std::function<void(float)> set, std::string_view help, float min,
                               float max, OptionGroup group);

// A whole number >= 0 in decimal digits (an index), with no range shown
// in --help.
CLI::Validator index_number();

// Shows "range: min to max" in --help for an option whose value is read
// and range-checked later (a "[I:]V" light value); returns it.
CLI::Option* show_range(CLI::Option* option, float min, float max);

// Names the completion script offers for an option whose value may also
// be something else (a built-in scene, or a scene file); returns it.
CLI::Option* suggest_names(CLI::Option* option, const std::vector<std::string>& names);

// "--name NAME": one of `choices`; a wrong name is an error that lists
// them and suggests the nearest.
CLI::Option* add_choice(CLI::App& app, std::string_view name, std::string& value,
                        std::string_view help, const std::vector<std::string>& choices,
                        OptionGroup group);

// "--name LIST": "all" or comma-separated names from `choices`; a list of
// one name is one name. `alias` (if any) is a second name for the option.
CLI::Option* add_list(CLI::App& app, std::string_view name, std::string& value,
                      std::string_view help, const std::vector<std::string>& choices,
                      OptionGroup group, std::string_view alias = {});

// "--name" / "--no-name" sets `value` to true / false; "--name on|off"
// (and =true|false) is read as well. The two spellings of one switch
// exclude each other.
void add_switch(CLI::App& app, std::string_view name, std::string_view help, bool& value,
                OptionGroup group);

// The names an option's value may take (for completion and suggestions):
// add_choice's and add_list's choices, an on/off switch's none; empty
// when the value is free (a number, a file).
std::vector<std::string> option_choices(const CLI::Option& option);

// suggest_names' names; empty if none.
std::vector<std::string> option_suggestions(const CLI::Option& option);

// The range an add_number option shows ("0 to 32"); empty otherwise.
std::string option_range(const CLI::Option& option);

// The "--no-name" half of an add_switch option, registered hidden (the
// help shows it beside "--name"); null for other options.
const CLI::Option* negation_of(const CLI::App& app, const CLI::Option& option);

// The placeholder shown after the option's name in --help ("N", "FILE");
// empty for a switch.
std::string option_placeholder(const CLI::Option& option);

}  // namespace penumbra
