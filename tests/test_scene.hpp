#pragma once
// The one small-scene and settings builder of the GPU tests: a grey
// diffuse material (material 0), shapes, a camera and lights, each said in
// one line, so that a test's scene reads as what it is.
#include <gtest/gtest.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "penumbra/gl/resources.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace penumbra::testing {

class TestScene {
 public:
  // `albedo`: material 0's grey, diffuse only (Blinn-Phong exponent 8).
  explicit TestScene(std::string name, float albedo = 0.7f);

  // A plane facing +y, `width` along x and `depth` along z (depth 0: square).
  TestScene& ground(float width, float depth = 0.0f, const glm::vec3& centre = glm::vec3(0.0f));
  // A square plane `width` wide, turned from facing +y by `rotation_degrees`
  // (about x, then y, then z).
  TestScene& plane(const glm::vec3& centre, float width, const glm::vec3& rotation_degrees);
  TestScene& box(const glm::vec3& centre, const glm::vec3& size,
                 const glm::vec3& rotation_degrees = glm::vec3(0.0f));
  TestScene& shape(Shape shape);  // anything the two above do not say
  // fov_y_degrees not given: Camera's default.
  TestScene& camera(const glm::vec3& position, const glm::vec3& target,
                    std::optional<float> fov_y_degrees = std::nullopt);
  TestScene& light(const Light& light);

  const Scene& scene() const { return scene_; }
  operator const Scene&() const { return scene_; }  // NOLINT: a builder reads as its scene

 private:
  Scene scene_;
};

// A spot light at `position` aimed at `target`, its cone's half-angles.
Light spot_light(const glm::vec3& position, const glm::vec3& target, float cone_degrees,
                 float inner_cone_degrees);
// A directional light shining along `direction` (normalized here).
Light sun_light(const glm::vec3& direction);
Light point_light(const glm::vec3& position, float intensity);
// A light of any type above the origin: spot and point at (0.6, 4, 0.3)
// (point: intensity 30), spot and sun shining along (0.2, -1, 0.1).
Light overhead_light(LightType type);

// A small frame of the given view.
RenderSettings small_frame(int width, int height, View view = View::Shadow);
// The technique over virtual shadow maps, every other setting its default.
ShadowSettings virtual_maps(Technique technique);

// The light type's name, for tests instantiated over every light type.
std::string light_type_name(const ::testing::TestParamInfo<LightType>& info);

// An engine's own indexed mesh of quads with flat normals per face:
// interleaved position xyz and normal xyz, the positions again for
// ShadowMaps' casters, and the indices.
struct EngineMesh {
  std::vector<float> vertices;
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;

  // The quad a, b, c, d, counter-clockwise seen from its front.
  void quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d);
  // The box lo..hi without its bottom face.
  void box(glm::vec3 lo, glm::vec3 hi);
};

// An engine's vertex shader for EngineMesh: position and normal at
// attributes 0 and 1, the view-projection at uniform location 0, the world
// position and normal out as v_world and v_normal.
extern const std::string kEngineSceneVertex;

// A linked program of the two stages, or 0 with the logs in `log`.
GLuint link_program(const std::string& vertex, const std::string& fragment, std::string& log);

// A triangle list of positions at attribute 0, drawn as an engine draws its
// meshes into ShadowMaps' views.
class PositionMesh {
 public:
  explicit PositionMesh(const std::vector<glm::vec3>& triangles);
  void draw() const;

 private:
  gl::Buffer buffer_;
  gl::VertexArray vao_;
  GLsizei count_;
};

}  // namespace penumbra::testing
