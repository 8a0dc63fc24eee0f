#pragma once
// Camera and light changes on top of a scene's own, from the command line:
// `render` and `view` read them, the viewer's "Copy as command" writes
// them. Each flag's name, help and range live in the tables below only.
#include <CLI/CLI.hpp>
#include <array>
#include <glm/glm.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"

namespace penumbra {

// Which lights have a light parameter.
enum class LightScope {
  All,
  Positional,  // spot and point lights (a position)
  Directed,    // spot and directional lights (a direction)
  Spot,        // spot lights only (a cone)
};

constexpr bool applies_to(LightScope scope, LightType type) {
  switch (scope) {
    case LightScope::Positional:
      return type != LightType::Directional;
    case LightScope::Directed:
      return type != LightType::Point;
    case LightScope::Spot:
      return type == LightType::Spot;
    default:
      return true;
  }
}

template <class Object>
struct VectorParam {
  std::string_view name;
  std::string_view help;
  glm::vec3 Object::*field;
  LightScope scope = LightScope::All;  // lights: which have the value
};

template <class Object>
struct ScalarParam {
  std::string_view name;
  std::string_view help;
  float min;
  float max;
  float Object::*field;
  LightScope scope = LightScope::All;
};

inline constexpr std::array<VectorParam<Camera>, 2> kCameraVectorParams{{
    {"camera-position", "X,Y,Z: where the camera is (world units)", &Camera::position},
    {"camera-target", "X,Y,Z: the point the camera looks at", &Camera::target},
}};

inline constexpr std::array<ScalarParam<Camera>, 1> kCameraScalarParams{{
    {"camera-fov", "DEGREES: the camera's vertical field of view", 1.0f, 170.0f,
     &Camera::fov_y_degrees},
}};

// Light flags take "[I:]VALUE": light I's value, or --light-index's light
// without "I:". They may be repeated for several lights.
inline constexpr std::array<VectorParam<Light>, 3> kLightVectorParams{{
    {"light-position", "[I:]X,Y,Z: a spot or point light's position", &Light::position,
     LightScope::Positional},
    {"light-direction",
     "[I:]X,Y,Z: the direction a spot or directional light shines in (any length from 1e-6)",
     &Light::direction, LightScope::Directed},
    {"light-color", "[I:]R,G,B: a light's linear colour", &Light::color},
}};

inline constexpr std::array<ScalarParam<Light>, 2> kLightScalarParams{{
    {"light-intensity",
     "[I:]V: a spot or point light's radiant intensity (irradiance at 1 m, falling off as "
     "1/d^2), a directional light's irradiance",
     0.0f, 1e6f, &Light::intensity},
    {"light-cone", "[I:]DEGREES: a spot light's cone half-angle, where its light ends", 0.1f, 89.9f,
     &Light::cone_degrees, LightScope::Spot},
}};

// The flags' values as given, parsed by apply_scene_options().
struct SceneOptions {
  std::array<std::string, kCameraVectorParams.size()> camera_vectors;
  std::array<std::string, kCameraScalarParams.size()> camera_scalars;
  std::array<std::vector<std::string>, kLightVectorParams.size()> light_vectors;
  std::array<std::vector<std::string>, kLightScalarParams.size()> light_scalars;
};

void add_scene_options(CLI::App& app, SceneOptions& options);

// Applies the options to the scene's camera and lights; a light value
// without "I:" goes to light `light_index`. Throws UsageError naming the
// flag for a malformed or out-of-range value, a light the scene lacks, a
// value the light does not have (a directional light's position, a point
// light's direction or cone, ...), or a camera whose
// position is its target.
void apply_scene_options(const SceneOptions& options, int light_index, Scene& scene);

// The flags that turn `original`'s camera and lights into `edited`'s, as
// "--name=value" arguments (so negative numbers read as values), exact to
// the last bit of each float. `edited` has `original`'s lights, changed.
std::vector<std::string> scene_option_args(const Scene& original, const Scene& edited,
                                           int light_index);

// The shortest text that reads back as exactly `value`.
std::string format_float(float value);

}  // namespace penumbra
