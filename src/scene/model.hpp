#pragma once
// Triangle models read from files (OBJ, PLY, glTF 2.0, STL, OFF and the
// other formats Open Asset Import Library reads), checked so that a bad
// file ends in one error naming it rather than a crash or a broken image.
#include <cstddef>
#include <string>
#include <vector>

#include "scene/mesh.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// The model reader (assimp, in a child process) runs under an address-space
// limit of kReaderMemoryFloor plus kReaderMemoryPerFileByte per byte of the
// file; a file that needs more is an error naming it.
inline constexpr std::size_t kReaderMemoryFloor = std::size_t{2} << 30;
inline constexpr std::size_t kReaderMemoryPerFileByte = 48;

// A camera or a light of the file, placed by its node.
struct ModelCamera {
  std::string name;
  Camera camera;              // fov_y_degrees, near_plane and far_plane from the file
  bool orthographic = false;  // penumbra draws perspective only
};
struct ModelLight {
  std::string name;
  Light light;
};

struct Model {
  std::string path;  // as given to load_model
  // Object space, as the file places it (its node transforms applied).
  // Vertex::material indexes `materials`.
  TriangleMesh mesh;
  std::vector<Material> materials;  // at least one; textures decoded
  Bounds bounds;
  // glTF cameras and KHR_lights_punctual lights, in the file's order, in
  // the model's space (see gltf_scene.hpp for their units).
  std::vector<ModelCamera> cameras;
  std::vector<ModelLight> lights;
  // What could not be read but has a fallback (a missing texture file):
  // one line each, for the caller to print as warnings.
  std::vector<std::string> warnings;
};

// Reads a model and checks it (textures that cannot be read are a warning
// each and the flat colour): every index in range, every position
// finite, at least one triangle. Normals missing from the file are
// computed (smooth_normals.hpp, creases above 80 degrees kept); a file's
// normal that is non-finite or zero becomes the area-weighted mean of its
// triangles' normals.
// OBJ files without materials and binary PLY files are read by the direct
// readers (direct_readers.hpp) in this process; every other file by
// assimp in a child process. ModelReader::Assimp sends every file to
// assimp (the tests compare the two).
// Throws RuntimeError "<path>: <what is wrong>".
enum class ModelReader { Any, Assimp };
Model load_model(const std::string& path, ModelReader reader = ModelReader::Any);

// Loads the model into `shape` (kind Model, file = path). With
// `own_materials`, the model's materials are appended to the scene and
// `shape.material` becomes the first of them; otherwise the whole model
// takes `shape.material`. Throws as load_model does.
void attach_model(Scene& scene, Shape& shape, const std::string& path, bool own_materials);

}  // namespace penumbra
