#pragma once
// The extensions a glTF file declares (extensionsUsed, extensionsRequired),
// read from its JSON (a .gltf, or a .glb's JSON chunk), so that a file that
// needs one penumbra does not read is refused by name instead of drawn
// wrong, and one it merely uses is named in a warning.
#include <string>
#include <vector>

namespace penumbra {

// The extensions penumbra reads: KHR_lights_punctual, KHR_texture_transform.
bool is_supported_gltf_extension(const std::string& name);

struct GltfExtensions {
  std::vector<std::string> used;
  std::vector<std::string> required;
};

// Throws RuntimeError "<path>: ..." for a file whose JSON cannot be read
// (the model reader would refuse it too).
GltfExtensions read_gltf_extensions(const std::string& path);

}  // namespace penumbra
