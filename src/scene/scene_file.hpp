#pragma once
// Scenes as JSON files. The format (every key optional unless stated):
//
// {
//   "camera":    {"position": [x,y,z], "target": [x,y,z], "up": [x,y,z], "fov": degrees},
//   "materials": {"NAME": {"albedo": [r,g,b], "specular": [r,g,b], "shininess": s}, ...},
//   "lights":    [{"type": "spot"|"directional", "position": [..], "direction": [..] or
//                  "target": [..], "color": [r,g,b], "intensity": i,
//                  "cone": degrees, "inner_cone": degrees}, ...],      (at least one)
//   "objects":   [{"shape": "plane"|"box"|"sphere"|"cylinder"|"torus"|"model",
//                  "size": [..], "radius": r, "height": h, "tube": t,
//                  "file": "models/x.obj", "scale": s or [x,y,z],
//                  "position": [..], "rotation": [x,y,z degrees],
//                  "material": "NAME"}, ...]                          (at least one)
// }
//
// Every shape is scaled, then rotated (x, then y, then z), then moved. A
// model's "file" is relative to the scene file's folder (model.hpp lists
// the checks); without "material" it keeps the colours its file gives.
//
// Unknown keys and bad values are errors naming the file and the key's path
// (e.g. "scene.json: /objects/2/radius: must be > 0").
#include <cstddef>
#include <string>

#include "scene/scene.hpp"

namespace penumbra {

// Parses a scene from JSON text; `origin` names the source in messages, and
// model files are found relative to its folder.
// Throws RuntimeError.
Scene parse_scene_json(const std::string& text, const std::string& origin);

// The largest scene file read: far above any hand-written scene (the
// bundled ones are a few kB), far below what would exhaust memory.
inline constexpr std::size_t kMaxSceneFileBytes = std::size_t{16} << 20;

// Reads and parses a scene file: a regular file of at most
// kMaxSceneFileBytes (a FIFO, a device or a folder is refused unread).
// Throws RuntimeError.
Scene load_scene_file(const std::string& path);

// A built-in scene name, a path to a .json file, or a glTF file (.gltf,
// .glb: gltf_scene.hpp, its camera `camera_index`, -1 for its first).
// Throws UsageError for an unknown name, RuntimeError for a file that
// cannot be read or parsed.
Scene resolve_scene(const std::string& name_or_path, int camera_index = -1);

}  // namespace penumbra
