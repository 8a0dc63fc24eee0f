#include "app/options.hpp"

#include <cmath>
#include <sstream>

#include "core/error.hpp"

namespace penumbra {

namespace {

// Accepts finite numbers in [min, max]; CLI::Range would let NaN through.
template <class T>
CLI::Validator finite_range(T min, T max) {
  std::ostringstream description;
  description << "[" << min << " .. " << max << "]";
  return CLI::Validator(
      [min, max](std::string& input) -> std::string {
        T value{};
        if (!CLI::detail::lexical_cast(input, value)) return "'" + input + "' is not a number";
        if constexpr (std::is_floating_point_v<T>) {
          if (!std::isfinite(value)) return "'" + input + "' is not a finite number";
        }
        if (value < min || value > max) {
          std::ostringstream msg;
          msg << input << " is outside [" << min << ", " << max << "]";
          return msg.str();
        }
        return {};
      },
      description.str());
}

template <class Settings, class T, std::size_t N>
void add_params(CLI::App& app, Settings& settings,
                const std::array<NumericParam<Settings, T>, N>& params) {
  for (const auto& p : params) {
    app.add_option("--" + std::string(p.name), settings.*(p.field), std::string(p.help))
        ->capture_default_str()
        ->check(finite_range<T>(p.min, p.max));
  }
}

template <class E, std::size_t N>
std::string choices(const std::array<std::pair<E, std::string_view>, N>& table) {
  return enum_choices<E>(EnumTable<E>(table));
}

bool parse_switch(const std::string& flag, const std::string& value) {
  if (auto on = parse_enum<bool>(kOnOffNames, value)) return *on;
  throw UsageError(flag + " '" + value + "': choose from " + choices(kOnOffNames));
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
  if (list == "all") return all;
  std::vector<E> values;
  for (const std::string& name : split_list(list)) {
    const std::optional<E> value = parse_enum<E>(table, name);
    if (!value) {
      throw UsageError(flag + ": unknown " + what + " '" + name + "' (choose all, or from " +
                       choices(table) + ", comma-separated)");
    }
    if (std::find(values.begin(), values.end(), *value) == values.end()) values.push_back(*value);
  }
  if (values.empty()) throw UsageError(flag + " is empty");
  return values;
}

}  // namespace

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
  app.add_option("--technique", named.technique, "shadow technique: " + choices(kTechniqueNames))
      ->capture_default_str();
  named.filter = std::string(enum_name<Filter>(kFilterNames, settings.filter));
  app.add_option("--filter", named.filter,
                 "filter of the vsm/esm/msm/msm16/evsm2/evsm4 maps: " + choices(kFilterNames) +
                     " (separable Gaussian, or summed-area table)")
      ->capture_default_str();
  add_shadow_parameters(app, settings);
}

void add_shadow_parameters(CLI::App& app, ShadowSettings& settings) {
  for (const auto& p : kShadowFlagParams) {
    app.add_flag("--" + std::string(p.name), settings.*(p.field), std::string(p.help));
  }
  for (const auto& p : kShadowSwitchParams) {
    bool* field = &(settings.*(p.field));
    app.add_option_function<std::string>(
           "--" + std::string(p.name),
           [field](const std::string& value) { *field = *parse_enum<bool>(kOnOffNames, value); },
           std::string(p.help) + ": " + choices(kOnOffNames))
        ->check(CLI::IsMember({"on", "off"}))
        ->default_str(std::string(enum_name<bool>(kOnOffNames, settings.*(p.field))));
  }
  add_params(app, settings, kShadowIntParams);
  add_params(app, settings, kShadowFloatParams);
}

void add_accumulate_option(CLI::App& app, ShadowSettings& settings) {
  add_params(app, settings, kAccumulateParams);
}

void add_render_parameters(CLI::App& app, RenderSettings& settings) {
  add_params(app, settings, kRenderIntParams);
}

void add_reference_options(CLI::App& app, ReferenceSettings& settings) {
  add_params(app, settings, kReferenceIntParams);
}

void add_render_options(CLI::App& app, RenderSettings& settings, NamedOptions& named) {
  named.view = std::string(enum_name<View>(kViewNames, settings.view));
  app.add_option(
         "--view", named.view,
         "what to write: " + choices(kViewNames) +
             " (shadow: the shadow factor, 1 = lit, 0 on surfaces facing away from the light; "
             "shadow-reference: what a filtered technique "
             "approximates, the unfiltered map's depth tests averaged with the same "
             "filter kernel; shadow-map: the light's relative "
             "depth z-bar, a light with several views (the six cube faces of a point light, "
             "the cascades of a directional one) shown tiled; moments, moments-filtered: the "
             "technique's map before and after the filter, as colour, tiled the same way; for "
             "esm, log(map)/c + 1, in depth units (evsm: its positive warp, likewise); ao: the "
             "ambient-occlusion buffer, 1 = "
             "unoccluded; cascades: the cascade or cube face whose map each pixel reads, as a "
             "colour: red, green, blue, yellow, magenta, cyan for views 0-5, black where no "
             "map covers the point)")
      ->capture_default_str();
  add_render_parameters(app, settings);
}

void add_ssao_options(CLI::App& app, SsaoSettings& settings, NamedOptions& named) {
  named.ssao = std::string(enum_name<bool>(kOnOffNames, settings.enabled));
  app.add_option(
         "--ssao", named.ssao,
         "screen-space ambient occlusion darkening the ambient light: " + choices(kOnOffNames))
      ->capture_default_str();
  named.ssao_half_resolution = std::string(enum_name<bool>(kOnOffNames, settings.half_resolution));
  app.add_option("--ssao-half-resolution", named.ssao_half_resolution,
                 "compute the AO at half width and height, then upsample it with depth and "
                 "normal awareness: " +
                     choices(kOnOffNames))
      ->capture_default_str();
  add_params(app, settings, kSsaoIntParams);
  add_params(app, settings, kSsaoFloatParams);
}

void parse_named_options(const NamedOptions& named, ShadowSettings& shadow, RenderSettings& render,
                         SsaoSettings& ssao) {
  parse_named_options(named, shadow, render);
  ssao.enabled = parse_switch("--ssao", named.ssao);
  ssao.half_resolution = parse_switch("--ssao-half-resolution", named.ssao_half_resolution);
}

void parse_named_options(const NamedOptions& named, ShadowSettings& shadow,
                         RenderSettings& render) {
  if (auto t = parse_enum<Technique>(kTechniqueNames, named.technique)) {
    shadow.technique = *t;
  } else {
    throw UsageError("unknown technique '" + named.technique + "' (choose from " +
                     choices(kTechniqueNames) + ")");
  }
  if (auto f = parse_enum<Filter>(kFilterNames, named.filter)) {
    shadow.filter = *f;
  } else {
    throw UsageError("unknown filter '" + named.filter + "' (choose from " + choices(kFilterNames) +
                     ")");
  }
  if (auto v = parse_enum<View>(kViewNames, named.view)) {
    render.view = *v;
  } else {
    throw UsageError("unknown view '" + named.view + "' (choose from " + choices(kViewNames) + ")");
  }
}

}  // namespace penumbra
