// `--model` shows the model's own shadow: on a few shapes framed as
// framed_model_scene frames them, the camera sees a good part of the key
// spot light's shadow on the ground, and that shadow falls towards the
// camera, not behind the model.
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "gpu_fixture.hpp"
#include "model_files.hpp"
#include "render/camera_depth.hpp"
#include "render/renderer.hpp"
#include "scene/builtin_scenes.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;
using testing::write_model_file;

// An axis-aligned box from (0, 0, 0) to `size`, in material "red".
std::string box_obj(glm::vec3 size) {
  std::ostringstream obj;
  obj << "mtllib framing.mtl\n";
  for (int i = 0; i < 8; ++i) {
    obj << "v " << (i & 1 ? size.x : 0.0f) << " " << (i & 2 ? size.y : 0.0f) << " "
        << (i & 4 ? size.z : 0.0f) << "\n";
  }
  // Counter-clockwise seen from outside (vertex i = 1 + x + 2y + 4z).
  obj << "usemtl red\n"
         "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  return obj.str();
}

struct Shot {
  int model = 0;            // pixels of the model
  int ground_shadowed = 0;  // ground pixels in the key light's shadow
  // The shadowed ground's mean offset from the model's foot, along the
  // ground towards the camera (> 0: the shadow falls on the camera's side).
  double towards_camera = 0.0;
  int model_rows = 0;  // image rows the model covers
};

Shot shoot(const std::string& name, const std::string& obj) {
  write_model_file("framing.mtl", testing::red_mtl());
  const Scene scene = framed_model_scene(write_model_file(name, obj));
  Renderer renderer(scene);
  RenderSettings rs;
  rs.width = 160;
  rs.height = 90;
  ShadowSettings shadow;
  shadow.technique = Technique::Hard;
  shadow.map_size = 1024;
  rs.view = View::Shadow;  // the first light's: the key spot light
  renderer.render(rs, shadow);
  const Image factor = renderer.read_view();
  rs.view = View::Albedo;
  renderer.render(rs, shadow);
  const Image albedo = renderer.read_view();

  const glm::dmat4 inverse = glm::inverse(
      glm::dmat4(renderer.camera_projection(rs.width, rs.height) * renderer.camera_view()));
  const glm::vec2 to_camera =
      glm::normalize(glm::vec2(scene.camera.position.x, scene.camera.position.z));
  Shot shot;
  int top = rs.height, bottom = -1;
  for (int y = 0; y < rs.height; ++y) {
    for (int x = 0; x < rs.width; ++x) {
      const float* a = albedo.pixel(x, y);
      if (a[3] < 0.5f) continue;  // no surface
      if (a[1] < 0.3f) {          // the red model (the ground is grey, 0.70)
        ++shot.model;
        top = std::min(top, y);
        bottom = std::max(bottom, y);
        continue;
      }
      const float* f = factor.pixel(x, y);
      if (f[3] < 0.5f || f[0] >= 0.5f) continue;
      ++shot.ground_shadowed;
      // Where the pixel's ray meets the ground (y = 0); the model stands
      // centred on the origin.
      const glm::dvec2 ndc{(x + 0.5) / rs.width * 2.0 - 1.0, 1.0 - (y + 0.5) / rs.height * 2.0};
      const glm::vec3 origin(position_from_depth(inverse, ndc, CAMERA_NEAR_DEPTH));
      const glm::vec3 dir = glm::vec3(position_from_depth(inverse, ndc, CAMERA_FAR_DEPTH)) - origin;
      const glm::vec3 p = origin + dir * (-origin.y / dir.y);
      shot.towards_camera += glm::dot(glm::vec2(p.x, p.z), to_camera);
    }
  }
  shot.towards_camera /= std::max(shot.ground_shadowed, 1);
  shot.model_rows = bottom - top + 1;
  return shot;
}

TEST_F(GpuTest, FramedModelsShowTheirShadowOnTheCamerasSide) {
  struct Case {
    const char* name;
    std::string obj;
  };
  const std::vector<Case> cases = {
      {"framing-cube.obj", box_obj({1.0f, 1.0f, 1.0f})},
      {"framing-tower.obj", box_obj({0.25f, 2.0f, 0.25f})},  // tall and thin
      {"framing-slab.obj", box_obj({2.0f, 0.35f, 1.2f})},    // wide and low
      {"framing-tetrahedron.obj", testing::tetrahedron_obj("framing.mtl")},
  };
  for (const Case& c : cases) {
    const Shot shot = shoot(c.name, c.obj);
    std::printf("%s: model %d px (%d of 90 rows), shadowed ground %d px, %.2f towards the camera\n",
                c.name, shot.model, shot.model_rows, shot.ground_shadowed, shot.towards_camera);
    ASSERT_GT(shot.model, 100) << c.name;
    // The shadow in view is a good part of the picture, not a sliver
    // peeking out from behind the model (a light from the camera's side
    // leaves the slab a twenty-fifth of its own pixels in shadow, the
    // cube a fifth).
    EXPECT_GT(shot.ground_shadowed, shot.model / 6) << c.name;
    // On the camera's side of the model's foot, in world units (the model
    // is kFramedModelSize across).
    EXPECT_GT(shot.towards_camera, 0.1) << c.name;
  }
}

}  // namespace
}  // namespace penumbra
