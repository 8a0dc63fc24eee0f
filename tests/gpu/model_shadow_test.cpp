// A model read from a file casts its shadow like a built-in shape: a cube
// (an OFF file of six quads) floating over a plane under a spot light.
#include <algorithm>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <optional>

#include "gpu_fixture.hpp"
#include "model_files.hpp"
#include "render/camera_depth.hpp"
#include "render/renderer.hpp"
#include "scene/model.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

constexpr float kHalf = 0.5f;    // the cube's half side once scaled
constexpr float kBottom = 1.5f;  // its height above the plane

Scene cube_model_above_plane() {
  Scene scene;
  scene.name = "model above plane";
  scene.materials = {Material{"grey", glm::vec3(0.7f), glm::vec3(0.0f), 8.0f}};
  Shape plane;
  plane.kind = ShapeKind::Plane;
  plane.size = {12.0f, 0.0f, 12.0f};
  scene.shapes.push_back(plane);
  Shape cube;
  attach_model(scene, cube, testing::write_model_file("shadow-cube.off", testing::cube_off()),
               /*own_materials=*/true);
  cube.scale = glm::vec3(kHalf);  // the file's cube has side 2
  cube.position = {0.0f, kBottom + kHalf, 0.0f};
  cube.rotation_degrees = {0.0f, 90.0f, 0.0f};  // a quarter turn: the same footprint
  scene.shapes.push_back(cube);
  scene.camera.position = {0.0f, 9.0f, 5.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.fov_y_degrees = 50.0f;
  Light spot;
  spot.type = LightType::Spot;
  spot.position = {0.0f, 8.0f, 0.0f};
  spot.direction = {0.0f, -1.0f, 0.0f};
  spot.cone_degrees = 40.0f;
  spot.inner_cone_degrees = 35.0f;
  spot.intensity = 60.0f;
  scene.lights.push_back(spot);
  return scene;
}

// Where the camera ray through a pixel meets the plane y = 0, unless the
// cube is in the way.
std::optional<glm::vec3> plane_point(const Renderer& r, int width, int height, int x, int y) {
  const glm::dmat4 inverse =
      glm::inverse(glm::dmat4(r.camera_projection(width, height) * r.camera_view()));
  const glm::dvec2 ndc{(x + 0.5) / width * 2.0 - 1.0, 1.0 - (y + 0.5) / height * 2.0};
  const glm::vec3 origin(position_from_depth(inverse, ndc, CAMERA_NEAR_DEPTH));
  const glm::vec3 dir =
      glm::normalize(glm::vec3(position_from_depth(inverse, ndc, CAMERA_FAR_DEPTH)) - origin);
  if (dir.y >= 0.0f) return std::nullopt;
  const glm::vec3 lo{-kHalf, kBottom, -kHalf}, hi{kHalf, kBottom + 2 * kHalf, kHalf};
  const glm::vec3 t0 = (lo - origin) / dir, t1 = (hi - origin) / dir;
  const glm::vec3 tmin = glm::min(t0, t1), tmax = glm::max(t0, t1);
  const float enter = std::max({tmin.x, tmin.y, tmin.z});
  const float leave = std::min({tmax.x, tmax.y, tmax.z});
  if (enter <= leave && leave > 0.0f) return std::nullopt;
  return origin + dir * (-origin.y / dir.y);
}

struct Measured {
  int under = 0, under_shadowed = 0;  // the light's path crosses the cube
  int outside = 0, outside_lit = 0;   // well away from the shadow, inside the cone
  double under_brightness = 0.0, outside_brightness = 0.0;  // mean red of the final image
};

Measured measure(const ShadowSettings& shadow) {
  const Scene scene = cube_model_above_plane();
  Renderer renderer(scene);
  RenderSettings rs = testing::small_frame(128, 128);
  renderer.render(rs, shadow);
  const Image factor = renderer.read_view();
  rs.view = View::Final;
  renderer.render(rs, shadow);
  const Image final_image = renderer.read_view();

  Measured m;
  const glm::vec3 light = scene.lights[0].position;
  const float margin = 0.2f;  // world units: the filters' reach on a 512 map, and more
  for (int y = 0; y < rs.height; ++y) {
    for (int x = 0; x < rs.width; ++x) {
      const auto p = plane_point(renderer, rs.width, rs.height, x, y);
      if (!p) continue;
      // Where the path to the light crosses the cube's mid-height.
      const glm::vec3 to_light = glm::normalize(light - *p);
      const glm::vec3 q = *p + to_light * ((kBottom + kHalf - p->y) / to_light.y);
      const float d = std::max(std::abs(q.x), std::abs(q.z));
      const float r = glm::length(glm::vec2(p->x, p->z));
      if (d < kHalf - margin) {
        ++m.under;
        m.under_shadowed += factor.pixel(x, y)[0] < 0.5f;
        m.under_brightness += final_image.pixel(x, y)[0];
      } else if (d > kHalf + 3.0f * margin && r < 3.0f) {
        ++m.outside;
        m.outside_lit += factor.pixel(x, y)[0] > 0.95f;
        m.outside_brightness += final_image.pixel(x, y)[0];
      }
    }
  }
  m.under_brightness /= std::max(m.under, 1);
  m.outside_brightness /= std::max(m.outside, 1);
  return m;
}

TEST_F(GpuTest, ModelCastsItsShadowWithHardAndFilteredTechniques) {
  ShadowSettings hard;
  hard.technique = Technique::Hard;
  hard.map_size = 512;
  ShadowSettings msm = hard;
  msm.technique = Technique::Msm;
  msm.filter = Filter::Gaussian;
  msm.blur = 2;
  for (const ShadowSettings& shadow : {hard, msm}) {
    const Measured m = measure(shadow);
    std::printf("%s: %d/%d under the cube shadowed, %d/%d outside lit, brightness %.3f vs %.3f\n",
                shadow.technique == Technique::Hard ? "hard" : "msm", m.under_shadowed, m.under,
                m.outside_lit, m.outside, m.under_brightness, m.outside_brightness);
    ASSERT_GT(m.under, 50);
    ASSERT_GT(m.outside, 1000);
    EXPECT_EQ(m.under_shadowed, m.under);
    EXPECT_GT(m.outside_lit, 0.99 * m.outside);
    EXPECT_LT(m.under_brightness, 0.5 * m.outside_brightness) << "darker under the model";
  }
}

// A million-triangle model draws: a grid as the ground, a box's shadow on it.
TEST_F(GpuTest, MillionTriangleModelReceivesAShadow) {
  Scene scene = cube_model_above_plane();
  Shape ground;
  attach_model(scene, ground, testing::write_grid_ply("gpu-grid-1m.ply", 708),
               /*own_materials=*/false);
  ground.scale = glm::vec3(8.0f);  // the grid spans [0, 1] in x and z
  ground.position = {-4.0f, 0.0f, -4.0f};
  scene.shapes[0] = ground;
  scene.camera.position = {0.0f, 8.0f, 4.0f};
  Renderer renderer(scene);
  ASSERT_EQ(renderer.mesh().indices.size() / 3, 2u * 708 * 708 + 12u);
  RenderSettings rs = testing::small_frame(64, 64);
  ShadowSettings shadow;
  shadow.map_size = 512;
  renderer.render(rs, shadow);
  const Image image = renderer.read_view();
  // The pixels that see the ground under the cube, and beside it.
  const glm::mat4 to_clip =
      renderer.camera_projection(rs.width, rs.height) * renderer.camera_view();
  const auto value_at = [&](glm::vec3 world) {
    const glm::vec4 clip = to_clip * glm::vec4(world, 1.0f);
    const int x = static_cast<int>((clip.x / clip.w * 0.5f + 0.5f) * rs.width);
    const int y = static_cast<int>((0.5f - clip.y / clip.w * 0.5f) * rs.height);
    return image.pixel(x, y)[0];
  };
  EXPECT_LT(value_at({0.0f, 0.0f, 0.0f}), 0.5f);
  EXPECT_GT(value_at({2.5f, 0.0f, 0.0f}), 0.95f);
  EXPECT_GT(value_at({-2.5f, 0.0f, 0.5f}), 0.95f);
}

}  // namespace
}  // namespace penumbra
