#include "forward_renderer.hpp"

#include <penumbra/shadow_maps.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace embed {

namespace {

constexpr int kMaxLights = 2;

const char* kVertexShader = R"(#version 450 core
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 0) uniform mat4 u_view_projection;
out vec3 v_world;
out vec3 v_normal;
void main() {
  v_world = in_position;
  v_normal = in_normal;
  gl_Position = u_view_projection * vec4(in_position, 1.0);
}
)";

// After "#version" and penumbra's lookup.
const char* kFragmentShader = R"(
in vec3 v_world;
in vec3 v_normal;
layout(location = 0) out vec4 out_color;
layout(location = 1) uniform int u_light_count;
layout(location = 2) uniform int u_shadow_of;
layout(location = 3) uniform vec4 u_light_position[2];   // xyz; w: 1 spot, 0 sun
layout(location = 5) uniform vec4 u_light_direction[2];  // xyz: the way it shines; w: cos(cone)
layout(location = 7) uniform vec3 u_light_color[2];

void main() {
  vec3 n = normalize(v_normal);
  // The triangle's own normal, which the shadow map's flat triangles agree
  // with, from the world position's screen derivatives (on the side of
  // the interpolated one): penumbra's lookup biases and clips by it and
  // weighs the light's source above the interpolated normal's horizon.
  vec3 face = normalize(cross(dFdx(v_world), dFdy(v_world)));
  if (dot(face, n) < 0.0) face = -face;
  if (u_shadow_of >= 0) {
    out_color = vec4(vec3(penumbra_shadow(u_shadow_of, v_world, face, n)), 1.0);
    return;
  }
  vec3 albedo = vec3(0.75);
  vec3 color = vec3(0.05) * albedo;
  for (int i = 0; i < u_light_count; ++i) {
    vec3 to_light = -u_light_direction[i].xyz;
    vec3 irradiance = u_light_color[i];
    if (u_light_position[i].w != 0.0) {
      vec3 d = u_light_position[i].xyz - v_world;
      float distance2 = dot(d, d);
      to_light = d * inversesqrt(distance2);
      float cos_axis = dot(-to_light, u_light_direction[i].xyz);
      float cone = smoothstep(u_light_direction[i].w, u_light_direction[i].w + 0.05, cos_axis);
      irradiance *= cone / distance2;
    }
    float n_dot_l = dot(n, to_light);
    if (n_dot_l <= 0.0) continue;
    color += penumbra_shadow(i, v_world, face, n) * n_dot_l * irradiance * albedo;
  }
  color = color / (1.0 + color);  // Reinhard
  out_color = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
)";

GLuint compile(GLenum stage, const std::string& source) {
  GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error(std::string("shader compile failed: ") + log);
  }
  return shader;
}

}  // namespace

ForwardRenderer::ForwardRenderer(int width, int height) : width_(width), height_(height) {
  const GLuint vertex = compile(GL_VERTEX_SHADER, kVertexShader);
  const GLuint fragment = compile(
      GL_FRAGMENT_SHADER, "#version 450 core\n" + penumbra::shadow_lookup_glsl() + kFragmentShader);
  program_ = glCreateProgram();
  glAttachShader(program_, vertex);
  glAttachShader(program_, fragment);
  glLinkProgram(program_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = 0;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) throw std::runtime_error("shader link failed");

  glCreateTextures(GL_TEXTURE_2D, 1, &color_);
  glTextureStorage2D(color_, 1, GL_RGBA8, width, height);
  glCreateRenderbuffers(1, &depth_);
  glNamedRenderbufferStorage(depth_, GL_DEPTH_COMPONENT24, width, height);
  glCreateFramebuffers(1, &framebuffer_);
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, color_, 0);
  glNamedFramebufferRenderbuffer(framebuffer_, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  if (glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("incomplete framebuffer");
  }
}

ForwardRenderer::~ForwardRenderer() {
  glDeleteProgram(program_);
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteTextures(1, &color_);
  glDeleteRenderbuffers(1, &depth_);
}

void ForwardRenderer::draw(const GpuMesh& mesh, const glm::mat4& view_projection,
                           std::span<const EngineLight> lights, int shadow_of) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width_, height_);
  const float background[] = {0.2f, 0.22f, 0.26f, 1.0f};
  const float far_depth = 1.0f;
  glClearNamedFramebufferfv(framebuffer_, GL_COLOR, 0, background);
  glClearNamedFramebufferfv(framebuffer_, GL_DEPTH, 0, &far_depth);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glUseProgram(program_);
  glProgramUniformMatrix4fv(program_, 0, 1, GL_FALSE, &view_projection[0][0]);
  const int count = static_cast<int>(std::min<std::size_t>(lights.size(), kMaxLights));
  glProgramUniform1i(program_, 1, count);
  glProgramUniform1i(program_, 2, shadow_of);
  for (int i = 0; i < count; ++i) {
    const EngineLight& light = lights[static_cast<std::size_t>(i)];
    glProgramUniform4f(program_, 3 + i, light.position.x, light.position.y, light.position.z,
                       light.directional ? 0.0f : 1.0f);
    glProgramUniform4f(program_, 5 + i, light.direction.x, light.direction.y, light.direction.z,
                       std::cos(glm::radians(light.cone_degrees)));
    glProgramUniform3f(program_, 7 + i, light.color.x, light.color.y, light.color.z);
  }
  mesh.draw();
}

std::vector<std::uint8_t> ForwardRenderer::read_rgb() const {
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width_) * height_ * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(color_, 0, GL_RGB, GL_UNSIGNED_BYTE, static_cast<GLsizei>(pixels.size()),
                    pixels.data());
  // GL rows run bottom to top.
  std::vector<std::uint8_t> flipped(pixels.size());
  const std::size_t row = static_cast<std::size_t>(width_) * 3;
  for (int y = 0; y < height_; ++y) {
    std::copy_n(pixels.begin() + static_cast<std::ptrdiff_t>((height_ - 1 - y) * row), row,
                flipped.begin() + static_cast<std::ptrdiff_t>(y * row));
  }
  return flipped;
}

}  // namespace embed
