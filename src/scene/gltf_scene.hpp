#pragma once
// A glTF file (.gltf, .glb) as a whole scene, at its own scale: its node
// hierarchy, its materials, a camera of its own and its KHR_lights_punctual
// lights (units: gltf_lights.hpp). Where the file has no camera, the scene
// is framed as framed_model_scene frames a model; where it has no lights,
// it is lit by framed_model_scene's lights. Nothing is rescaled and no
// ground is added (`--model` does that).
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace penumbra {

// Whether a path names a glTF file (by its extension, in any case).
bool is_gltf_path(const std::string& path);

// The most lights a scene has (MAX_LIGHTS of shaders/shared/bindings.h).
inline constexpr int kMaxSceneLights = 4;

struct GltfSceneNotes {
  std::vector<std::string> warnings;  // one line each: dropped lights, unreadable textures
};

// Loads the scene; camera_index picks the file's camera (-1: its first, if
// any). Throws RuntimeError as load_model does, and UsageError for a
// camera_index the file does not have or an orthographic camera. Warnings
// (lights beyond kMaxSceneLights, dropped by name) go to `notes`.
Scene gltf_scene(const std::string& path, int camera_index, GltfSceneNotes& notes);

// The same, printing each warning as one "penumbra: warning: ..." line on
// stderr.
Scene gltf_scene(const std::string& path, int camera_index = -1);

}  // namespace penumbra
