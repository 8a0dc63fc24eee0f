#pragma once
// Registers the shared settings structs with CLI11, from the parameter
// tables in penumbra/settings.hpp: one name, one help text, one range, one
// default (the struct's) and one --help section per parameter.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "penumbra/settings.hpp"

namespace penumbra {

// Options whose values are names are read as strings, then parsed by
// parse_named_options().
struct NamedOptions {
  std::string technique;
  std::string filter;
  std::string view;
  std::string shadow_maps;
};

void add_shadow_options(CLI::App& app, ShadowSettings& settings, NamedOptions& named);
void add_render_options(CLI::App& app, RenderSettings& settings, NamedOptions& named);
void add_ssao_options(CLI::App& app, SsaoSettings& settings);

// The numeric and on/off parameters alone, for commands that take the
// technique, filter or view their own way.
void add_shadow_parameters(CLI::App& app, ShadowSettings& settings);
// --accumulate (render and compare only).
void add_accumulate_option(CLI::App& app, ShadowSettings& settings);
// --shadow-maps into `name` (its default: settings.shadow_maps); `note` adds
// what the command does with virtual maps.
void add_shadow_maps_option(CLI::App& app, const ShadowSettings& settings, std::string& name,
                            const std::string& note = "");
void add_render_parameters(CLI::App& app, RenderSettings& settings);
void add_reference_options(CLI::App& app, ReferenceSettings& settings);

// The names a technique, filter or view option accepts.
std::vector<std::string> technique_names();
std::vector<std::string> filter_names();
std::vector<std::string> shadow_map_kind_names();

// "all" or a comma-separated list of names, for commands that take several
// techniques (all: every one but none) or filters; `flag` names the option
// in errors. Throws UsageError.
std::vector<Technique> parse_technique_list(const std::string& list, const std::string& flag);
std::vector<Filter> parse_filter_list(const std::string& list, const std::string& flag);

// --shadow-maps NAME; throws UsageError for an unknown name.
ShadowMapKind parse_shadow_map_kind(const std::string& name);

// Throws UsageError for an unknown name.
void parse_named_options(const NamedOptions& named, ShadowSettings& shadow, RenderSettings& render);

}  // namespace penumbra
