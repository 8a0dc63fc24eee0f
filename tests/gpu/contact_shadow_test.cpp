// No contact darkening: ground that sees the whole light at the foot of a
// box's lit face stays lit. Filter windows there also cover texels of the
// face itself, nearer the light than the ground's plane; counted as
// occluders they drew a dark streak along the foot (about -0.4 against
// the traced reference). Only surfaces inside the cone from the receiver
// to the light's source may now block it (shaders/shadow/occluder_cone.glsl);
// for the moment soft shadows, which cannot test texels one by one, the
// depth map's cone-tested blocker search decides that nothing blocks.
#include <algorithm>
#include <cstdio>
#include <string>

#include "gpu_fixture.hpp"
#include "reference/traced_reference.hpp"
#include "render/renderer.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

constexpr float kBoxSize = 1.5f;

// A box on a plane, lit by a spot light at `light` in front of it (+z).
Scene box_scene(const glm::vec3& light) {
  return testing::TestScene("box")
      .ground(16.0f)
      .box({0.0f, 0.5f * kBoxSize, 0.0f}, glm::vec3(kBoxSize))
      .camera({0.0f, 3.0f, 6.0f}, {0.0f, 0.5f, 0.0f}, 40.0f)
      .light(testing::spot_light(light, glm::vec3(0.0f), 40.0f, 35.0f));
}

// Low in front (the light meets the ground at the foot at 25 degrees) and
// high (60 degrees, meeting the face at 30 degrees from its plane).
class ContactTest : public GpuTest, public ::testing::WithParamInterface<glm::vec3> {};

TEST_P(ContactTest, GroundAtTheFootOfALitFaceIsNotDarkened) {
  Renderer renderer(box_scene(GetParam()));
  RenderSettings rs = testing::small_frame(240, 136);
  for (float light_size : {0.5f, 1.5f}) {
    ShadowSettings base;
    base.map_size = 512;
    base.light_size = light_size;
    renderer.render(rs, base);
    const TracedReference reference = traced_reference(renderer, rs, base, 64, "");
    const SurfacePoints surfaces = renderer.read_surfaces();
    // msm --soft: the moments over the SAT, with the depth map's
    // cone-tested search deciding that nothing blocks.
    for (const Technique technique :
         {Technique::Pcf, Technique::Pcss, Technique::Backprojection, Technique::Msm}) {
      ShadowSettings shadow = base;
      shadow.technique = technique;
      if (technique == Technique::Msm) {
        shadow.filter = Filter::Sat;
        shadow.soft = true;
      }
      renderer.render(rs, shadow);
      const Image image = renderer.read_view();
      int lit = 0, darker = 0;
      float worst = 0.0f;
      for (int y = 0; y < rs.height; ++y) {
        for (int x = 0; x < rs.width; ++x) {
          const std::size_t i = static_cast<std::size_t>(y) * rs.width + x;
          const glm::vec3 p = surfaces.position[i];
          // Ground in front of the lit face (+z), up to a box width from
          // its foot (beside the box, PCF's fixed window blurs the edge of
          // the box's own shadow: a penumbra, not this defect).
          const float front = p.z - 0.5f * kBoxSize;
          if (!surfaces.covered[i] || p.y > 1e-3f || front <= 0.0f || front > kBoxSize ||
              std::abs(p.x) > 1.5f * kBoxSize) {
            continue;
          }
          const float ref = reference.image.pixel(x, y)[0];
          if (ref < 0.99f) continue;
          ++lit;
          const float d = ref - image.pixel(x, y)[0];
          worst = std::max(worst, d);
          darker += d > 0.1f;
        }
      }
      const std::string name = std::string(enum_name<Technique>(kTechniqueNames, technique)) +
                               (shadow.soft ? " --soft" : "") + ", light " +
                               std::to_string(light_size);
      std::printf(
          "%-22s %d lit ground pixels near the foot, %d darker than the reference by more "
          "than 0.1 (largest %.3f)\n",
          name.c_str(), lit, darker, worst);
      EXPECT_GT(lit, 2000) << name;
      EXPECT_EQ(darker, 0) << name;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(LightHeights, ContactTest,
                         ::testing::Values(glm::vec3(0.0f, 2.0f, 5.0f),
                                           glm::vec3(0.0f, 5.5f, 3.9f)));

}  // namespace
}  // namespace penumbra
