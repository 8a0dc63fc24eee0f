#pragma once
// The engine's own renderer: one forward pass into its own framebuffer,
// Lambert-lit, each light's contribution shadowed by penumbra's lookup,
// penumbra_shadow(), called from the engine's fragment shader.
// The engine's own GL loader (GLEW); penumbra's headers bring none.
#include <GL/glew.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "mesh.hpp"

namespace embed {

struct EngineLight {
  bool directional = false;
  glm::vec3 position{0.0f};   // spot
  glm::vec3 direction{0.0f};  // the way it shines (unit)
  glm::vec3 color{1.0f};      // spot: intensity at 1 m; sun: irradiance
  float cone_degrees = 45.0f;
};

class ForwardRenderer {
 public:
  // Compiles the engine's shaders around penumbra::shadow_lookup_glsl().
  ForwardRenderer(int width, int height);
  ~ForwardRenderer();
  ForwardRenderer(const ForwardRenderer&) = delete;
  ForwardRenderer& operator=(const ForwardRenderer&) = delete;

  // Draws the mesh lit by the lights (light i is penumbra's light i), with
  // the shadow maps bound (penumbra::ShadowMaps::bind()). shadow_of >= 0:
  // writes that light's shadow factor instead, grey (1 = lit).
  void draw(const GpuMesh& mesh, const glm::mat4& view_projection,
            std::span<const EngineLight> lights, int shadow_of);

  // The image, 8-bit RGB, rows top to bottom.
  [[nodiscard]] std::vector<std::uint8_t> read_rgb() const;

 private:
  int width_, height_;
  GLuint program_ = 0, framebuffer_ = 0, color_ = 0, depth_ = 0;
};

}  // namespace embed
