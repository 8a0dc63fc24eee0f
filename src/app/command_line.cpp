#include "app/command_line.hpp"

#include <charconv>

namespace penumbra {

namespace {

// The shortest text that parses back to the same float.
std::string number(float value) {
  char buffer[32];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}
std::string number(int value) {
  return std::to_string(value);
}

template <class Settings, class T, std::size_t N>
void append_changed(std::string& out, const Settings& settings,
                    const std::array<NumericParam<Settings, T>, N>& params) {
  const Settings defaults{};
  for (const auto& p : params) {
    if (settings.*(p.field) != defaults.*(p.field)) {
      out += " --" + std::string(p.name) + " " + number(settings.*(p.field));
    }
  }
}

}  // namespace

std::string render_command_line(const std::string& scene, const RenderSettings& render,
                                const ShadowSettings& shadow, const std::string& output) {
  const ShadowSettings shadow_defaults{};
  const RenderSettings render_defaults{};
  std::string out = "penumbra render --scene " + scene;
  if (shadow.technique != shadow_defaults.technique) {
    out += " --technique " + std::string(enum_name<Technique>(kTechniqueNames, shadow.technique));
  }
  if (shadow.filter != shadow_defaults.filter) {
    out += " --filter " + std::string(enum_name<Filter>(kFilterNames, shadow.filter));
  }
  if (shadow.soft) out += " --soft";
  if (render.view != render_defaults.view) {
    out += " --view " + std::string(enum_name<View>(kViewNames, render.view));
  }
  append_changed(out, render, kRenderIntParams);
  append_changed(out, shadow, kShadowIntParams);
  append_changed(out, shadow, kShadowFloatParams);
  return out + " -o " + output;
}

}  // namespace penumbra
