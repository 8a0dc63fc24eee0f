#include "report/foliage_scene.hpp"

#include <filesystem>

#include "io/atomic_file.hpp"

namespace penumbra {

std::string write_foliage_scene(const std::string& folder) {
  std::filesystem::create_directories(folder);
  std::string gltf;
  for (const EmbeddedFile& file : foliage_scene_files()) {
    const std::string path = (std::filesystem::path(folder) / file.name).string();
    write_file_atomically(path, std::string(file.bytes));
    if (file.name.ends_with(".gltf")) gltf = path;
  }
  return gltf;
}

}  // namespace penumbra
