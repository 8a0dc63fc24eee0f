#pragma once
// A glTF file (.gltf, .glb) as a whole scene, at its own scale: its node
// hierarchy, its materials, a camera of its own and its KHR_lights_punctual
// lights (units: gltf_lights.hpp). Where the file has no camera, the scene
// is framed as framed_model_scene frames a model; where it has no lights,
// it is lit by framed_model_scene's lights; where it has no ground
// (has_ground), one is added only when asked for (`--ground on`). Each of
// these assumptions is a note. Nothing is rescaled.
#include <string>
#include <vector>

#include "scene/mesh.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// Whether a path names a glTF file (by its extension, in any case).
bool is_gltf_path(const std::string& path);

// The most lights a scene has (MAX_LIGHTS of shaders/shared/bindings.h).
inline constexpr int kMaxSceneLights = 4;

struct GltfSceneNotes {
  std::vector<std::string> warnings;  // one line each: dropped lights, unreadable textures
  // One line each: what was assumed for a camera, lights or a ground the
  // file does not have.
  std::vector<std::string> assumptions;
};

// Whether the triangles have a ground: faces within 1% of the largest side
// of the bounds above the lowest point, facing up or down (within 18
// degrees of vertical), whose area is at least a quarter of the bounds'
// x-z footprint.
bool has_ground(const TriangleMesh& mesh, const Bounds& bounds);

// Loads the scene; camera_index picks the file's camera (-1: its first, if
// any); `ground` adds framed_model_scene's ground under a scene without
// one. Throws RuntimeError as load_model does, and UsageError for a
// camera_index the file does not have or an orthographic camera. Warnings
// (lights beyond kMaxSceneLights, dropped by name) and assumptions go to
// `notes`.
Scene gltf_scene(const std::string& path, int camera_index, GltfSceneNotes& notes,
                 bool ground = false);

// The same, printing each warning as one "penumbra: warning: ..." line and
// each assumption as one "penumbra: note: ..." line on stderr.
Scene gltf_scene(const std::string& path, int camera_index = -1, bool ground = false);

}  // namespace penumbra
