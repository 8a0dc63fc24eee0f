#include "app/command_line.hpp"

#include "app/option_style.hpp"
#include "app/scene_options.hpp"

namespace penumbra {

namespace {

std::string text(float value) {
  return format_float(value);
}
std::string text(int value) {
  return std::to_string(value);
}

template <class Owner, class Settings, class T, std::size_t N>
void add_changed(std::vector<std::string>& args, const Owner& settings,
                 const std::array<NumericParam<Settings, T>, N>& params) {
  const Owner defaults{};
  for (const auto& p : params) {
    if (settings.*(p.field) != defaults.*(p.field)) {
      args.push_back(flag(p.name) + "=" + text(settings.*(p.field)));
    }
  }
}

template <class E, std::size_t N>
void add_changed_name(std::vector<std::string>& args, std::string_view name, E value, E fallback,
                      const std::array<std::pair<E, std::string_view>, N>& table) {
  if (value != fallback) {
    args.push_back(flag(name) + "=" + std::string(enum_name<E>(EnumTable<E>(table), value)));
  }
}

// On/off parameters: "--name" or "--no-name", when not the default.
template <class Settings, class Param, std::size_t N>
void add_changed_switches(std::vector<std::string>& args, const Settings& settings,
                          const std::array<Param, N>& params) {
  const Settings defaults{};
  for (const auto& p : params) {
    const bool value = settings.*(p.field);
    if (value != defaults.*(p.field))
      args.push_back((value ? "--" : "--no-") + std::string(p.name));
  }
}

bool needs_quotes(const std::string& arg) {
  if (arg.empty()) return true;
  for (const char c : arg) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       std::string_view("-_=.,:/+@%").find(c) != std::string_view::npos;
    if (!plain) return true;
  }
  return false;
}

}  // namespace

std::vector<std::string> render_command_args(const RenderCommand& command) {
  const RenderSettings render_defaults{};
  const ShadowSettings shadow_defaults{};
  std::vector<std::string> args{"render"};
  if (!command.model_argument.empty()) {
    args.push_back("--model=" + command.model_argument);
  } else if (command.scene_argument != "default") {
    args.push_back("--scene=" + command.scene_argument);
  }
  if (command.camera_index >= 0) {
    args.push_back("--camera-index=" + std::to_string(command.camera_index));
  }
  if (command.ground) args.push_back("--ground");
  if (!command.light.empty()) args.push_back("--light=" + command.light);
  add_changed_name(args, "technique", command.shadow.technique, shadow_defaults.technique,
                   kTechniqueNames);
  add_changed_name(args, "filter", command.shadow.filter, shadow_defaults.filter, kFilterNames);
  add_changed_name(args, "shadow-maps", command.shadow.shadow_maps, shadow_defaults.shadow_maps,
                   kShadowMapKindNames);
  add_changed_name(args, "view", command.render.view, render_defaults.view, kViewNames);
  add_changed(args, command.render, kRenderIntParams);
  add_changed(args, command.shadow, kShadowIntParams);
  add_changed(args, command.shadow, kAccumulateParams);
  add_changed(args, command.shadow, kShadowFloatParams);
  add_changed(args, command.shadow, kRendererShadowIntParams);
  add_changed(args, command.shadow, kRendererShadowFloatParams);
  for (const SourceSizeParam& p : kSourceSizeParams) {
    const SourceSizeOverride& size = command.shadow.*(p.override_field);
    if (size.is_set()) args.push_back(flag(p.name) + "=" + text(static_cast<float>(size)));
  }
  add_changed_switches(args, command.ssao, kSsaoSwitchParams);
  add_changed(args, command.ssao, kSsaoIntParams);
  add_changed(args, command.ssao, kSsaoFloatParams);
  add_changed_switches(args, command.shadow, kShadowSwitchParams);
  add_changed_switches(args, command.shadow, kRendererShadowSwitchParams);
  add_changed_switches(args, command.shadow, kShadowFlagParams);
  if (command.original != nullptr && command.edited != nullptr) {
    for (std::string& arg :
         scene_option_args(*command.original, *command.edited, command.render.light_index)) {
      args.push_back(std::move(arg));
    }
  }
  args.push_back("--output=" + command.output);
  return args;
}

std::string shell_command(const std::vector<std::string>& args) {
  std::string line = "penumbra";
  for (const std::string& arg : args) {
    line += ' ';
    if (!needs_quotes(arg)) {
      line += arg;
      continue;
    }
    line += '\'';
    for (const char c : arg) {
      if (c == '\'') {
        line += "'\\''";
      } else {
        line += c;
      }
    }
    line += '\'';
  }
  return line;
}

}  // namespace penumbra
