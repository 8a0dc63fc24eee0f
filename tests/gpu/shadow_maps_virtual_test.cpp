// Virtual shadow maps through the public API, as an engine embeds them
// (include/penumbra/shadow_maps.hpp, ShadowMapKind::Virtual): the engine
// draws its depth, ShadowMaps marks the pages from it and draws the
// engine's casters into them through the callback, and the engine's own
// shader reads the shadow through the emitted lookup (prefixed names,
// the page table at the engine's bindings). The shadow agrees with
// cascades'; pages the camera still reads are cached.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
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

constexpr int kSize = 128;

const std::string kFragment =
    "#version 450 core\n"
    "in vec3 v_world;\n"
    "in vec3 v_normal;\n"
    "layout(location = 0) out vec4 out_lit;\n"
    "void main() { out_lit = vec4(penumbra_shadow(0, v_world, normalize(v_normal))); }\n";

// A 24 x 24 ground and three boxes on it, flat normals per face; the
// casters are the same triangles.
struct GroundAndBoxes : testing::EngineMesh {
  GroundAndBoxes() {
    quad({-12, 0, 12}, {12, 0, 12}, {12, 0, -12}, {-12, 0, -12});
    box({-1.0f, 0.0f, -1.0f}, {1.0f, 2.0f, 1.0f});
    box({2.0f, 0.0f, -3.0f}, {3.0f, 3.0f, -2.0f});
    box({-3.0f, 0.0f, 1.5f}, {-2.5f, 1.0f, 2.0f});
  }
};

// The engine: its scene, its depth and colour targets, its own shader with
// the lookup inserted; a frame draws the depth, the shadow maps, then the
// shadow factor per pixel (-1 where no surface is).
class VirtualMapsEngine {
 public:
  VirtualMapsEngine() {
    glVertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, 6 * sizeof(float));
    glVertexArrayElementBuffer(vao_.id(), indices_.id());
    for (GLuint attribute : {0u, 1u}) {
      glEnableVertexArrayAttrib(vao_.id(), attribute);
      glVertexArrayAttribFormat(vao_.id(), attribute, 3, GL_FLOAT, GL_FALSE,
                                attribute * 3 * sizeof(float));
      glVertexArrayAttribBinding(vao_.id(), attribute, 0);
    }
    std::string log;
    program_ =
        testing::link_program(testing::kEngineSceneVertex, insert_shadow_lookup(kFragment), log);
    EXPECT_NE(program_, 0u) << log;
    framebuffer_.attach_color(0, color_);
    framebuffer_.attach_depth(depth_);
    framebuffer_.set_draw_buffers(1);
    framebuffer_.check_complete();
  }
  ~VirtualMapsEngine() { glDeleteProgram(program_); }
  VirtualMapsEngine(const VirtualMapsEngine&) = delete;
  VirtualMapsEngine& operator=(const VirtualMapsEngine&) = delete;

  std::vector<float> frame(ShadowMaps& maps, const ShadowMapSettings& settings) {
    const glm::vec3 eye(0.0f, 6.0f, 8.0f);
    const CameraFrustum camera{.position = eye,
                               .forward = glm::normalize(-eye),
                               .up = {0.0f, 1.0f, 0.0f},
                               .fov_y = glm::radians(50.0f),
                               .aspect = 1.0f,
                               .near_plane = 1.0f,
                               .far_plane = 40.0f};
    const glm::mat4 view_projection =
        glm::perspective(camera.fov_y, 1.0f, camera.near_plane, camera.far_plane) *
        glm::lookAt(eye, glm::vec3(0.0f), camera.up);
    // The engine's depth (its own pass; here the lit pass's depth, with
    // the maps of an earlier frame read into a colour nobody looks at).
    draw_camera(view_projection);
    const Light sun{.type = LightType::Directional,
                    .direction = glm::normalize(glm::vec3(-1.0f, -1.0f, 0.6f)),
                    .sun_angle = 0.0f};
    const CameraDepthBuffer depth{.texture = depth_.id(),
                                  .width = kSize,
                                  .height = kSize,
                                  .view_projection = view_projection,
                                  .clip_depth = ClipDepth::NegativeOneToOne,
                                  .background_depth = 1.0f};
    maps.update(std::span(&sun, 1), camera,
                {.positions = scene_.positions, .indices = scene_.indices}, settings, depth);
    maps.render([&](const CasterView&) { draw_scene(); });
    maps.bind();
    draw_camera(view_projection);
    std::vector<float> lit(static_cast<std::size_t>(kSize) * kSize);
    glGetTextureImage(color_.id(), 0, GL_RED, GL_FLOAT,
                      static_cast<GLsizei>(lit.size() * sizeof(float)), lit.data());
    return lit;
  }

 private:
  void draw_camera(const glm::mat4& view_projection) {
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
    glUniformMatrix4fv(0, 1, GL_FALSE, &view_projection[0][0]);
    draw_scene();
    glUseProgram(0);
    glBindVertexArray(0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  }
  void draw_scene() const {
    glBindVertexArray(vao_.id());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(scene_.indices.size()), GL_UNSIGNED_INT,
                   nullptr);
  }

  GroundAndBoxes scene_;
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
};

// A shadow-factor image under the test output folder, for looking at.
void save(const std::vector<float>& lit, const std::string& name) {
  Image image(kSize, kSize);
  for (std::size_t i = 0; i < lit.size(); ++i) {
    for (int c = 0; c < 3; ++c) image.rgba[4 * i + c] = std::max(lit[i], 0.0f);
    image.rgba[4 * i + 3] = 1.0f;
  }
  const std::filesystem::path dir =
      std::filesystem::path(PENUMBRA_TEST_OUTPUT) / "shadow_maps_virtual";
  std::filesystem::create_directories(dir);
  write_png(image, (dir / (name + ".png")).string(), PngEncoding::Linear);
}

ShadowMapSettings hard_settings(ShadowMapKind kind) {
  ShadowMapSettings s;
  s.technique = Technique::Hard;
  s.map_size = 1024;
  s.shadow_maps = kind;
  s.page_pool_mib = 16;
  return s;
}

TEST_F(GpuTest, EngineVirtualShadowMapsAgreeWithCascades) {
  VirtualMapsEngine engine;
  ShadowMaps cascaded;
  const std::vector<float> cascades =
      engine.frame(cascaded, hard_settings(ShadowMapKind::Cascades));
  EXPECT_EQ(cascaded.virtual_light(), -1);
  EXPECT_EQ(cascaded.pages_drawn(), 0);

  ShadowMaps maps;
  const std::vector<float> first = engine.frame(maps, hard_settings(ShadowMapKind::Virtual));
  EXPECT_EQ(maps.virtual_light(), 0);
  // The sun's cascades are not drawn: its pages are.
  EXPECT_EQ(maps.views_drawn(), 0);
  const int pages = maps.pages_drawn();
  EXPECT_GT(pages, 0);
  EXPECT_EQ(maps.pages_resident(), pages);

  int seen = 0, agree = 0, shadowed = 0;
  for (std::size_t i = 0; i < first.size(); ++i) {
    if (cascades[i] < 0.0f) continue;
    ++seen;
    agree += std::abs(first[i] - cascades[i]) < 0.5f ? 1 : 0;
    shadowed += first[i] < 0.5f ? 1 : 0;
  }
  ASSERT_GT(seen, kSize * kSize / 2);
  // The boxes' shadows on the ground and their own unlit sides.
  EXPECT_GT(shadowed, seen / 20) << shadowed << " of " << seen << " pixels shadowed";
  save(first, "virtual");
  save(cascades, "cascades");
  EXPECT_GE(agree, seen * 99 / 100) << agree << " of " << seen << " pixels agree";

  // The same camera again: every page it reads is cached, the same image.
  const std::vector<float> second = engine.frame(maps, hard_settings(ShadowMapKind::Virtual));
  EXPECT_EQ(maps.pages_drawn(), 0);
  EXPECT_EQ(maps.pages_resident(), pages);
  EXPECT_EQ(second, first);
}

TEST_F(GpuTest, VirtualShadowMapsNeedTheCamerasDepthBuffer) {
  ShadowMaps maps;
  const Light sun{.type = LightType::Directional, .direction = {0.0f, -1.0f, 0.0f}};
  const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
  const std::vector<std::uint32_t> indices = {0, 1, 2};
  EXPECT_THROW(
      maps.update(std::span(&sun, 1), CameraFrustum{}, {.positions = positions, .indices = indices},
                  hard_settings(ShadowMapKind::Virtual)),
      UsageError);
}

}  // namespace
}  // namespace penumbra
