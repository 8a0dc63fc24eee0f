#pragma once
// glTF scenes the tests write themselves: quads with materials (textures,
// alpha modes, doubleSided), cameras and KHR_lights_punctual lights, and
// the PNG textures they name.
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <string>
#include <vector>

namespace penumbra::testing {

// A quad: corners counter-clockwise seen from its front; glTF texture
// coordinates (0,0), (1,0), (1,1), (0,1) at corners 0..3 (v down the image).
struct GltfQuad {
  glm::vec3 corners[4];
  int material = 0;
};

struct GltfMaterialSpec {
  glm::vec4 base_color{1.0f};
  std::string image{};  // a uri beside the file, or empty
  std::string alpha_mode = "OPAQUE";
  float alpha_cutoff = 0.5f;
  bool double_sided = false;
  std::string texture_transform{};  // the KHR_texture_transform object's JSON, or empty
};

struct GltfCameraSpec {
  glm::vec3 position{0.0f};
  glm::vec3 target{0.0f, 0.0f, -1.0f};
  float yfov = 0.8f;
  float znear = 0.1f;
  float zfar = 100.0f;
  float aspect_ratio = 0.0f;  // 0: not given (any other value is written, even a bad one)
};

struct GltfLightSpec {
  std::string name{};
  std::string type = "spot";  // "spot", "point", "directional"
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
  float inner_cone = 0.0f;
  float outer_cone = 0.785398f;
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, -1.0f, 0.0f};
};

struct GltfSpec {
  std::vector<GltfQuad> quads;
  std::vector<GltfMaterialSpec> materials;  // at least one
  std::vector<GltfCameraSpec> cameras;
  std::vector<GltfLightSpec> lights;
  // A .glb: one binary buffer holding the geometry and the images (read
  // from the files the materials name, under the model folder).
  bool binary = false;
  std::vector<std::string> extensions_used;      // beyond the ones the above need
  std::vector<std::string> extensions_required;  // also listed as used
};

// Writes the scene as `name` (a .gltf with its buffer embedded, or a .glb)
// under the tests' model folder, and returns the path.
std::string write_gltf(const std::string& name, const GltfSpec& spec);

// Writes an 8-bit RGBA PNG (rows top to bottom) under the model folder.
std::string write_rgba_png(const std::string& name, int width, int height,
                           const std::vector<std::uint8_t>& rgba);

}  // namespace penumbra::testing
