#pragma once
// The foliage scene that scripts/make-foliage-scene writes (scenes/foliage/:
// a glTF file, its buffer and its two mask textures), built into the
// binary at build time (cmake/embed_files.cmake), so that `penumbra
// report` needs neither the source tree nor Python, and downloads nothing.
#include <span>
#include <string>
#include <string_view>

namespace penumbra {

struct EmbeddedFile {
  std::string_view name;  // relative to scenes/foliage/
  std::string_view bytes;
};

std::span<const EmbeddedFile> foliage_scene_files();

// Writes the scene's files into `folder` (made if missing) and returns the
// path of its .gltf file. Throws RuntimeError when a file cannot be written.
std::string write_foliage_scene(const std::string& folder);

}  // namespace penumbra
