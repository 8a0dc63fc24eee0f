// The lookup as an engine uses it (penumbra/shadow_maps.hpp): compiled
// inside an engine's shader that declares the names the lookup's own
// shaders use, with the engine's line numbers kept; and ShadowMaps with
// every binding point moved, drawing the same shadows as with the defaults.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "gpu_fixture.hpp"
#include "io/image.hpp"
#include "penumbra/error.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/shadow_maps.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

struct Compiled {
  bool ok = false;
  std::string log;
};

Compiled compile(GLenum stage, const std::string& source) {
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE, length = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  glDeleteShader(shader);
  return {ok == GL_TRUE, log.c_str()};
}

// An engine's fragment shader (its lines 2 on) that declares what the
// lookup's own shaders declare: MAX_LIGHTS (as a macro, or with
// `constant` a const int), a struct GpuLight, functions shadow_bias and
// cube_face, a block PoissonSamples and a global poisson_samples. Line 14
// holds `error_line`, empty or an error of the engine's own.
std::string engine_fragment_body(bool constant, const std::string& error_line) {
  return std::string(constant ? "const int MAX_LIGHTS = 8;\n" : "#define MAX_LIGHTS 8\n") +  // 2
         "struct GpuLight { vec4 position; vec4 color; };\n"                                 // 3
         "layout(std140, binding = 1) uniform EngineLights { GpuLight lights[MAX_LIGHTS]; };\n"
         "layout(std430, binding = 0) readonly buffer PoissonSamples { vec2 disc[]; };\n"  // 5
         "vec2 poisson_samples[4];\n"                                                      // 6
         "float shadow_bias(float cos_theta) { return 0.001 * cos_theta; }\n"              // 7
         "int cube_face(vec3 d) { return d.x > 0.0 ? 0 : 1; }\n"                           // 8
         "in vec3 v_world;\n"                                                              // 9
         "layout(location = 0) out vec4 out_color;\n"                                      // 10
         "void main() {\n"                                                                 // 11
         "  float lit = penumbra_shadow(0, v_world, vec3(0.0, 1.0, 0.0));\n"               // 12
         "  float bias = shadow_bias(lit) + float(cube_face(v_world)) + disc[0].x;\n"      // 13
         + error_line + "\n" +                                                             // 14
         "  out_color = lights[0].color * lit + vec4(bias);\n"                             // 15
         "}\n";
}

const std::string kEngineVertex =
    "#version 450 core\n"
    "layout(location = 0) in vec3 in_position;\n"
    "out vec3 v_world;\n"
    "void main() { v_world = in_position; gl_Position = vec4(in_position, 1.0); }\n";

// The engine's shader with the lookup pasted after its #version line (the
// documented way: the lookup ends in "#line 2"), or inserted by
// insert_shadow_lookup() after the #version and #extension lines.
std::string engine_fragment(bool constant, bool inserted, const std::string& error_line) {
  if (!inserted) {
    return "#version 450 core\n" + shadow_lookup_glsl() +
           engine_fragment_body(constant, error_line);
  }
  // Two lines more before the body: the body's line 14 is the shader's 16.
  return insert_shadow_lookup(
      "#version 450 core\n#extension GL_ARB_gpu_shader5 : enable\n"
      "// the engine's own comment\n" +
      engine_fragment_body(constant, error_line));
}

TEST_F(GpuTest, ShadowLookupKeepsToItsNamespaceInAnEngineShader) {
  // (Each way of inserting it once: the lookup is long to compile here.)
  for (bool constant : {false, true}) {
    const bool inserted = constant;
    SCOPED_TRACE(std::string(constant ? "const int" : "#define") + " MAX_LIGHTS, " +
                 (inserted ? "insert_shadow_lookup()" : "pasted after #version"));
    std::string log;
    const GLuint program =
        testing::link_program(kEngineVertex, engine_fragment(constant, inserted, ""), log);
    EXPECT_NE(program, 0u) << log;
    glDeleteProgram(program);
  }
}

// An error on the engine's line 14 is reported on line 14 (Mesa's info log:
// "0:14(col): error: ..."), however long the lookup before it.
TEST_F(GpuTest, ShadowLookupKeepsTheEngineLineNumbers) {
  for (bool inserted : {false, true}) {
    SCOPED_TRACE(inserted ? "insert_shadow_lookup()" : "pasted after #version");
    const Compiled compiled =
        compile(GL_FRAGMENT_SHADER,
                engine_fragment(false, inserted, "  lit += engine_name_nobody_declared;"));
    // The driver's debug output counts the failed compile as an error:
    // expected here, so the fixture's check starts again after it.
    SetUp();
    ASSERT_FALSE(compiled.ok);
    const std::string line = inserted ? "16" : "14";
    EXPECT_NE(compiled.log.find("0:" + line + "("), std::string::npos) << compiled.log;
    EXPECT_NE(compiled.log.find("engine_name_nobody_declared"), std::string::npos) << compiled.log;
    // Every error is the engine's, on that line: nothing of the lookup's
    // own collides with the engine's names.
    std::istringstream lines(compiled.log);
    for (std::string text; std::getline(lines, text);) {
      if (text.find("error") != std::string::npos) {
        EXPECT_TRUE(text.starts_with("0:" + line + "(")) << compiled.log;
      }
    }
  }
}

// --- bindings ----------------------------------------------------------------

// A ground quad and a box on it, flat normals per face; the casters are
// the same triangles.
struct GroundAndBox : testing::EngineMesh {
  GroundAndBox() {
    quad({-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5});
    box({-0.8f, 0.0f, -0.8f}, {0.8f, 1.6f, 0.8f});
  }
};

const std::string kSceneFragment =
    "in vec3 v_world;\n"
    "in vec3 v_normal;\n"
    "layout(location = 0) out vec4 out_lit;\n"
    "void main() { out_lit = vec4(penumbra_shadow(0, v_world, normalize(v_normal))); }\n";

constexpr int kSize = 96;

// An engine's frame around ShadowMaps at `bindings`: its scene drawn from
// above with its own shader, which writes the lookup's shadow factor.
class EngineFrame {
 public:
  explicit EngineFrame(const ShadowBindings& bindings, const std::string& fragment = kSceneFragment)
      : bindings_(bindings), maps_(bindings) {
    glVertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, 6 * sizeof(float));
    glVertexArrayElementBuffer(vao_.id(), indices_.id());
    for (GLuint attribute : {0u, 1u}) {
      glEnableVertexArrayAttrib(vao_.id(), attribute);
      glVertexArrayAttribFormat(vao_.id(), attribute, 3, GL_FLOAT, GL_FALSE,
                                attribute * 3 * sizeof(float));
      glVertexArrayAttribBinding(vao_.id(), attribute, 0);
    }
    std::string log;
    program_ = testing::link_program(
        testing::kEngineSceneVertex,
        insert_shadow_lookup("#version 450 core\n" + fragment, bindings), log);
    EXPECT_NE(program_, 0u) << log;
    framebuffer_.attach_color(0, color_);
    framebuffer_.attach_depth(depth_);
    framebuffer_.set_draw_buffers(1);
    framebuffer_.check_complete();
  }
  ~EngineFrame() { glDeleteProgram(program_); }
  EngineFrame(const EngineFrame&) = delete;
  EngineFrame& operator=(const EngineFrame&) = delete;

  // The shadow factor per pixel (-1 where no surface is), with every
  // default binding point holding something else than the maps.
  std::vector<float> draw(const ShadowSettings& settings) {
    const Light light{.type = LightType::Spot,
                      .position = {3.0f, 7.0f, 2.0f},
                      .direction = glm::normalize(glm::vec3(-3.0f, -7.0f, -2.0f)),
                      .cone_degrees = 40.0f};
    const glm::vec3 eye(0.0f, 9.0f, 0.01f);
    const CameraFrustum camera{.position = eye,
                               .forward = glm::normalize(-eye),
                               .up = {0.0f, 0.0f, -1.0f},
                               .near_plane = 1.0f,
                               .far_plane = 20.0f};
    maps_.update(std::span(&light, 1), camera,
                 {.positions = scene_.positions, .indices = scene_.indices}, settings);
    maps_.render([&](const CasterView&) { draw_scene(); });
    maps_.bind();
    // What an engine might keep at the default binding points: a block of
    // zeros (no lights: everything lit), no textures, no samples.
    const ShadowBindings defaults;
    if (bindings_.block != defaults.block) {
      glBindBufferBase(GL_UNIFORM_BUFFER, defaults.block, decoy_.id());
    }
    if (bindings_.poisson_buffer != defaults.poisson_buffer) {
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, defaults.poisson_buffer, decoy_.id());
    }
    for (unsigned unit :
         {defaults.depth_unit, defaults.compare_unit, defaults.filtered_unit, defaults.sat_unit}) {
      if (unit != bindings_.depth_unit && unit != bindings_.compare_unit &&
          unit != bindings_.filtered_unit && unit != bindings_.sat_unit) {
        glBindTextureUnit(unit, 0);
        glBindSampler(unit, 0);
      }
    }

    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, kSize, kSize);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    const float clear_lit = -1.0f, clear_depth = 1.0f;
    glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, &clear_lit);
    glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &clear_depth);
    glUseProgram(program_);
    const glm::mat4 view_projection =
        glm::perspective(glm::radians(60.0f), 1.0f, camera.near_plane, camera.far_plane) *
        glm::lookAt(eye, glm::vec3(0.0f), camera.up);
    glUniformMatrix4fv(0, 1, GL_FALSE, &view_projection[0][0]);
    draw_scene();
    glUseProgram(0);
    glBindVertexArray(0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);

    std::vector<float> lit(static_cast<std::size_t>(kSize) * kSize);
    glGetTextureImage(color_.id(), 0, GL_RED, GL_FLOAT,
                      static_cast<GLsizei>(lit.size() * sizeof(float)), lit.data());
    return lit;
  }

 private:
  void draw_scene() const {
    glBindVertexArray(vao_.id());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(scene_.indices.size()), GL_UNSIGNED_INT,
                   nullptr);
  }

  ShadowBindings bindings_;
  ShadowMaps maps_;
  GroundAndBox scene_;
  gl::Buffer vertices_ = gl::Buffer::from(std::span<const float>(scene_.vertices), "test vertices");
  gl::Buffer indices_ =
      gl::Buffer::from(std::span<const std::uint32_t>(scene_.indices), "test indices");
  gl::VertexArray vao_{"test scene"};
  GLuint program_ = 0;
  gl::Texture color_{
      gl::TextureInfo{.format = GL_R32F, .width = kSize, .height = kSize, .label = "test lit"}};
  gl::Texture depth_{gl::TextureInfo{
      .format = GL_DEPTH_COMPONENT32F, .width = kSize, .height = kSize, .label = "test depth"}};
  gl::Framebuffer framebuffer_{"test framebuffer"};
  std::vector<std::byte> zeros_ = std::vector<std::byte>(sizeof(ShadowBlock));
  gl::Buffer decoy_{zeros_.size(), zeros_.data(), false, "test decoy"};
};

// Writes a shadow-factor image under the test output folder, for looking at.
void save(const std::vector<float>& lit, const std::string& name) {
  Image image(kSize, kSize);
  for (std::size_t i = 0; i < lit.size(); ++i) {
    for (int c = 0; c < 3; ++c) image.rgba[4 * i + c] = std::max(lit[i], 0.0f);
    image.rgba[4 * i + 3] = 1.0f;
  }
  const std::filesystem::path dir = std::filesystem::path(PENUMBRA_TEST_OUTPUT) / "shadow_lookup";
  std::filesystem::create_directories(dir);
  write_png(image, (dir / (name + ".png")).string(), PngEncoding::Linear);
}

// Every binding point moved (none where a default was): the same shadows
// as with the defaults, for every family of techniques: the depth tests
// (depth unit), PCF and PCSS (the comparison unit, the sample set), the
// Gaussian-filtered moments (the filtered unit) and the moments' soft
// shadows from summed-area tables (the SAT unit and the depth unit), all
// through the block. (One case per family: llvmpipe compiles the lookup
// again for each new set of textures, seconds each.)
TEST_F(GpuTest, ShadowMapsDrawTheSameShadowsAtBindingsTheEngineChose) {
  const ShadowBindings moved{.block = 3,
                             .depth_unit = 2,
                             .filtered_unit = 5,
                             .compare_unit = 6,
                             .sat_unit = 9,
                             .poisson_buffer = 5};
  EngineFrame engine_default({});
  EngineFrame engine_moved(moved);
  struct Case {
    const char* name;
    Technique technique;
    Filter filter;
    bool soft;
  };
  for (const Case& c : {Case{"hard", Technique::Hard, Filter::Gaussian, false},
                        Case{"pcf", Technique::Pcf, Filter::Gaussian, false},
                        Case{"pcss", Technique::Pcss, Filter::Gaussian, false},
                        Case{"vsm", Technique::Vsm, Filter::Gaussian, false},
                        Case{"msm-sat-soft", Technique::Msm, Filter::Sat, true}}) {
    SCOPED_TRACE(c.name);
    ShadowSettings settings;
    settings.technique = c.technique;
    settings.filter = c.filter;
    settings.soft = c.soft;
    settings.map_size = 256;
    const std::vector<float> expected = engine_default.draw(settings);
    const std::vector<float> actual = engine_moved.draw(settings);
    save(expected, std::string(c.name) + "-default");
    save(actual, std::string(c.name) + "-moved");
    // The default image shows the box's shadow on lit ground.
    const auto shadowed = std::count_if(expected.begin(), expected.end(),
                                        [](float v) { return v >= 0.0f && v < 0.2f; });
    const auto lit =
        std::count_if(expected.begin(), expected.end(), [](float v) { return v > 0.8f; });
    EXPECT_GT(shadowed, kSize * kSize / 50);
    EXPECT_GT(lit, kSize * kSize / 2);
    float worst = 0.0f;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      worst = std::max(worst, std::abs(expected[i] - actual[i]));
    }
    EXPECT_LT(worst, 1e-4f);
  }
}

// The entry point with a shading normal: backprojection weighs its source
// above that normal's horizon, as penumbra's renderer does on smooth-shaded
// meshes. Given the surface's own normal twice it draws what the
// three-argument form draws; given a normal tilted so that its horizon
// crosses the light's source, the penumbrae change (their lit part is the
// part of the source above the horizon that the casters leave) and the
// fully lit and fully shadowed pixels do not.
TEST_F(GpuTest, ShadowLookupWeighsBackprojectionsSourceAboveTheShadingNormalsHorizon) {
  auto fragment = [](const std::string& shading) {
    return "in vec3 v_world;\n"
           "in vec3 v_normal;\n"
           "layout(location = 0) out vec4 out_lit;\n"
           "void main() {\n"
           "  vec3 n = normalize(v_normal);\n"
           "  out_lit = vec4(penumbra_shadow(0, v_world, n, " +
           shading +
           "));\n"
           "}\n";
  };
  ShadowSettings settings;
  settings.technique = Technique::Backprojection;
  settings.map_size = 256;
  settings.light_size = 1.5f;
  const std::vector<float> own = EngineFrame({}).draw(settings);
  const std::vector<float> twice = EngineFrame({}, fragment("n")).draw(settings);
  // Square to the direction towards the spot light (from the ground's
  // middle towards (3, 7, 2)), and up.
  const std::vector<float> tilted =
      EngineFrame({}, fragment("normalize(vec3(-0.88, 0.38, 0.0))")).draw(settings);
  save(own, "backprojection-own-normal");
  save(tilted, "backprojection-tilted-shading-normal");
  int penumbra = 0, settled = 0;
  double moved = 0.0;
  float settled_worst = 0.0f, twice_worst = 0.0f;
  for (std::size_t i = 0; i < own.size(); ++i) {
    twice_worst = std::max(twice_worst, std::abs(twice[i] - own[i]));
    if (own[i] < 0.0f) continue;  // no surface
    if (own[i] > 0.05f && own[i] < 0.95f) {
      ++penumbra;
      moved += std::abs(tilted[i] - own[i]);
    } else if (own[i] == 0.0f || own[i] == 1.0f) {
      ++settled;
      settled_worst = std::max(settled_worst, std::abs(tilted[i] - own[i]));
    }
  }
  std::printf("penumbra pixels %d: mean change %.3f; lit and umbra pixels %d: largest %.4f\n",
              penumbra, penumbra ? moved / penumbra : 0.0, settled, settled_worst);
  EXPECT_EQ(twice_worst, 0.0f);
  ASSERT_GT(penumbra, 50);
  EXPECT_GT(moved / penumbra, 0.05);
  EXPECT_GT(settled, kSize * kSize / 2);
  EXPECT_EQ(settled_worst, 0.0f);
}

TEST_F(GpuTest, ShadowMapsRefuseBindingsThatCoincideOrPassTheLimits) {
  EXPECT_THROW(ShadowMaps(ShadowBindings{.depth_unit = 4, .compare_unit = 4}), UsageError);
  EXPECT_THROW(ShadowMaps(ShadowBindings{.sat_unit = 100000}), UsageError);
  EXPECT_THROW(ShadowMaps(ShadowBindings{.block = 100000}), UsageError);
  EXPECT_THROW(ShadowMaps(ShadowBindings{.poisson_buffer = 100000}), UsageError);
}

}  // namespace
}  // namespace penumbra
