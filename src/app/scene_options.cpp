#include "app/scene_options.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

#include "app/option_style.hpp"
#include "penumbra/error.hpp"
#include "scene/scene_checks.hpp"

namespace penumbra {

namespace {

float parse_number(std::string_view name, std::string_view text) {
  float value = 0.0f;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) {
    throw UsageError(flag(name) + ": '" + std::string(text) + "' is not a finite number");
  }
  return value;
}

glm::vec3 parse_vector(std::string_view name, std::string_view text) {
  glm::vec3 v{};
  std::size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    const std::size_t comma = text.find(',', start);
    if ((i < 2) != (comma != std::string_view::npos)) {
      throw UsageError(flag(name) + ": '" + std::string(text) +
                       "' must be three numbers separated by commas");
    }
    v[i] = parse_number(name, text.substr(start, i < 2 ? comma - start : std::string_view::npos));
    start = comma + 1;
  }
  return v;
}

float parse_scalar(std::string_view name, std::string_view text, float min, float max) {
  const float value = parse_number(name, text);
  if (value < min || value > max) {
    std::ostringstream msg;
    msg << flag(name) << ": " << text << " is outside [" << min << ", " << max << "]";
    throw UsageError(msg.str());
  }
  return value;
}

// "[I:]VALUE" -> the light it names and its value.
Light& target_light(std::string_view name, std::string_view& text, int light_index,
                    LightScope scope, Scene& scene) {
  int index = light_index;
  const std::size_t colon = text.find(':');
  if (colon != std::string_view::npos) {
    const std::string_view prefix = text.substr(0, colon);
    auto [ptr, ec] = std::from_chars(prefix.data(), prefix.data() + prefix.size(), index);
    if (ec != std::errc() || ptr != prefix.data() + prefix.size() || index < 0) {
      throw UsageError(flag(name) + ": '" + std::string(prefix) +
                       "' is not a light index (the form is [I:]VALUE)");
    }
    text = text.substr(colon + 1);
  }
  if (index >= static_cast<int>(scene.lights.size())) {
    throw UsageError(flag(name) + ": scene '" + scene.name + "' has no light " +
                     std::to_string(index) + " (it has " + std::to_string(scene.lights.size()) +
                     ")");
  }
  Light& light = scene.lights[static_cast<std::size_t>(index)];
  if (!applies_to(scope, light.type)) {
    throw UsageError(flag(name) + ": light " + std::to_string(index) + " is a " +
                     std::string(enum_name<LightType>(kLightTypeNames, light.type)) +
                     " light, which has no such value");
  }
  return light;
}

std::string vector_text(const glm::vec3& v) {
  return format_float(v.x) + "," + format_float(v.y) + "," + format_float(v.z);
}

}  // namespace

std::string format_float(float value) {
  char buffer[64];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, end);
}

void add_scene_options(CLI::App& app, SceneOptions& options) {
  // Each help starts with the value's form ("X,Y,Z: ..."): it becomes the
  // placeholder, the rest the description. The range and default read as
  // every other option's (option_style.hpp).
  const auto add = [&app](std::string_view name, std::string_view help, auto& value,
                          OptionGroup group) {
    const std::size_t colon = help.find(": ");
    CLI::Option* option = app.add_option(flag(name), value, std::string(help.substr(colon + 2)))
                              ->type_name(std::string(help.substr(0, colon)))
                              ->default_str("the scene's");
    return in_group(option, group);
  };
  for (std::size_t i = 0; i < kCameraVectorParams.size(); ++i) {
    const auto& p = kCameraVectorParams[i];
    add(p.name, p.help, options.camera_vectors[i], OptionGroup::SceneAndCamera);
  }
  for (std::size_t i = 0; i < kCameraScalarParams.size(); ++i) {
    const auto& p = kCameraScalarParams[i];
    show_range(add(p.name, p.help, options.camera_scalars[i], OptionGroup::SceneAndCamera), p.min,
               p.max);
  }
  for (std::size_t i = 0; i < kLightVectorParams.size(); ++i) {
    const auto& p = kLightVectorParams[i];
    add(p.name, p.help, options.light_vectors[i], OptionGroup::Lights)->allow_extra_args(false);
  }
  for (std::size_t i = 0; i < kLightScalarParams.size(); ++i) {
    const auto& p = kLightScalarParams[i];
    show_range(add(p.name, p.help, options.light_scalars[i], OptionGroup::Lights), p.min, p.max)
        ->allow_extra_args(false);
  }
}

void apply_scene_options(const SceneOptions& options, int light_index, Scene& scene) {
  bool camera_changed = false;
  for (std::size_t i = 0; i < kCameraVectorParams.size(); ++i) {
    const auto& p = kCameraVectorParams[i];
    if (options.camera_vectors[i].empty()) continue;
    scene.camera.*(p.field) = parse_vector(p.name, options.camera_vectors[i]);
    camera_changed = true;
  }
  for (std::size_t i = 0; i < kCameraScalarParams.size(); ++i) {
    const auto& p = kCameraScalarParams[i];
    if (options.camera_scalars[i].empty()) continue;
    scene.camera.*(p.field) = parse_scalar(p.name, options.camera_scalars[i], p.min, p.max);
  }
  if (camera_changed) {
    switch (camera_defect(scene.camera)) {
      case CameraDefect::TargetAtPosition:
        throw UsageError("--camera-position and --camera-target are the same point");
      case CameraDefect::UpAlongView:
        throw UsageError(
            "--camera-position and --camera-target: the view direction is parallel to the "
            "camera's up vector " +
            vector_text(scene.camera.up));
      case CameraDefect::None:
        break;
    }
  }
  for (std::size_t i = 0; i < kLightVectorParams.size(); ++i) {
    const auto& p = kLightVectorParams[i];
    for (const std::string& value : options.light_vectors[i]) {
      std::string_view text = value;
      Light& light = target_light(p.name, text, light_index, p.scope, scene);
      const glm::vec3 v = parse_vector(p.name, text);
      if (p.field == &Light::direction && !is_usable_direction(v)) {
        throw UsageError(flag(p.name) + ": '" + std::string(text) +
                         "' is too short to be a direction");
      }
      if (p.field == &Light::color && (v.x < 0.0f || v.y < 0.0f || v.z < 0.0f)) {
        throw UsageError(flag(p.name) + ": a colour cannot be negative (got '" + std::string(text) +
                         "')");
      }
      light.*(p.field) = v;
    }
  }
  for (std::size_t i = 0; i < kLightScalarParams.size(); ++i) {
    const auto& p = kLightScalarParams[i];
    for (const std::string& value : options.light_scalars[i]) {
      std::string_view text = value;
      Light& light = target_light(p.name, text, light_index, p.scope, scene);
      light.*(p.field) = parse_scalar(p.name, text, p.min, p.max);
    }
  }
}

std::vector<std::string> scene_option_args(const Scene& original, const Scene& edited,
                                           int light_index) {
  std::vector<std::string> args;
  for (const auto& p : kCameraVectorParams) {
    if (original.camera.*(p.field) != edited.camera.*(p.field)) {
      args.push_back(flag(p.name) + "=" + vector_text(edited.camera.*(p.field)));
    }
  }
  for (const auto& p : kCameraScalarParams) {
    if (original.camera.*(p.field) != edited.camera.*(p.field)) {
      args.push_back(flag(p.name) + "=" + format_float(edited.camera.*(p.field)));
    }
  }
  const std::size_t lights = std::min(original.lights.size(), edited.lights.size());
  for (std::size_t i = 0; i < lights; ++i) {
    const Light& before = original.lights[i];
    const Light& after = edited.lights[i];
    const std::string prefix =
        static_cast<int>(i) == light_index ? std::string() : std::to_string(i) + ":";
    for (const auto& p : kLightVectorParams) {
      if (applies_to(p.scope, after.type) && before.*(p.field) != after.*(p.field)) {
        args.push_back(flag(p.name) + "=" + prefix + vector_text(after.*(p.field)));
      }
    }
    for (const auto& p : kLightScalarParams) {
      if (applies_to(p.scope, after.type) && before.*(p.field) != after.*(p.field)) {
        args.push_back(flag(p.name) + "=" + prefix + format_float(after.*(p.field)));
      }
    }
  }
  return args;
}

}  // namespace penumbra
