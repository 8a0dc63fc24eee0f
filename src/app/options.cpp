#include "app/options.hpp"

#include <algorithm>
#include <sstream>

#include "app/option_style.hpp"
#include "app/suggestions.hpp"
#include "penumbra/error.hpp"

namespace penumbra {

namespace {

// A parameter whose table entry names no group goes to `fallback`, the
// section of its table.
OptionGroup group_or(OptionGroup group, OptionGroup fallback) {
  return group == OptionGroup::Unset ? fallback : group;
}

template <class Owner, class Settings, class T, std::size_t N>
void add_params(CLI::App& app, Owner& settings,
                const std::array<NumericParam<Settings, T>, N>& params, OptionGroup fallback) {
  for (const auto& p : params) {
    add_number<T>(app, p.name, settings.*(p.field), p.help, p.min, p.max,
                  group_or(p.group, fallback));
  }
}

template <class Param, std::size_t N, class Settings>
void add_switches(CLI::App& app, Settings& settings, const std::array<Param, N>& params,
                  OptionGroup fallback) {
  for (const auto& p : params) {
    add_switch(app, p.name, p.help, settings.*(p.field), group_or(p.group, fallback));
  }
}

template <class E, std::size_t N>
std::vector<std::string> names_of(const std::array<std::pair<E, std::string_view>, N>& table) {
  std::vector<std::string> names;
  for (const auto& [value, name] : table) names.emplace_back(name);
  return names;
}

std::vector<std::string> split_list(const std::string& list) {
  std::vector<std::string> names;
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');) {
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t") + 1);
    names.push_back(name);
  }
  return names;
}

template <class E, std::size_t N>
std::vector<E> parse_list(const std::string& list, const std::string& flag, const char* what,
                          const std::array<std::pair<E, std::string_view>, N>& table,
                          const std::vector<E>& all) {
  if (names_equal(list, "all")) return all;
  std::vector<E> values;
  for (const std::string& name : split_list(list)) {
    const std::optional<E> value = parse_enum<E>(table, name);
    if (!value) {
      throw UsageError(flag + ": unknown " + what + " '" + name + "' (all, or a comma-separated " +
                       "list of " + enum_choices<E>(EnumTable<E>(table), ", ") + ")" +
                       did_you_mean(name, names_of(table)));
    }
    if (std::find(values.begin(), values.end(), *value) == values.end()) values.push_back(*value);
  }
  if (values.empty()) throw UsageError(flag + " is empty");
  return values;
}

template <class E, std::size_t N>
E parse_name(const std::string& name, const std::string& flag, const char* what,
             const std::array<std::pair<E, std::string_view>, N>& table) {
  if (auto value = parse_enum<E>(table, name)) return *value;
  throw UsageError(flag + ": unknown " + what + " '" + name + "' (one of " +
                   enum_choices<E>(EnumTable<E>(table), ", ") + ")" +
                   did_you_mean(name, names_of(table)));
}

}  // namespace

std::vector<std::string> technique_names() {
  return names_of(kTechniqueNames);
}

std::vector<std::string> filter_names() {
  return names_of(kFilterNames);
}

std::vector<std::string> shadow_map_kind_names() {
  return names_of(kShadowMapKindNames);
}

std::vector<Technique> parse_technique_list(const std::string& list, const std::string& flag) {
  std::vector<Technique> all;
  for (const auto& [t, name] : kTechniqueNames) {
    if (t != Technique::None) all.push_back(t);
  }
  return parse_list<Technique>(list, flag, "technique", kTechniqueNames, all);
}

std::vector<Filter> parse_filter_list(const std::string& list, const std::string& flag) {
  std::vector<Filter> all;
  for (const auto& [f, name] : kFilterNames) all.push_back(f);
  return parse_list<Filter>(list, flag, "filter", kFilterNames, all);
}

void add_shadow_options(CLI::App& app, ShadowSettings& settings, NamedOptions& named) {
  named.technique = std::string(enum_name<Technique>(kTechniqueNames, settings.technique));
  add_choice(app, "technique", named.technique, "shadow technique", technique_names(),
             OptionGroup::Technique);
  named.filter = std::string(enum_name<Filter>(kFilterNames, settings.filter));
  add_choice(app, "filter", named.filter,
             "filter of the vsm, esm, msm, msm16, evsm2 and evsm4 maps: a separable Gaussian, or a "
             "summed-area table",
             filter_names(), OptionGroup::Filter);
  add_shadow_maps_option(app, settings, named.shadow_maps);
  add_shadow_parameters(app, settings);
}

void add_shadow_maps_option(CLI::App& app, const ShadowSettings& settings, std::string& name,
                            const std::string& note) {
  name = std::string(enum_name<ShadowMapKind>(kShadowMapKindNames, settings.shadow_maps));
  std::string techniques;
  for (const auto& [t, technique] : kTechniqueNames) {
    if (t == Technique::None || !supports_virtual_maps(t)) continue;
    techniques += (techniques.empty() ? "" : ", ") + std::string(technique);
  }
  add_choice(app, "shadow-maps", name,
             "directional and spot lights: cascades and spot maps, or virtual shadow maps (a "
             "clipmap of 16384^2-texel levels, a spot's 16384^2 map with mip levels, in 128^2 "
             "pages, the pages the image needs rendered into --page-pool-mib; " +
                 techniques + note + ")",
             shadow_map_kind_names(), OptionGroup::Lights);
}

void add_shadow_parameters(CLI::App& app, ShadowSettings& settings) {
  add_switches(app, settings, kShadowFlagParams, OptionGroup::Technique);
  add_switches(app, settings, kShadowSwitchParams, OptionGroup::Technique);
  add_params(app, settings, kShadowIntParams, OptionGroup::Technique);
  add_params(app, settings, kShadowFloatParams, OptionGroup::Technique);
  add_switches(app, settings, kRendererShadowSwitchParams, OptionGroup::Technique);
  add_params(app, settings, kRendererShadowIntParams, OptionGroup::Technique);
  add_params(app, settings, kRendererShadowFloatParams, OptionGroup::Technique);
  // Given, a source size applies to every light of its kind (the scene's
  // own sizes otherwise): set through the override, which records that.
  for (const SourceSizeParam& p : kSourceSizeParams) {
    SourceSizeOverride& size = settings.*(p.override_field);
    add_number_setter(
        app, p.name, size, [&size](float value) { size = value; }, p.help, p.min, p.max,
        group_or(p.group, OptionGroup::Lights));
  }
}

void add_accumulate_option(CLI::App& app, ShadowSettings& settings) {
  add_params(app, settings, kAccumulateParams, OptionGroup::SoftShadows);
}

void add_render_parameters(CLI::App& app, RenderSettings& settings) {
  add_params(app, settings, kRenderIntParams, OptionGroup::Output);
}

void add_reference_options(CLI::App& app, ReferenceSettings& settings) {
  add_params(app, settings, kReferenceIntParams, OptionGroup::Reference);
}

void add_render_options(CLI::App& app, RenderSettings& settings, NamedOptions& named) {
  named.view = std::string(enum_name<View>(kViewNames, settings.view));
  add_choice(app, "view", named.view,
             "what to write: the lit image (final); the shadow factor, 1 = lit (shadow); what a "
             "filtered technique approximates (shadow-reference); the light's depth map "
             "(shadow-map) or the technique's map before and after its filter (moments, "
             "moments-filtered), a light's several views tiled; the G-buffer (normals, albedo); "
             "the ambient occlusion (ao); the cascade or cube face each pixel reads (cascades: "
             "red, green, blue, yellow, magenta, cyan for 0-5, black for none); the virtual "
             "page each pixel reads (pages, --shadow-maps virtual: a colour per clipmap level, "
             "bright where the page was rendered this frame, dark where cached); the shadow-map "
             "texels that fall into each pixel's footprint on the receiver, an area ratio "
             "(texel-density: log scale, red 1/4 or less, green 1, blue 4 or more, black for "
             "none)",
             names_of(kViewNames), OptionGroup::Output);
  add_render_parameters(app, settings);
}

void add_ssao_options(CLI::App& app, SsaoSettings& settings) {
  add_switches(app, settings, kSsaoSwitchParams, OptionGroup::Ssao);
  add_params(app, settings, kSsaoIntParams, OptionGroup::Ssao);
  add_params(app, settings, kSsaoFloatParams, OptionGroup::Ssao);
}

ShadowMapKind parse_shadow_map_kind(const std::string& name) {
  return parse_name(name, "--shadow-maps", "shadow-map kind", kShadowMapKindNames);
}

void parse_named_options(const NamedOptions& named, ShadowSettings& shadow,
                         RenderSettings& render) {
  shadow.technique = parse_name(named.technique, "--technique", "technique", kTechniqueNames);
  shadow.filter = parse_name(named.filter, "--filter", "filter", kFilterNames);
  if (!named.shadow_maps.empty()) shadow.shadow_maps = parse_shadow_map_kind(named.shadow_maps);
  render.view = parse_name(named.view, "--view", "view", kViewNames);
}

}  // namespace penumbra
