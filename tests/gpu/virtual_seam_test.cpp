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

// Over the pairs of neighbouring pixels either side of one kind of
// border: their summed steps, and those of the control pairs a few pixels
// either side of each (their mean).
struct BorderSum {
  double step = 0.0, step_control = 0.0;
  int pairs = 0;
};
struct BorderSteps {
  BorderSum page, level;
};

// Long bars above a wide ground, running away from the camera at angles
// to each other, under a sun a little off overhead, seen obliquely so that
// the image spans several clipmap levels: their shadows' edges cross page
// borders and level borders (circles of camera distance) all along them.
Scene seam_scene(float sun_degrees) {
  Light sun = testing::sun_light({0.25f, -1.0f, 0.15f});
  sun.sun_angle = sun_degrees;
  return testing::TestScene("virtual seams")
      .ground(120.0f)
      .box({-3.5f, 2.0f, -12.0f}, {0.3f, 0.2f, 36.0f}, {0.0f, 12.0f, 0.0f})
      .box({0.0f, 2.5f, -12.0f}, {0.3f, 0.2f, 36.0f}, {0.0f, -20.0f, 0.0f})
      .box({3.0f, 1.5f, -12.0f}, {0.3f, 0.2f, 36.0f}, {0.0f, 35.0f, 0.0f})
      .light(sun)
      .camera({0.0f, 5.0f, 7.0f}, {0.0f, 0.0f, -6.0f}, 60.0f);
}

// The level and world page a ground pixel's lookup reads under the frame's
// level bias (the surface point moved by the normal offset, as
// shadow_lookup() moves it); level -1 off the ground.
glm::ivec3 lookup_page(const VirtualClipmap& clipmap, const glm::vec3& p, const glm::vec3& n,
                       float normal_offset, int bias) {
  const int level = virtual_level_of(clipmap, p, n, bias);
  const LightView& view = clipmap.levels[static_cast<std::size_t>(level)].view;
  const glm::vec4 clip =
      view.view_projection * glm::vec4(p + n * (normal_offset * view.texel_world), 1.0f);
  const glm::vec2 uv = glm::vec2(clip) * 0.5f + 0.5f;
  return {level, glm::ivec2(glm::floor(uv * float(kVirtualPages)))};
}

BorderSteps measure_border_steps(const ShadowSettings& shadow, float sun_degrees) {
  Renderer renderer(seam_scene(sun_degrees));
  const RenderSettings rs = testing::small_frame(384, 240);
  renderer.render(rs, shadow);
  EXPECT_EQ(renderer.virtual_light(), 0);
  EXPECT_EQ(renderer.virtual_page_stats().unserved, 0);
  const Image image = renderer.read_view();
  const SurfacePoints surfaces = renderer.read_surfaces();
  const VirtualClipmap& clipmap = renderer.virtual_clipmap();
  const int bias = renderer.virtual_page_stats().bias;
  const int w = rs.width, h = rs.height;
  std::vector<glm::ivec3> page(surfaces.size(), glm::ivec3(-1));
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    // The ground only: no silhouette between neighbours.
    if (surfaces.covered[i] == 0 || std::abs(surfaces.position[i].y) > 1e-3f) continue;
    page[i] =
        lookup_page(clipmap, surfaces.position[i], surfaces.normal[i], shadow.normal_offset, bias);
  }
  const auto at = [&](glm::ivec2 q) { return static_cast<std::size_t>(q.y) * w + q.x; };
  const auto inside = [&](glm::ivec2 q) { return q.x >= 0 && q.y >= 0 && q.x < w && q.y < h; };
  const auto value = [&](glm::ivec2 q) { return image.rgba[4 * at(q)]; };
  // Pixel q + k d lies on the ground in page `p`.
  const auto in_page = [&](glm::ivec2 q, glm::ivec2 d, int k, glm::ivec3 p) {
    const glm::ivec2 r = q + k * d;
    return inside(r) && page[at(r)] == p;
  };
  const auto step_of = [&](glm::ivec2 q, glm::ivec2 d) {
    return std::abs(value(q + d) - value(q));
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
        // The controls lie inside the pages either side, with every pixel
        // they read: no other border between them and this one.
        bool usable = true;
        for (int k = 1; k <= kOffset; ++k) {
          usable = usable && in_page(q, d, -k, a) && in_page(q, d, k + 1, b);
        }
        if (!usable) continue;
        const glm::ivec2 before = q - kOffset * d, after = q + kOffset * d;
        const double step = step_of(q, d);
        const double step_control = 0.5 * (step_of(before, d) + step_of(after, d));
        BorderSum& sum = a.x != b.x ? steps.level : steps.page;
        sum.step += step;
        sum.step_control += step_control;
        ++sum.pairs;
      }
    }
  }
  return steps;
}

ShadowSettings virtual_maps_in_a_small_pool(Technique technique) {
  ShadowSettings s = testing::virtual_maps(technique);
  // A pool with no room for a finer level bias: the levels one texel per
  // pixel asks for, so that their borders cross the image (the test checks
  // that every page was served).
  s.page_pool_mib = 12;
  return s;
}

TEST_F(GpuTest, VirtualShadowsHaveNoSeamAtPageOrLevelBorders) {
  ShadowSettings pcf = virtual_maps_in_a_small_pool(Technique::Pcf);
  pcf.pcf_width = 8.0f;  // windows reach 4 texels into the neighbouring page
  struct Case {
    ShadowSettings shadow;
    float sun_degrees;
  };
  for (const Case& c : {Case{virtual_maps_in_a_small_pool(Technique::Hard), 0.0f}, Case{pcf, 1.0f},
                        Case{virtual_maps_in_a_small_pool(Technique::Pcss), 6.0f}}) {
    const BorderSteps s = measure_border_steps(c.shadow, c.sun_degrees);
    const std::string name(enum_name<Technique>(kTechniqueNames, c.shadow.technique));
    for (const auto& [kind, b] : {std::pair{"page", s.page}, std::pair{"level", s.level}}) {
      std::printf("%s, %s borders, %d pairs: summed step %.2f (controls %.2f)\n", name.c_str(),
                  kind, b.pairs, b.step, b.step_control);
      // The image spans pages and levels, and shadow edges cross them.
      EXPECT_GE(b.pairs, 100) << name << ", " << kind;
      EXPECT_GT(b.step_control, 2.0) << name << ", " << kind;
      // No more change across a border than a few pixels either side of it,
      // within 1.5x: hard and pcf measure 1.2-1.25x at page borders here (a
      // page read one texel off measures 1.7x).
      EXPECT_LE(b.step, 1.5 * b.step_control + 0.25) << name << ", " << kind;
    }
  }
}

}  // namespace
}  // namespace penumbra
