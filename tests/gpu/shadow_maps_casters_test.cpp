// ShadowMaps as an engine drives it (include/penumbra/shadow_maps.hpp):
// casters placed by the model matrix, refits when the casters change, and
// maps cached across frames (a view drawn again only when its light, its
// fit or a caster it sees changed), identical to maps drawn anew.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <set>
#include <string>
#include <vector>

#include "gpu_fixture.hpp"
#include "penumbra/error.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/shadow_maps.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;
using Mesh = testing::PositionMesh;

// The twelve triangles of the box lo..hi.
std::vector<glm::vec3> box_triangles(const glm::vec3& lo, const glm::vec3& hi) {
  std::vector<glm::vec3> corners;
  for (int c = 0; c < 8; ++c) {
    corners.emplace_back((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
  }
  const int faces[36] = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                         2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  std::vector<glm::vec3> triangles;
  for (int corner : faces) triangles.push_back(corners[static_cast<std::size_t>(corner)]);
  return triangles;
}

CasterBounds unit_box_at(const glm::vec3& centre) {
  return {centre - glm::vec3(0.5f), centre + glm::vec3(0.5f)};
}

// Two spot lights looking straight down, 20 units apart, over a ground
// (the box -12..32 x -12..12, 0.1 thick), and a few unit boxes placed by
// their model matrices.
struct TwoSpotLightsScene {
  std::vector<Light> lights;
  CameraFrustum camera;
  ShadowSettings settings;
  std::vector<glm::vec3> box_centres;
  CasterBounds ground{{-12.0f, -0.1f, -12.0f}, {32.0f, 0.0f, 12.0f}};

  TwoSpotLightsScene() {
    for (float x : {0.0f, 20.0f}) {
      Light spot;
      spot.position = {x, 10.0f, 0.0f};
      spot.direction = {0.0f, -1.0f, 0.0f};
      spot.cone_degrees = 30.0f;
      lights.push_back(spot);
    }
    camera.position = {10.0f, 12.0f, 20.0f};
    camera.forward = glm::normalize(glm::vec3(0.0f, -0.5f, -1.0f));
    settings.map_size = 64;
    box_centres = {{0.0f, 1.0f, 0.0f}, {1.5f, 0.5f, 1.0f}, {20.0f, 1.0f, 0.5f}};
  }
  [[nodiscard]] std::vector<CasterBounds> bounds() const {
    std::vector<CasterBounds> b = {ground};
    for (const glm::vec3& c : box_centres) b.push_back(unit_box_at(c));
    return b;
  }
};

// The engine's side: a ground mesh and a unit box drawn per object with
// set_model(); counts the views drawn.
class Engine {
 public:
  Engine()
      : ground_(box_triangles(glm::vec3(0.0f), glm::vec3(1.0f))),
        box_(box_triangles(glm::vec3(-0.5f), glm::vec3(0.5f))) {}

  void frame(ShadowMaps& maps, const TwoSpotLightsScene& scene) {
    maps.update(scene.lights, scene.camera, std::span<const CasterBounds>(scene.bounds()),
                scene.settings);
    drawn.clear();
    maps.render([&](const CasterView& view) {
      drawn.insert(view.index);
      const glm::vec3 size = scene.ground.max - scene.ground.min;
      view.set_model(glm::scale(glm::translate(glm::mat4(1.0f), scene.ground.min), size));
      ground_.draw();
      for (const glm::vec3& c : scene.box_centres) {
        view.set_model(glm::translate(glm::mat4(1.0f), c));
        box_.draw();
      }
    });
  }
  std::set<int> drawn;

 private:
  Mesh ground_, box_;
};

// Every layer of a texture array, as floats (channels per texel).
std::vector<float> read_layers(GLuint texture, GLenum format, int channels) {
  GLint width = 0, height = 0, layers = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &width);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &height);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_DEPTH, &layers);
  std::vector<float> texels(static_cast<std::size_t>(width) * height * layers * channels);
  glGetTextureImage(texture, 0, format, GL_FLOAT, static_cast<GLsizei>(texels.size() * 4),
                    texels.data());
  return texels;
}

std::vector<float> depths(const ShadowMaps& maps) {
  return read_layers(maps.depth_maps(), GL_DEPTH_COMPONENT, 1);
}

TEST_F(GpuTest, CasterModelMatrixPlacesObjectsBySetModelAndByName) {
  TwoSpotLightsScene scene;
  scene.box_centres = {{2.0f, 2.0f, 0.0f}};
  Mesh ground(box_triangles(scene.ground.min, scene.ground.max));
  Mesh box(box_triangles(glm::vec3(-0.5f), glm::vec3(0.5f)));
  auto render = [&](auto place) {
    ShadowMaps maps;
    maps.update(scene.lights, scene.camera, std::span<const CasterBounds>(scene.bounds()),
                scene.settings);
    maps.render([&](const CasterView& view) {
      ground.draw();
      place(view);
      box.draw();
    });
    return depths(maps);
  };
  const glm::mat4 model = glm::translate(glm::mat4(1.0f), scene.box_centres[0]);
  const std::vector<float> unplaced = render([](const CasterView&) {});
  const std::vector<float> by_method = render([&](const CasterView& v) { v.set_model(model); });
  // As an engine's own depth pass sets its "model" uniform.
  const std::vector<float> by_name = render([&](const CasterView& v) {
    glUniformMatrix4fv(glGetUniformLocation(v.program, "model"), 1, GL_FALSE, &model[0][0]);
  });
  EXPECT_NE(by_method, unplaced) << "set_model() did not move the box";
  EXPECT_EQ(by_name, by_method) << "\"model\" set by name does not place the box";

  // The box over the first light's axis, 2 above the ground: its texels
  // there are nearer the light than the ground's.
  const int size = scene.settings.map_size;
  const std::size_t centre = static_cast<std::size_t>(size / 2) * size + size / 2;
  const std::vector<float> ground_only = render([&](const CasterView& v) {
    v.set_model(glm::translate(glm::mat4(1.0f), glm::vec3(100.0f, 0.0f, 0.0f)));
  });
  scene.box_centres = {{0.0f, 2.0f, 0.0f}};
  const std::vector<float> centred = render([&](const CasterView& v) {
    v.set_model(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 2.0f, 0.0f)));
  });
  EXPECT_LT(centred[centre] + 0.05f, ground_only[centre]);
}

// Failure 5 of issue 30: casters grown from y <= 2 to y <= 12 in the
// engine's own arrays must change the fitted depth range as a fresh
// ShadowMaps fits it.
TEST_F(GpuTest, UpdateRefitsWhenTheCastersChange) {
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  CameraFrustum camera;
  camera.position = {0.0f, 4.0f, 12.0f};
  camera.forward = glm::normalize(glm::vec3(0.0f, -0.3f, -1.0f));
  camera.far_plane = 40.0f;
  ShadowSettings settings;
  settings.map_size = 64;
  std::vector<glm::vec3> positions = box_triangles({-10.0f, 0.0f, -10.0f}, {10.0f, 2.0f, 10.0f});
  std::vector<std::uint32_t> indices(positions.size());
  for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<std::uint32_t>(i);
  const std::vector<Light> lights = {sun};

  ShadowMaps maps;
  maps.update(lights, camera, {positions, indices}, settings);
  const float low_z0 = maps.block().views[0].depth_range.x;
  for (glm::vec3& p : positions) p.y = p.y > 1.0f ? 12.0f : p.y;
  maps.update(lights, camera, {positions, indices}, settings);
  ShadowMaps fresh;
  fresh.update(lights, camera, {positions, indices}, settings);
  const float fresh_z0 = fresh.block().views[0].depth_range.x;
  EXPECT_NE(fresh_z0, low_z0) << "the test's casters no longer change the fit";
  EXPECT_EQ(maps.block().views[0].depth_range, fresh.block().views[0].depth_range);
  EXPECT_EQ(maps.block().views[0].view_projection, fresh.block().views[0].view_projection);

  // The same through bounding boxes.
  std::vector<CasterBounds> boxes = {{{-10.0f, 0.0f, -10.0f}, {10.0f, 2.0f, 10.0f}}};
  maps.update(lights, camera, std::span<const CasterBounds>(boxes), settings);
  EXPECT_NEAR(maps.block().views[0].depth_range.x, low_z0, 1e-4f);
  boxes[0].max.y = 12.0f;
  maps.update(lights, camera, std::span<const CasterBounds>(boxes), settings);
  EXPECT_NEAR(maps.block().views[0].depth_range.x, fresh_z0, 1e-4f);
  EXPECT_NEAR(maps.block().views[0].depth_range.y, fresh.block().views[0].depth_range.y, 1e-4f);
}

// With a generation the engine bumps, update() refits when the generation
// changes and only then: it reads no vertex (an engine that changes its
// arrays without bumping it keeps the old fit), and a bumped generation
// refits as a fresh ShadowMaps fits.
TEST_F(GpuTest, UpdateRefitsWhenTheEngineBumpsTheGeneration) {
  TwoSpotLightsScene scene;
  std::vector<glm::vec3> positions = box_triangles({-10.0f, 0.0f, -10.0f}, {30.0f, 2.0f, 10.0f});
  std::vector<std::uint32_t> indices(positions.size());
  for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<std::uint32_t>(i);
  const auto geometry = [&](std::uint64_t generation) {
    return CasterGeometry{.positions = positions, .indices = indices, .generation = generation};
  };
  const auto draw = [](const CasterView&) {};
  ShadowMaps maps;
  maps.update(scene.lights, scene.camera, geometry(1), scene.settings);
  maps.render(draw);
  const glm::vec4 low = maps.block().views[0].depth_range;
  maps.update(scene.lights, scene.camera, geometry(1), scene.settings);
  maps.render(draw);
  EXPECT_EQ(maps.views_drawn(), 0);

  for (glm::vec3& p : positions) p.y = p.y > 1.0f ? 8.0f : p.y;
  // Not bumped: the arrays are not read, the fit stays.
  maps.update(scene.lights, scene.camera, geometry(1), scene.settings);
  maps.render(draw);
  EXPECT_EQ(maps.views_drawn(), 0);
  EXPECT_EQ(maps.block().views[0].depth_range, low);
  // Bumped: refitted as anew, every view drawn.
  maps.update(scene.lights, scene.camera, geometry(2), scene.settings);
  maps.render(draw);
  EXPECT_EQ(maps.views_drawn(), 2);
  ShadowMaps fresh;
  fresh.update(scene.lights, scene.camera, {positions, indices}, scene.settings);
  EXPECT_NE(fresh.block().views[0].depth_range, low)
      << "the test's casters no longer change the fit";
  EXPECT_EQ(maps.block().views[0].depth_range, fresh.block().views[0].depth_range);
  // From a generation to the hash (none given) and back: each switch
  // refits and draws anew; the hash then keeps the maps while nothing moves.
  maps.update(scene.lights, scene.camera, {positions, indices}, scene.settings);
  maps.render(draw);
  EXPECT_EQ(maps.views_drawn(), 2);
  maps.update(scene.lights, scene.camera, {positions, indices}, scene.settings);
  maps.render(draw);
  EXPECT_EQ(maps.views_drawn(), 0);
  maps.update(scene.lights, scene.camera, geometry(2), scene.settings);
  maps.render(draw);
  EXPECT_EQ(maps.views_drawn(), 2);
}

TEST_F(GpuTest, StaticFrameDrawsNoViewAndInvalidateDrawsThemAll) {
  TwoSpotLightsScene scene;
  ShadowMaps maps;
  Engine engine;
  engine.frame(maps, scene);
  EXPECT_EQ(engine.drawn, (std::set<int>{0, 1}));
  EXPECT_EQ(maps.views_drawn(), 2);
  const std::vector<float> first = depths(maps);
  engine.frame(maps, scene);
  EXPECT_TRUE(engine.drawn.empty());
  EXPECT_EQ(maps.views_drawn(), 0);
  EXPECT_EQ(depths(maps), first);
  maps.invalidate();
  engine.frame(maps, scene);
  EXPECT_EQ(engine.drawn, (std::set<int>{0, 1}));
  // A light that moves has its own view drawn again, and no other.
  scene.lights[1].position.x += 0.5f;
  engine.frame(maps, scene);
  EXPECT_EQ(engine.drawn, (std::set<int>{1}));
}

// One box moves: the views that see it before or after are drawn again,
// no other, and the maps (depths and filtered moments, which the resolve
// and the filters redo for the drawn views' layers only) equal maps drawn
// anew by a fresh ShadowMaps: with the fused resolve + filter and with the
// resolve and two blur passes.
class MovingCasterTest : public GpuTest, public ::testing::WithParamInterface<bool> {};

TEST_P(MovingCasterTest, MovingOneCasterDrawsOnlyTheViewsThatSeeIt) {
  TwoSpotLightsScene scene;
  scene.settings.technique = Technique::Vsm;
  scene.settings.filter = Filter::Gaussian;
  scene.settings.blur = 2;
  scene.settings.fused = GetParam();
  ShadowMaps maps;
  Engine engine;
  engine.frame(maps, scene);

  scene.box_centres[2].x += 0.5f;  // under the second light
  engine.frame(maps, scene);
  EXPECT_EQ(engine.drawn, (std::set<int>{1}));
  scene.box_centres[1] = {20.0f, 0.5f, -2.0f};  // from under the first to the second
  engine.frame(maps, scene);
  EXPECT_EQ(engine.drawn, (std::set<int>{0, 1}));
  // Turned inside its box: the engine says so.
  maps.moved(3);
  engine.frame(maps, scene);
  EXPECT_EQ(engine.drawn, (std::set<int>{1}));
  EXPECT_THROW(maps.moved(4), UsageError);

  ShadowMaps fresh;
  Engine fresh_engine;
  fresh_engine.frame(fresh, scene);
  EXPECT_EQ(depths(maps), depths(fresh));
  ASSERT_NE(maps.filtered_maps(), 0u);
  EXPECT_EQ(read_layers(maps.filtered_maps(), GL_RGBA, 4),
            read_layers(fresh.filtered_maps(), GL_RGBA, 4));

  // Another filter width re-filters the cached depths without drawing.
  scene.settings.blur = 3;
  engine.frame(maps, scene);
  EXPECT_TRUE(engine.drawn.empty());
  fresh_engine.frame(fresh, scene);
  EXPECT_EQ(read_layers(maps.filtered_maps(), GL_RGBA, 4),
            read_layers(fresh.filtered_maps(), GL_RGBA, 4));
}

INSTANTIATE_TEST_SUITE_P(Filters, MovingCasterTest, ::testing::Values(true, false),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return info.param ? std::string("Fused") : std::string("TwoPass");
                         });

}  // namespace
}  // namespace penumbra
