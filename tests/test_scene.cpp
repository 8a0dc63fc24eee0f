#include "test_scene.hpp"

#include <array>
#include <utility>

namespace penumbra::testing {

TestScene::TestScene(std::string name, float albedo) {
  scene_.name = std::move(name);
  scene_.materials = {Material{"grey", glm::vec3(albedo), glm::vec3(0.0f), 8.0f}};
}

TestScene& TestScene::ground(float width, float depth, const glm::vec3& centre) {
  Shape plane;
  plane.kind = ShapeKind::Plane;
  plane.size = {width, 0.0f, depth > 0.0f ? depth : width};
  plane.position = centre;
  return shape(std::move(plane));
}

TestScene& TestScene::plane(const glm::vec3& centre, float width,
                            const glm::vec3& rotation_degrees) {
  Shape plane;
  plane.kind = ShapeKind::Plane;
  plane.size = {width, 0.0f, width};
  plane.position = centre;
  plane.rotation_degrees = rotation_degrees;
  return shape(std::move(plane));
}

TestScene& TestScene::box(const glm::vec3& centre, const glm::vec3& size,
                          const glm::vec3& rotation_degrees) {
  Shape box;
  box.kind = ShapeKind::Box;
  box.size = size;
  box.position = centre;
  box.rotation_degrees = rotation_degrees;
  return shape(std::move(box));
}

TestScene& TestScene::shape(Shape shape) {
  scene_.shapes.push_back(std::move(shape));
  return *this;
}

TestScene& TestScene::camera(const glm::vec3& position, const glm::vec3& target,
                             std::optional<float> fov_y_degrees) {
  scene_.camera.position = position;
  scene_.camera.target = target;
  if (fov_y_degrees) scene_.camera.fov_y_degrees = *fov_y_degrees;
  return *this;
}

TestScene& TestScene::light(const Light& light) {
  scene_.lights.push_back(light);
  return *this;
}

Light spot_light(const glm::vec3& position, const glm::vec3& target, float cone_degrees,
                 float inner_cone_degrees) {
  Light spot;
  spot.type = LightType::Spot;
  spot.position = position;
  spot.direction = glm::normalize(target - position);
  spot.cone_degrees = cone_degrees;
  spot.inner_cone_degrees = inner_cone_degrees;
  return spot;
}

Light sun_light(const glm::vec3& direction) {
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(direction);
  return sun;
}

Light point_light(const glm::vec3& position, float intensity) {
  Light point;
  point.type = LightType::Point;
  point.position = position;
  point.intensity = intensity;
  return point;
}

Light overhead_light(LightType type) {
  Light light;
  light.type = type;
  light.position = {0.6f, 4.0f, 0.3f};
  light.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
  light.intensity = type == LightType::Point ? 30.0f : 1.0f;
  return light;
}

RenderSettings small_frame(int width, int height, View view) {
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.view = view;
  return settings;
}

ShadowSettings virtual_maps(Technique technique) {
  ShadowSettings settings;
  settings.technique = technique;
  settings.shadow_maps = ShadowMapKind::Virtual;
  return settings;
}

std::string light_type_name(const ::testing::TestParamInfo<LightType>& info) {
  return std::string(enum_name<LightType>(kLightTypeNames, info.param));
}

void EngineMesh::quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
  const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
  const auto first = static_cast<std::uint32_t>(positions.size());
  for (glm::vec3 p : {a, b, c, d}) {
    positions.push_back(p);
    vertices.insert(vertices.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
  }
  indices.insert(indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
}

void EngineMesh::box(glm::vec3 lo, glm::vec3 hi) {
  quad({lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z});  // top
  quad({lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z});  // +z
  quad({hi.x, lo.y, lo.z}, {lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z});  // -z
  quad({hi.x, lo.y, hi.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z});  // +x
  quad({lo.x, lo.y, lo.z}, {lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {lo.x, hi.y, lo.z});  // -x
}

const std::string kEngineSceneVertex =
    "#version 450 core\n"
    "layout(location = 0) in vec3 in_position;\n"
    "layout(location = 1) in vec3 in_normal;\n"
    "layout(location = 0) uniform mat4 u_view_projection;\n"
    "out vec3 v_world;\n"
    "out vec3 v_normal;\n"
    "void main() {\n"
    "  v_world = in_position;\n"
    "  v_normal = in_normal;\n"
    "  gl_Position = u_view_projection * vec4(in_position, 1.0);\n"
    "}\n";

GLuint link_program(const std::string& vertex, const std::string& fragment, std::string& log) {
  const GLuint program = glCreateProgram();
  std::vector<GLuint> shaders;
  for (auto [stage, source] :
       {std::pair{GL_VERTEX_SHADER, &vertex}, {GL_FRAGMENT_SHADER, &fragment}}) {
    const GLuint shader = glCreateShader(stage);
    const char* text = source->c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    std::array<char, 8192> info{};
    glGetShaderInfoLog(shader, static_cast<GLsizei>(info.size()), nullptr, info.data());
    log += info.data();
    glAttachShader(program, shader);
    shaders.push_back(shader);
  }
  glLinkProgram(program);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  for (GLuint shader : shaders) glDeleteShader(shader);
  if (ok == GL_TRUE) return program;
  std::array<char, 8192> text{};
  glGetProgramInfoLog(program, static_cast<GLsizei>(text.size()), nullptr, text.data());
  log += text.data();
  glDeleteProgram(program);
  return 0;
}

PositionMesh::PositionMesh(const std::vector<glm::vec3>& triangles)
    : buffer_(gl::Buffer::from(std::span<const glm::vec3>(triangles), "test mesh")),
      vao_("test mesh"),
      count_(static_cast<GLsizei>(triangles.size())) {
  glVertexArrayVertexBuffer(vao_.id(), 0, buffer_.id(), 0, sizeof(glm::vec3));
  glEnableVertexArrayAttrib(vao_.id(), 0);
  glVertexArrayAttribFormat(vao_.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao_.id(), 0, 0);
}

void PositionMesh::draw() const {
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, count_);
  glBindVertexArray(0);
}

}  // namespace penumbra::testing
