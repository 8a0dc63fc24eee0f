#pragma once
// A static scene: materials, shapes placed with transforms, a camera and
// lights. Shapes are described by their parameters; mesh.hpp turns them
// into world-space triangles.
#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

#include <vector>
#include "penumbra/enum_names.hpp"
#include "penumbra/light.hpp"

namespace penumbra {

// A decoded texture: 8-bit RGBA, rows from the top of the image down, the
// colour sRGB-encoded and the alpha linear (as PNG and JPEG store them).
struct TextureImage {
  std::string name;  // the file, or "<model>: embedded texture N", for messages
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
};

// glTF's sampler wrap modes (OBJ textures repeat).
enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };

// glTF's alphaMode. A deferred renderer draws no translucency: Blend
// surfaces are drawn as Mask at a cutoff of 0.5, in the G-buffer and in
// every shadow pass (documented in docs/scenes.md, "Scenes").
enum class AlphaMode { Opaque, Mask, Blend };

struct Material {
  std::string name;
  glm::vec3 albedo{0.8f};     // linear diffuse reflectance
  glm::vec3 specular{0.04f};  // Blinn-Phong specular colour
  float shininess = 32.0f;    // Blinn-Phong exponent
  // Coverage: the base colour's alpha factor, times the texture's alpha
  // and the vertex colour's; below alpha_cutoff a Mask surface is a hole.
  float alpha = 1.0f;
  AlphaMode alpha_mode = AlphaMode::Opaque;
  float alpha_cutoff = 0.5f;
  // Single-sided surfaces (glTF's default) are culled where their back
  // faces the camera or the light; the built-in shapes are double-sided.
  bool double_sided = true;
  // The base colour texture, multiplied into albedo and alpha, or null.
  std::shared_ptr<const TextureImage> texture{};
  TextureWrap wrap_s = TextureWrap::Repeat;
  TextureWrap wrap_t = TextureWrap::Repeat;
  bool nearest_magnification = false;  // glTF magFilter NEAREST
  // The texture coordinate of a vertex's uv: uv_transform * (u, v, 1), in
  // the image's own coordinates ((0, 0) its top-left corner). Vertices
  // carry uv with v up (OpenGL's and OBJ's convention, which the model
  // reader converts glTF's to), so the default flips v.
  glm::mat3x2 uv_transform{1.0f, 0.0f, 0.0f, -1.0f, 0.0f, 1.0f};
};

// The cutoff below which a material's coverage is a hole, or a negative
// number when it has none (opaque).
inline float coverage_cutoff(const Material& m) {
  switch (m.alpha_mode) {
    case AlphaMode::Mask:
      return m.alpha_cutoff;
    case AlphaMode::Blend:
      return 0.5f;
    default:
      return -1.0f;
  }
}

enum class ShapeKind { Plane, Box, Sphere, Cylinder, Torus, Model };

struct Model;  // a model file's triangles: scene/model.hpp

struct Shape {
  ShapeKind kind = ShapeKind::Box;
  // Shape parameters; each kind reads the ones it needs:
  glm::vec3 size{1.0f};  // plane: x,z extent; box: x,y,z extent
  float radius = 0.5f;   // sphere, cylinder; torus: ring radius
  float height = 1.0f;   // cylinder, centred on the origin along y
  float tube = 0.15f;    // torus: tube radius
  // Model: the file, and its triangles as loaded with the scene (so that
  // every mesh built from the scene reuses one copy). With own_materials,
  // the model's material i is scene.materials[material + i]; without, the
  // whole model takes `material`.
  std::string file;
  std::shared_ptr<const Model> model;
  bool own_materials = false;
  // Placement: scale (per axis, > 0), then rotate (degrees about x, then y,
  // then z), then translate.
  glm::vec3 scale{1.0f};
  glm::vec3 position{0.0f};
  glm::vec3 rotation_degrees{0.0f};
  int material = 0;
};

struct Camera {
  glm::vec3 position{0.0f, 5.0f, 10.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_degrees = 45.0f;
  // The clip planes a scene file gives (glTF's znear / zfar), or 0: the
  // renderer fits its planes to the geometry in view, within these.
  float near_plane = 0.0f;
  float far_plane = 0.0f;
  bool operator==(const Camera&) const = default;
};

struct Scene {
  std::string name;
  std::vector<Material> materials;
  std::vector<Shape> shapes;
  Camera camera;
  std::vector<Light> lights;
};

// Axis-aligned bounds of world-space points.
struct Bounds {
  glm::vec3 min{1e30f};
  glm::vec3 max{-1e30f};
  void extend(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  [[nodiscard]] bool empty() const { return min.x > max.x; }
  [[nodiscard]] glm::vec3 center() const { return 0.5f * (min + max); }
};

}  // namespace penumbra
