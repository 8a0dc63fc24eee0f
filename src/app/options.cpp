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

}  // namespace

void add_shadow_options(CLI::App& app, ShadowSettings& settings, NamedOptions& named) {
  named.technique = std::string(enum_name<Technique>(kTechniqueNames, settings.technique));
  app.add_option("--technique", named.technique, "shadow technique: " + choices(kTechniqueNames))
      ->capture_default_str();
  named.filter = std::string(enum_name<Filter>(kFilterNames, settings.filter));
  app.add_option("--filter", named.filter,
                 "filter of the vsm/esm/msm/msm16 maps: " + choices(kFilterNames) +
                     " (separable Gaussian, or summed-area table)")
      ->capture_default_str();
  for (const auto& p : kShadowFlagParams) {
    app.add_flag("--" + std::string(p.name), settings.*(p.field), std::string(p.help));
  }
  add_params(app, settings, kShadowIntParams);
  add_params(app, settings, kShadowFloatParams);
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
             "depth z-bar; moments, moments-filtered: the technique's map before and "
             "after the filter, as colour; for esm, log(map)/c + 1, in depth units)")
      ->capture_default_str();
  add_params(app, settings, kRenderIntParams);
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
