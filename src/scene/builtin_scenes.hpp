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

// A model file (scene/model.hpp) scaled so that its largest side is
// kFramedModelSize, standing on the middle of a ground plane, seen whole by
// the camera from the front left, lit by a spot light from the right and a
// little behind, which throws the model's shadow beside it and towards the
// camera, where the camera sees it, and by a dim directional light. The
// model keeps its file's materials. Throws RuntimeError naming the file,
// as load_model does.
inline constexpr float kFramedModelSize = 2.0f;
Scene framed_model_scene(const std::string& path);

// Throws RuntimeError "<path>: coordinates reach X, too large to make
// <what> for ..." where the bounds' size, times the ground's 10, overflows
// a float (coordinates near 3.4e38): the camera, lights or ground made
// from them below would leave nothing in view.
void check_frameable(const std::string& path, const Bounds& bounds, const char* what);

// The camera framed_model_scene aims at a model, for any world-space
// bounds: from the front left (35 degrees round from the front), 40
// degrees above the horizon, the bounding sphere filling 80% of the
// image's height (the model itself less: its box's diagonal is the
// sphere's diameter).
Camera framing_camera(const Bounds& bounds);

// Adds framed_model_scene's ground to a scene: a grey plane at the bottom
// of `bounds`, centred under them, ten times their bounding sphere's radius
// across, with a material of its own, appended to scene.materials.
void add_ground(Scene& scene, const Bounds& bounds);

// framed_model_scene's lights for any world-space bounds: the key spot
// light up high, to the right and a little behind (105 degrees round from
// the camera), and the dim directional sky light.
std::vector<Light> framing_lights(const Bounds& bounds);

}  // namespace penumbra
