// Virtual shadow maps have no seam at page borders or at clipmap-level
// borders: the neighbour-step measurement of the cube faces
// (point_light_test.cpp) on a directional light's clipmap. Shadow edges
// cross the borders at an angle; along every image row and column, the
// change of the shadow factor between the two ground pixels either side of
// a border (their lookups read different pages or levels) is summed, and
// compared with the same sum between the pairs a few pixels either side of
// it, inside one page. A straight shadow edge changes by as much from one
// pair to the next wherever it crosses, and the samples' noise is the same
// everywhere, so only a seam makes the borders' sum larger. A lookup that
// reads a wrong texel beside a border (an off-by-one page in the page
// table) or a clamped page instead of its neighbour makes it several times
// larger.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "gpu_fixture.hpp"
#include "render/renderer.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

// The summed steps at the borders and the mean of those at the control
// pairs offset either side, per kind of border.
struct BorderSteps {
  double page = 0.0, page_control = 0.0;
  double level = 0.0, level_control = 0.0;
  int page_pairs = 0, level_pairs = 0;
};

// Three bars on posts above a wide ground, lying across each other, under
// a sun a little off overhead, seen obliquely so that the image spans
// several clipmap levels; their shadows cross page and level borders at
// many angles.
Scene seam_scene(float sun_degrees) {
  Light sun = testing::sun_light({0.25f, -1.0f, 0.15f});
  sun.sun_angle = sun_degrees;
  return testing::TestScene("virtual seams")
      .ground(80.0f)
      .box({0.0f, 2.5f, -4.0f}, {14.0f, 0.2f, 0.3f}, {0.0f, 35.0f, 0.0f})
      .box({-1.0f, 2.0f, -6.0f}, {14.0f, 0.2f, 0.3f}, {0.0f, -50.0f, 0.0f})
      .box({1.5f, 1.5f, 0.5f}, {10.0f, 0.2f, 0.3f}, {0.0f, 80.0f, 0.0f})
      .light(sun)
      .camera({0.0f, 6.0f, 7.0f}, {0.0f, 0.0f, -5.0f}, 60.0f);
}

// The level and world page a ground pixel's lookup reads (the surface
// point moved by the normal offset, as shadow_lookup() moves it); level
// -1 off the ground.
glm::ivec3 lookup_page(const VirtualClipmap& clipmap, const glm::vec3& p, const glm::vec3& n,
                       float normal_offset) {
  const int level = virtual_level_of(clipmap, p);
  const LightView& view = clipmap.levels[static_cast<std::size_t>(level)].view;
  const glm::vec4 clip =
      view.view_projection * glm::vec4(p + n * (normal_offset * view.texel_world), 1.0f);
  const glm::vec2 uv = glm::vec2(clip) * 0.5f + 0.5f;
  return {level, glm::ivec2(glm::floor(uv * float(kVirtualPages)))};
}

BorderSteps measure_border_steps(const ShadowSettings& shadow, float sun_degrees) {
  Renderer renderer(seam_scene(sun_degrees));
  const RenderSettings rs = testing::small_frame(256, 160);
  renderer.render(rs, shadow);
  EXPECT_EQ(renderer.virtual_light(), 0);
  EXPECT_EQ(renderer.virtual_page_stats().unserved, 0);
  const Image image = renderer.read_view();
  const SurfacePoints surfaces = renderer.read_surfaces();
  const VirtualClipmap& clipmap = renderer.virtual_clipmap();
  const int w = rs.width, h = rs.height;
  std::vector<glm::ivec3> page(surfaces.size(), glm::ivec3(-1));
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    // The ground only: no silhouette between neighbours.
    if (surfaces.covered[i] == 0 || std::abs(surfaces.position[i].y) > 1e-3f) continue;
    page[i] = lookup_page(clipmap, surfaces.position[i], surfaces.normal[i], shadow.normal_offset);
  }
  const auto at = [&](glm::ivec2 q) { return static_cast<std::size_t>(q.y) * w + q.x; };
  const auto inside = [&](glm::ivec2 q) { return q.x >= 0 && q.y >= 0 && q.x < w && q.y < h; };
  const auto value = [&](glm::ivec2 q) { return image.rgba[4 * at(q)]; };
  // The step of pair (q, q + d) if both lie on the ground in one page.
  const auto control_step = [&](glm::ivec2 q, glm::ivec2 d, double& step) {
    if (!inside(q) || !inside(q + d)) return false;
    const glm::ivec3 a = page[at(q)], b = page[at(q + d)];
    if (a.x < 0 || a != b) return false;
    step = std::abs(value(q + d) - value(q));
    return true;
  };
  constexpr int kOffset = 4;  // pixels from the border to the control pairs
  BorderSteps steps;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (const glm::ivec2 d : {glm::ivec2(1, 0), glm::ivec2(0, 1)}) {
        const glm::ivec2 q(x, y);
        if (!inside(q + d)) continue;
        const glm::ivec3 a = page[at(q)], b = page[at(q + d)];
        if (a.x < 0 || b.x < 0 || a == b) continue;
        double before = 0.0, after = 0.0;
        // The controls inside the pages either side (the same pages as the
        // border's pixels, so no other border lies between).
        if (!control_step(q - kOffset * d, d, before) || !control_step(q + kOffset * d, d, after) ||
            page[at(q - kOffset * d)] != a || page[at(q + kOffset * d)] != b) {
          continue;
        }
        const double step = std::abs(value(q + d) - value(q));
        if (a.x != b.x) {
          steps.level += step;
          steps.level_control += 0.5 * (before + after);
          ++steps.level_pairs;
        } else {
          steps.page += step;
          steps.page_control += 0.5 * (before + after);
          ++steps.page_pairs;
        }
      }
    }
  }
  return steps;
}

ShadowSettings virtual_maps(Technique technique) {
  ShadowSettings s;
  s.technique = technique;
  s.shadow_maps = ShadowMapKind::Virtual;
  return s;
}

TEST_F(GpuTest, VirtualShadowsHaveNoSeamAtPageOrLevelBorders) {
  ShadowSettings pcf = virtual_maps(Technique::Pcf);
  pcf.pcf_width = 8.0f;  // windows reach 4 texels into the neighbouring page
  struct Case {
    ShadowSettings shadow;
    float sun_degrees;
  };
  for (const Case& c : {Case{virtual_maps(Technique::Hard), 0.0f}, Case{pcf, 1.0f},
                        Case{virtual_maps(Technique::Pcss), 6.0f}}) {
    const BorderSteps s = measure_border_steps(c.shadow, c.sun_degrees);
    const std::string name(enum_name<Technique>(kTechniqueNames, c.shadow.technique));
    std::printf(
        "%s: summed step across %d page-border pairs %.2f (controls %.2f), across %d "
        "level-border pairs %.2f (controls %.2f)\n",
        name.c_str(), s.page_pairs, s.page, s.page_control, s.level_pairs, s.level,
        s.level_control);
    // The image spans pages and levels, and shadow edges cross them.
    EXPECT_GE(s.page_pairs, 300) << name;
    EXPECT_GE(s.level_pairs, 100) << name;
    EXPECT_GT(s.page_control, 3.0) << name;
    EXPECT_GT(s.level_control, 3.0) << name;
    // No more change across a border than a few pixels either side of it.
    EXPECT_LE(s.page, 1.25 * s.page_control + 1.0) << name;
    EXPECT_LE(s.level, 1.25 * s.level_control + 1.0) << name;
  }
}

}  // namespace
}  // namespace penumbra
