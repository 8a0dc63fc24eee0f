// The G-buffer keeps a material's linear albedo: it is stored sRGB-encoded
// (8 bits where they matter) and must come back as written, not squared
// through a second transfer curve.
#include "gpu_fixture.hpp"
#include "render/renderer.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

// Two planes side by side, seen from above: the left one dark,
// the right one light.
Scene two_planes(float left_albedo, float right_albedo) {
  Scene scene;
  scene.name = "two planes";
  scene.materials = {Material{"left", glm::vec3(left_albedo), glm::vec3(0.0f), 8.0f},
                     Material{"right", glm::vec3(right_albedo), glm::vec3(0.0f), 8.0f}};
  for (int side = 0; side < 2; ++side) {
    Shape plane;
    plane.kind = ShapeKind::Plane;
    plane.size = {4.0f, 0.0f, 8.0f};
    plane.position = {side == 0 ? -2.0f : 2.0f, 0.0f, 0.0f};
    plane.material = side;
    scene.shapes.push_back(plane);
  }
  scene.camera.position = {0.0f, 10.0f, 2.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  Light sun;
  sun.type = LightType::Directional;
  scene.lights.push_back(sun);
  return scene;
}

TEST_F(GpuTest, AlbedoViewReturnsTheLinearAlbedo) {
  const float left = 0.2f, right = 0.7f;
  Renderer renderer(two_planes(left, right));
  RenderSettings rs = testing::small_frame(64, 64, View::Albedo);
  renderer.render(rs, ShadowSettings{});
  const Image image = renderer.read_view();
  // sRGB 8-bit steps are below 0.004 in linear units over this range.
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(image.pixel(16, 32)[c], left, 0.004f) << "channel " << c;
    EXPECT_NEAR(image.pixel(48, 32)[c], right, 0.004f) << "channel " << c;
  }
}

}  // namespace
}  // namespace penumbra
