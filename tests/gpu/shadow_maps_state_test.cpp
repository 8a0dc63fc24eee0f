// ShadowMaps as a guest in an engine's GL context (issue 30, items 2, 5's
// destruction order, 7): render() and bind() leave the engine's state as
// they found it, except the bindings bind() documents (docs/library.md,
// "GL state"); they set what they need, so an engine's scissor, polygon
// mode, clip control, ... change nothing in the maps; release() and a
// destructor without a context call no GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "gpu_fixture.hpp"
#include "penumbra/gl/context.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/penumbra.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

// Texture units, image units and indexed buffer bindings the snapshot
// reads: every one ShadowMaps uses by default, and more.
constexpr int kUnits = 16;
constexpr int kImageUnits = 4;
constexpr int kUniformBuffers = 10;
constexpr int kStorageBuffers = 12;
// Clip distances, viewports and draw buffers every GL 4.5 device has.
constexpr GLenum kClipDistances = 8;
constexpr GLuint kViewports = 2;
constexpr GLuint kDrawBuffers = 8;

constexpr std::array<std::pair<GLenum, const char*>, 11> kTextureBindings{{
    {GL_TEXTURE_BINDING_1D, "1D"},
    {GL_TEXTURE_BINDING_2D, "2D"},
    {GL_TEXTURE_BINDING_3D, "3D"},
    {GL_TEXTURE_BINDING_1D_ARRAY, "1D_ARRAY"},
    {GL_TEXTURE_BINDING_2D_ARRAY, "2D_ARRAY"},
    {GL_TEXTURE_BINDING_RECTANGLE, "RECTANGLE"},
    {GL_TEXTURE_BINDING_CUBE_MAP, "CUBE_MAP"},
    {GL_TEXTURE_BINDING_CUBE_MAP_ARRAY, "CUBE_MAP_ARRAY"},
    {GL_TEXTURE_BINDING_BUFFER, "BUFFER"},
    {GL_TEXTURE_BINDING_2D_MULTISAMPLE, "2D_MULTISAMPLE"},
    {GL_TEXTURE_BINDING_2D_MULTISAMPLE_ARRAY, "2D_MULTISAMPLE_ARRAY"},
}};

// Every piece of state the contract covers, by name, read with glGet.
using Snapshot = std::vector<std::pair<std::string, std::int64_t>>;

Snapshot snapshot() {
  Snapshot s;
  const auto integer = [&](const char* name, GLenum pname, int count = 1) {
    std::array<GLint, 4> v{};
    glGetIntegerv(pname, v.data());
    for (int i = 0; i < count; ++i)
      s.emplace_back(name + std::string("[") + std::to_string(i) + "]", v[i]);
  };
  const auto enabled = [&](const char* name, GLenum capability) {
    s.emplace_back(name, glIsEnabled(capability));
  };
  integer("GL_DRAW_FRAMEBUFFER_BINDING", GL_DRAW_FRAMEBUFFER_BINDING);
  integer("GL_READ_FRAMEBUFFER_BINDING", GL_READ_FRAMEBUFFER_BINDING);
  integer("GL_VIEWPORT", GL_VIEWPORT, 4);
  integer("GL_SCISSOR_BOX", GL_SCISSOR_BOX, 4);
  integer("GL_CURRENT_PROGRAM", GL_CURRENT_PROGRAM);
  integer("GL_VERTEX_ARRAY_BINDING", GL_VERTEX_ARRAY_BINDING);
  integer("GL_ACTIVE_TEXTURE", GL_ACTIVE_TEXTURE);
  integer("GL_UNIFORM_BUFFER_BINDING", GL_UNIFORM_BUFFER_BINDING);
  integer("GL_SHADER_STORAGE_BUFFER_BINDING", GL_SHADER_STORAGE_BUFFER_BINDING);
  integer("GL_DEPTH_FUNC", GL_DEPTH_FUNC);
  integer("GL_POLYGON_MODE", GL_POLYGON_MODE);
  integer("GL_CLIP_ORIGIN", GL_CLIP_ORIGIN);
  integer("GL_CLIP_DEPTH_MODE", GL_CLIP_DEPTH_MODE);
  integer("GL_CULL_FACE_MODE", GL_CULL_FACE_MODE);
  integer("GL_PRIMITIVE_RESTART_INDEX", GL_PRIMITIVE_RESTART_INDEX);
  integer("GL_FRONT_FACE", GL_FRONT_FACE);
  enabled("GL_DEPTH_TEST", GL_DEPTH_TEST);
  enabled("GL_CULL_FACE", GL_CULL_FACE);
  enabled("GL_SCISSOR_TEST", GL_SCISSOR_TEST);
  enabled("GL_RASTERIZER_DISCARD", GL_RASTERIZER_DISCARD);
  enabled("GL_POLYGON_OFFSET_FILL", GL_POLYGON_OFFSET_FILL);
  enabled("GL_DEPTH_CLAMP", GL_DEPTH_CLAMP);
  enabled("GL_MULTISAMPLE", GL_MULTISAMPLE);
  enabled("GL_BLEND", GL_BLEND);
  enabled("GL_STENCIL_TEST", GL_STENCIL_TEST);
  enabled("GL_PRIMITIVE_RESTART", GL_PRIMITIVE_RESTART);
  enabled("GL_MULTISAMPLE", GL_MULTISAMPLE);
  enabled("GL_SAMPLE_ALPHA_TO_COVERAGE", GL_SAMPLE_ALPHA_TO_COVERAGE);
  enabled("GL_FRAMEBUFFER_SRGB", GL_FRAMEBUFFER_SRGB);
  for (GLenum i = 0; i < kClipDistances; ++i) {
    s.emplace_back("GL_CLIP_DISTANCE" + std::to_string(i), glIsEnabled(GL_CLIP_DISTANCE0 + i));
  }
  // Indexed state: viewports, their scissor tests and depth ranges, the
  // colour mask of each draw buffer.
  for (GLuint index = 0; index < kViewports; ++index) {
    const std::string suffix = "[" + std::to_string(index) + "]";
    std::array<GLfloat, 4> viewport{};
    glGetFloati_v(GL_VIEWPORT, index, viewport.data());
    for (int i = 0; i < 4; ++i) {
      s.emplace_back("GL_VIEWPORT" + suffix + "[" + std::to_string(i) + "]",
                     static_cast<std::int64_t>(viewport[i]));
    }
    s.emplace_back("GL_SCISSOR_TEST" + suffix, glIsEnabledi(GL_SCISSOR_TEST, index));
    std::array<GLdouble, 2> range{};
    glGetDoublei_v(GL_DEPTH_RANGE, index, range.data());
    for (int i = 0; i < 2; ++i) {
      s.emplace_back("GL_DEPTH_RANGE" + suffix + "[" + std::to_string(i) + "]",
                     static_cast<std::int64_t>(range[i] * 1e6));
    }
  }
  for (GLuint buffer = 0; buffer < kDrawBuffers; ++buffer) {
    std::array<GLboolean, 4> mask{};
    glGetBooleani_v(GL_COLOR_WRITEMASK, buffer, mask.data());
    for (int i = 0; i < 4; ++i) {
      s.emplace_back("GL_COLOR_WRITEMASK draw buffer " + std::to_string(buffer) + "[" +
                         std::to_string(i) + "]",
                     mask[i]);
    }
  }
  GLboolean depth_mask = GL_FALSE;
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask);
  s.emplace_back("GL_DEPTH_WRITEMASK", depth_mask);
  std::array<GLboolean, 4> color_mask{};
  glGetBooleanv(GL_COLOR_WRITEMASK, color_mask.data());
  for (int i = 0; i < 4; ++i)
    s.emplace_back("GL_COLOR_WRITEMASK[" + std::to_string(i) + "]", color_mask[i]);
  std::array<GLdouble, 2> depth_range{};
  glGetDoublev(GL_DEPTH_RANGE, depth_range.data());
  for (int i = 0; i < 2; ++i) {
    s.emplace_back("GL_DEPTH_RANGE[" + std::to_string(i) + "]",
                   static_cast<std::int64_t>(depth_range[i] * 1e6));
  }
  // Texture bindings are per active unit; the snapshot puts it back.
  GLint active = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
  for (int unit = 0; unit < kUnits; ++unit) {
    glActiveTexture(GL_TEXTURE0 + unit);
    const std::string prefix = "unit " + std::to_string(unit) + " ";
    for (auto [pname, name] : kTextureBindings) {
      GLint texture = 0;
      glGetIntegerv(pname, &texture);
      s.emplace_back(prefix + name, texture);
    }
    GLint sampler = 0;
    glGetIntegerv(GL_SAMPLER_BINDING, &sampler);
    s.emplace_back(prefix + "sampler", sampler);
  }
  glActiveTexture(static_cast<GLenum>(active));
  for (GLuint unit = 0; unit < kImageUnits; ++unit) {
    for (auto [pname, name] : std::array<std::pair<GLenum, const char*>, 6>{{
             {GL_IMAGE_BINDING_NAME, "name"},
             {GL_IMAGE_BINDING_LEVEL, "level"},
             {GL_IMAGE_BINDING_LAYERED, "layered"},
             {GL_IMAGE_BINDING_LAYER, "layer"},
             {GL_IMAGE_BINDING_ACCESS, "access"},
             {GL_IMAGE_BINDING_FORMAT, "format"},
         }}) {
      GLint value = 0;
      glGetIntegeri_v(pname, unit, &value);
      s.emplace_back("image " + std::to_string(unit) + " " + name, value);
    }
  }
  const auto buffers = [&](const char* kind, int count, GLenum binding, GLenum start, GLenum size) {
    for (GLuint index = 0; index < static_cast<GLuint>(count); ++index) {
      const std::string prefix = kind + std::string(" ") + std::to_string(index);
      GLint64 value = 0;
      glGetInteger64i_v(binding, index, &value);
      s.emplace_back(prefix + " buffer", value);
      glGetInteger64i_v(start, index, &value);
      s.emplace_back(prefix + " start", value);
      glGetInteger64i_v(size, index, &value);
      s.emplace_back(prefix + " size", value);
    }
  };
  buffers("uniform buffer", kUniformBuffers, GL_UNIFORM_BUFFER_BINDING, GL_UNIFORM_BUFFER_START,
          GL_UNIFORM_BUFFER_SIZE);
  buffers("storage buffer", kStorageBuffers, GL_SHADER_STORAGE_BUFFER_BINDING,
          GL_SHADER_STORAGE_BUFFER_START, GL_SHADER_STORAGE_BUFFER_SIZE);
  return s;
}

// The entries of `after` that differ from `before`, but for `allowed`.
std::string changes(const Snapshot& before, const Snapshot& after,
                    const std::set<std::string>& allowed = {}) {
  std::string changed;
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (before[i] != after[i] && !allowed.contains(before[i].first)) {
      changed += "  " + before[i].first + ": " + std::to_string(before[i].second) + " -> " +
                 std::to_string(after[i].second) + "\n";
    }
  }
  return changed;
}

// A ground quad and a box above it (world space), and the engine's vertex
// array that draws them.
struct Casters {
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;
  gl::Buffer vertices, elements;
  gl::VertexArray vertex_array{"test casters"};

  Casters() {
    const auto quad = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
      const auto first = static_cast<std::uint32_t>(positions.size());
      positions.insert(positions.end(), {a, b, c, d});
      indices.insert(indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
    };
    quad({-8, 0, -8}, {-8, 0, 8}, {8, 0, 8}, {8, 0, -8});
    const glm::vec3 lo(-1, 1, -1), hi(1, 3, 1);
    quad({lo.x, hi.y, lo.z}, {lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z});
    quad({lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, lo.y, lo.z});
    quad({lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z});
    quad({lo.x, lo.y, lo.z}, {lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {lo.x, hi.y, lo.z});
    quad({hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {hi.x, lo.y, hi.z});
    vertices = gl::Buffer::from(std::span<const glm::vec3>(positions), "test caster positions");
    elements = gl::Buffer::from(std::span<const std::uint32_t>(indices), "test caster indices");
    glVertexArrayVertexBuffer(vertex_array.id(), 0, vertices.id(), 0, sizeof(glm::vec3));
    glVertexArrayAttribFormat(vertex_array.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vertex_array.id(), 0, 0);
    glEnableVertexArrayAttrib(vertex_array.id(), 0);
    glVertexArrayElementBuffer(vertex_array.id(), elements.id());
  }

  [[nodiscard]] CasterGeometry geometry() const { return {positions, indices}; }

  // The engine's callback: its own vertex array, one draw.
  [[nodiscard]] DrawCasters draw() const {
    return [this](const CasterView&) {
      glBindVertexArray(vertex_array.id());
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(indices.size()), GL_UNSIGNED_INT, nullptr);
    };
  }
};

std::vector<Light> test_lights() {
  Light spot;
  spot.position = {2.0f, 8.0f, 1.0f};
  spot.direction = glm::normalize(glm::vec3(-0.2f, -1.0f, -0.1f));
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f));
  return {spot, sun};
}

CameraFrustum test_camera() {
  CameraFrustum camera;
  camera.position = {0.0f, 6.0f, 10.0f};
  camera.forward = glm::normalize(glm::vec3(0.0f, -6.0f, -10.0f));
  camera.far_plane = 30.0f;
  return camera;
}

ShadowSettings settings_for(Technique technique, Filter filter, bool fused, int samples = 1) {
  ShadowSettings s;
  s.technique = technique;
  s.filter = filter;
  s.fused = fused;
  s.shadow_msaa = samples;
  s.map_size = 64;
  s.cascades = 2;
  return s;
}

// The engine's GL objects and a state that differs from GL's defaults in
// everything the contract covers.
struct EngineState {
  gl::Texture color{{.format = GL_RGBA8, .width = 8, .height = 8, .label = "engine color"}};
  gl::Texture array{{.target = GL_TEXTURE_2D_ARRAY,
                     .format = GL_RGBA8,
                     .width = 8,
                     .height = 8,
                     .layers = 2,
                     .label = "engine array"}};
  gl::Texture image{{.target = GL_TEXTURE_2D_ARRAY,
                     .format = GL_RGBA32F,
                     .width = 8,
                     .height = 8,
                     .layers = 2,
                     .label = "engine image"}};
  gl::Framebuffer draw_framebuffer{"engine draw"}, read_framebuffer{"engine read"};
  gl::Sampler sampler{gl::SamplerInfo{.label = "engine sampler"}};
  gl::Buffer uniforms{1024, nullptr, false, "engine uniforms"};
  gl::Buffer storage{1024, nullptr, false, "engine storage"};
  gl::VertexArray vertex_array{"engine vertex array"};
  GLuint program = 0;

  EngineState() {
    draw_framebuffer.attach_color(0, color);
    read_framebuffer.attach_color(0, color);
    const char* source = "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n";
    program = glCreateShaderProgramv(GL_VERTEX_SHADER, 1, &source);
  }
  ~EngineState() { glDeleteProgram(program); }
  EngineState(const EngineState&) = delete;
  EngineState& operator=(const EngineState&) = delete;

  void apply() const {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, draw_framebuffer.id());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, read_framebuffer.id());
    glViewport(3, 5, 17, 19);
    glUseProgram(program);
    glBindVertexArray(vertex_array.id());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_FALSE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glFrontFace(GL_CW);
    glEnable(GL_SCISSOR_TEST);
    glScissor(1, 2, 3, 4);
    glEnable(GL_RASTERIZER_DISCARD);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(4.0f, 16.0f);
    glEnable(GL_DEPTH_CLAMP);
    glDisable(GL_MULTISAMPLE);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glColorMaski(1, GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
    glDepthRange(0.25, 0.75);
    // A second viewport of its own (a split screen's), its scissor off.
    glViewportIndexedf(1, 7.0f, 11.0f, 13.0f, 23.0f);
    glDepthRangeIndexed(1, 0.125, 0.5);
    glDisablei(GL_SCISSOR_TEST, 1);
    // Clip planes left on: the casters' vertex shader writes no
    // gl_ClipDistance, so with them on what it draws is undefined.
    for (GLenum i = 0; i < kClipDistances; ++i) glEnable(GL_CLIP_DISTANCE0 + i);
    // The engine's own draws (the callback's) keep their restart index:
    // one its casters' indices do not use.
    glEnable(GL_PRIMITIVE_RESTART);
    glPrimitiveRestartIndex(0xfffffffeu);
    glDisable(GL_MULTISAMPLE);
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glEnable(GL_FRAMEBUFFER_SRGB);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ZERO, GL_ZERO);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_NEVER, 0, 0xff);
    for (int unit = 0; unit < kUnits; ++unit) {
      glBindTextureUnit(unit, color.id());
      glBindTextureUnit(unit, array.id());
      glBindSampler(unit, sampler.id());
    }
    for (GLuint unit = 0; unit < kImageUnits; ++unit) {
      glBindImageTexture(unit, image.id(), 0, GL_FALSE, 1, GL_READ_WRITE, GL_RGBA32F);
    }
    for (GLuint index = 0; index < kUniformBuffers; ++index) {
      glBindBufferRange(GL_UNIFORM_BUFFER, index, uniforms.id(), 256, 256);
    }
    for (GLuint index = 0; index < kStorageBuffers; ++index) {
      glBindBufferRange(GL_SHADER_STORAGE_BUFFER, index, storage.id(), 512, 128);
    }
    glBindBuffer(GL_UNIFORM_BUFFER, storage.id());
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, uniforms.id());
    glActiveTexture(GL_TEXTURE3);
  }
};

// GL's defaults for what EngineState::apply changes.
void apply_default_state() {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glUseProgram(0);
  glBindVertexArray(0);
  glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_RASTERIZER_DISCARD);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_DEPTH_CLAMP);
  glEnable(GL_MULTISAMPLE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
  glDepthRange(0.0, 1.0);
  for (GLenum i = 0; i < kClipDistances; ++i) glDisable(GL_CLIP_DISTANCE0 + i);
  glDisable(GL_PRIMITIVE_RESTART);
  glPrimitiveRestartIndex(0u);
  glEnable(GL_MULTISAMPLE);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glDisable(GL_FRAMEBUFFER_SRGB);
  glDisable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ZERO);
  glDisable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  for (GLuint unit = 0; unit < kUnits; ++unit) {
    glBindTextureUnit(unit, 0);
    glBindSampler(unit, 0);
  }
  for (GLuint unit = 0; unit < kImageUnits; ++unit) {
    glBindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R8);
  }
  for (GLuint index = 0; index < kUniformBuffers; ++index)
    glBindBufferBase(GL_UNIFORM_BUFFER, index, 0);
  for (GLuint index = 0; index < kStorageBuffers; ++index) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, index, 0);
  }
  glActiveTexture(GL_TEXTURE0);
}

// Every texel of a float texture array's level 0 (the depth maps or the
// filtered representation).
std::vector<float> read_texels(GLuint texture, GLenum format, int components) {
  GLint width = 0, height = 0, layers = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &width);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &height);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_DEPTH, &layers);
  std::vector<float> texels(static_cast<std::size_t>(width) * height * layers * components);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(texture, 0, format, GL_FLOAT,
                    static_cast<GLsizei>(texels.size() * sizeof(float)), texels.data());
  return texels;
}

struct Config {
  Technique technique;
  Filter filter;
  bool fused;
  const char* name;
  int samples = 1;            // --shadow-msaa
  bool virtual_maps = false;  // the sun's virtual maps, marked from the engine's depth
};
// Depth maps alone; the resolve pass and a Gaussian (storage-buffer
// weights, image units, the compute input unit); summed-area tables; the
// multisampled layers (GL_MULTISAMPLE, which the engine turned off).
constexpr std::array<Config, 5> kConfigs{{
    {Technique::Pcf, Filter::Gaussian, true, "pcf"},
    {Technique::Vsm, Filter::Gaussian, false, "vsm gaussian"},
    {Technique::Msm, Filter::Sat, true, "msm sat"},
    {Technique::Vsm, Filter::Gaussian, true, "vsm fused, 4 samples", 4},
    {Technique::Hard, Filter::Gaussian, true, "hard, virtual maps", 1, true},
}};

// The engine's camera depth for virtual maps: a plane of constant window
// depth across its pixels, far enough out to cross the casters' ground.
struct EngineDepth {
  gl::Texture texture{gl::TextureInfo{
      .format = GL_DEPTH_COMPONENT32F, .width = 32, .height = 32, .label = "engine depth"}};
  EngineDepth() {
    const float depth = 0.97f;
    glClearTexImage(texture.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  }
  [[nodiscard]] CameraDepthBuffer buffer(const CameraFrustum& camera) const {
    const glm::mat4 projection =
        glm::perspective(camera.fov_y, camera.aspect, camera.near_plane, camera.far_plane);
    return {
        .texture = texture.id(),
        .width = 32,
        .height = 32,
        .view_projection =
            projection * glm::lookAt(camera.position, camera.position + camera.forward, camera.up)};
  }
};

// render() and bind() under an engine's state that differs from GL's
// defaults in every respect the contract names: render() leaves all of it
// as it was (today's library left its depth framebuffer bound for
// reading, its program, depth state, cull, the generic buffer bindings, a
// 2D-array texture on unit 0 and image unit 0), bind() all but the
// bindings it documents; and the maps are the same as under GL's defaults.
TEST_F(GpuTest, RenderAndBindLeaveTheEnginesStateAsTheyFoundIt) {
  const Casters casters;
  const std::vector<Light> lights = test_lights();
  for (const Config& config : kConfigs) {
    SCOPED_TRACE(config.name);
    ShadowSettings settings =
        settings_for(config.technique, config.filter, config.fused, config.samples);
    if (config.virtual_maps) settings.shadow_maps = ShadowMapKind::Virtual;
    ShadowMaps maps;
    const EngineDepth depth;
    maps.update(lights, test_camera(), casters.geometry(), settings, depth.buffer(test_camera()));
    if (config.virtual_maps) {
      EXPECT_EQ(maps.virtual_light(), 1);
    }

    apply_default_state();
    maps.render(casters.draw());
    const std::vector<float> expected_depth = read_texels(maps.depth_maps(), GL_DEPTH_COMPONENT, 1);
    const bool read_filtered = config.filter == Filter::Gaussian && maps.filtered_maps() != 0;
    const std::vector<float> expected_filtered =
        read_filtered ? read_texels(maps.filtered_maps(), GL_RGBA, 4) : std::vector<float>{};

    // The maps emptied (no casters), so that the render below must draw
    // them again: a render that draws or clears nothing fails. Nothing
    // changed, so each render is told its maps are stale (cached otherwise).
    maps.invalidate();
    maps.render([](const CasterView&) {});
    ASSERT_NE(read_texels(maps.depth_maps(), GL_DEPTH_COMPONENT, 1), expected_depth);

    const EngineState engine;
    engine.apply();
    maps.invalidate();
    const Snapshot before = snapshot();
    maps.render(casters.draw());
    const Snapshot after_render = snapshot();
    EXPECT_EQ(changes(before, after_render), "") << "render() changed the engine's state";
    if (config.virtual_maps) {
      EXPECT_GT(maps.pages_drawn(), 0);
    }

    maps.bind();
    // What bind() documents that it leaves bound: the block, the units the
    // lookup reads and their samplers, PCF's sample set.
    std::set<std::string> bound;
    const ShadowBindings& b = maps.bindings();
    for (const char* field : {" buffer", " start", " size"}) {
      bound.insert("uniform buffer " + std::to_string(b.block) + field);
      bound.insert("uniform buffer " + std::to_string(b.virtual_block) + field);
      bound.insert("storage buffer " + std::to_string(b.poisson_buffer) + field);
    }
    for (unsigned unit : {b.depth_unit, b.filtered_unit, b.compare_unit, b.sat_unit,
                          b.page_table_unit, b.page_pool_unit}) {
      for (auto [pname, name] : kTextureBindings) {
        bound.insert("unit " + std::to_string(unit) + " " + name);
      }
      bound.insert("unit " + std::to_string(unit) + " sampler");
    }
    const Snapshot after_bind = snapshot();
    EXPECT_EQ(changes(before, after_bind, bound), "") << "bind() changed the engine's state";

    // Under the engine's state the maps come out as under GL's defaults.
    apply_default_state();
    EXPECT_EQ(read_texels(maps.depth_maps(), GL_DEPTH_COMPONENT, 1), expected_depth);
    if (read_filtered) {
      EXPECT_EQ(read_texels(maps.filtered_maps(), GL_RGBA, 4), expected_filtered);
    }
  }
  apply_default_state();
}

// An engine's scissor test left on (a UI pass, a split screen) confined
// the maps' clear: whatever the maps held before stayed outside the
// scissor box, and with the casters gone the whole frame was in shadow.
// render() turns the scissor test off: with nothing drawn, every texel of
// every view is cleared to the far end.
TEST_F(GpuTest, ScissorLeftOnDoesNotConfineTheMapsClear) {
  const Casters casters;
  ShadowMaps maps;
  maps.update(test_lights(), test_camera(), casters.geometry(),
              settings_for(Technique::Pcf, Filter::Gaussian, true));
  apply_default_state();
  maps.render(casters.draw());
  const std::vector<float> with_casters = read_texels(maps.depth_maps(), GL_DEPTH_COMPONENT, 1);
  ASSERT_LT(*std::min_element(with_casters.begin(), with_casters.end()), 0.99f);

  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 2, 2);
  maps.invalidate();  // else the unchanged maps are kept, not drawn again
  maps.render([](const CasterView&) {});
  EXPECT_TRUE(glIsEnabled(GL_SCISSOR_TEST));
  glDisable(GL_SCISSOR_TEST);
  const std::vector<float> cleared = read_texels(maps.depth_maps(), GL_DEPTH_COMPONENT, 1);
  const auto not_far =
      std::count_if(cleared.begin(), cleared.end(), [](float z) { return z != 1.0f; });
  EXPECT_EQ(not_far, 0) << "of " << cleared.size() << " texels";
}

// Saving the engine's state costs queries, which can stall a driver that
// runs ahead: render() reads only what the frame's passes change (nothing
// on a cached frame, the compute passes' bindings alone when only the
// filter runs again), and with StateRestore::None nothing at all, the
// maps the same.
TEST_F(GpuTest, RenderReadsOnlyTheStateItChanges) {
  const Casters casters;
  const std::vector<Light> lights = test_lights();
  ShadowSettings settings = settings_for(Technique::Vsm, Filter::Gaussian, false);
  apply_default_state();
  ShadowMaps maps;
  maps.update(lights, test_camera(), casters.geometry(), settings);
  maps.render(casters.draw());
  const int drawn = maps.state_queries();
  maps.update(lights, test_camera(), casters.geometry(), settings);
  maps.render(casters.draw());
  ASSERT_EQ(maps.views_drawn(), 0);
  const int cached = maps.state_queries();
  settings.blur = 3;  // filtered again, nothing drawn
  maps.update(lights, test_camera(), casters.geometry(), settings);
  maps.render(casters.draw());
  ASSERT_EQ(maps.views_drawn(), 0);
  const int filtered = maps.state_queries();
  std::printf("state queries per render(): views drawn %d, filter only %d, cached %d\n", drawn,
              filtered, cached);
  EXPECT_EQ(cached, 0);
  EXPECT_GT(filtered, 0);
  EXPECT_LT(filtered, drawn);

  ShadowMaps promised({}, StateRestore::None);
  promised.update(lights, test_camera(), casters.geometry(), settings);
  promised.render(casters.draw());
  EXPECT_EQ(promised.state_queries(), 0);
  EXPECT_EQ(promised.views_drawn(), maps.view_count());
  EXPECT_EQ(read_texels(promised.depth_maps(), GL_DEPTH_COMPONENT, 1),
            read_texels(maps.depth_maps(), GL_DEPTH_COMPONENT, 1));
  EXPECT_EQ(read_texels(promised.filtered_maps(), GL_RGBA, 4),
            read_texels(maps.filtered_maps(), GL_RGBA, 4));
  apply_default_state();
}

// release() frees every GL object while the context is current; the
// handles it gave out no longer name objects, and the calls that need them
// say so.
TEST_F(GpuTest, ReleaseFreesTheMapsWhileTheContextIsCurrent) {
  const Casters casters;
  ShadowMaps maps;
  maps.update(test_lights(), test_camera(), casters.geometry(),
              settings_for(Technique::Vsm, Filter::Gaussian, true));
  maps.render(casters.draw());
  const GLuint depth = maps.depth_maps(), filtered = maps.filtered_maps();
  ASSERT_TRUE(glIsTexture(depth));
  ASSERT_TRUE(glIsTexture(filtered));
  maps.release();
  EXPECT_FALSE(glIsTexture(depth));
  EXPECT_FALSE(glIsTexture(filtered));
  EXPECT_THROW(maps.render(casters.draw()), std::logic_error);
  EXPECT_THROW(maps.bind(), std::logic_error);
  EXPECT_THROW((void)maps.depth_maps(), std::logic_error);
  maps.release();  // twice: nothing left to free
}

// The engine destroys its context, then ShadowMaps (a tutorial's main ends
// with glfwTerminate(), its objects' destructors run after it): the
// destructor calls no GL (libepoxy aborted: exit 134). Likewise a
// ShadowMaps released while the context was current. Each in a process of
// its own, whose GL functions libepoxy has not resolved yet.
void destroy_after_the_context(bool release_first) {
  std::unique_ptr<gl::Context> context = gl::Context::create_headless({.debug = false});
  const Casters casters;
  auto maps = std::make_unique<ShadowMaps>();
  maps->update(test_lights(), test_camera(), casters.geometry(),
               settings_for(Technique::Msm, Filter::Sat, true));
  maps->render(casters.draw());
  maps->bind();
  if (release_first) maps->release();
  // The casters' own buffers go with the context too.
  context.reset();
  maps.reset();
  std::_Exit(0);
}

TEST(ShadowMapsDestruction, DestructorWithoutAContextCallsNoGl) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(destroy_after_the_context(false), ::testing::ExitedWithCode(0), "");
  EXPECT_EXIT(destroy_after_the_context(true), ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace penumbra
