#pragma once
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace penumbra {

// Names of the scenes built into the tool ("default", "spot").
std::vector<std::string> builtin_scene_names();

// The built-in scene of that name, or nullopt.
std::optional<Scene> builtin_scene(const std::string& name);

}  // namespace penumbra
