// Summed-area-table lookups in a close-up, where one shadow-map texel
// covers many screen pixels: the box is integrated at the lookup's
// fractional position (shaders/filter/sat.glsl), so the shadow factor
// changes from pixel to pixel across a penumbra instead of in texel-sized
// steps, as smoothly as the bilinearly read Gaussian-filtered map.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/glm.hpp>

#include "gpu_fixture.hpp"
#include "render/renderer.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

constexpr int kMapSize = 64;
constexpr float kLightHeight = 10.0f;
constexpr float kConeDegrees = 30.0f;  // half-angle: the map spans 60 degrees
constexpr float kEdgeX = -2.0f;        // the slab's shadow edge on the ground

// A spot light straight above a slab floating halfway to the ground; the
// camera looks down from close by at the straight edge of the slab's
// shadow, which runs along z and so crosses every image row.
Scene closeup_scene() {
  return testing::TestScene("sat close-up")
      .ground(16.0f)
      // x in [-3, -1] at height 5: its right edge projects to x = -2
      .box({-2.0f, 0.5f * kLightHeight, 0.0f}, {2.0f, 0.1f, 2.0f})
      .camera({kEdgeX, 2.5f, 0.4f}, {kEdgeX, 0.0f, 0.0f}, 40.0f)
      .light(testing::spot_light({0.0f, kLightHeight, 0.0f}, {0.0f, 0.0f, 0.0f}, kConeDegrees,
                                 kConeDegrees - 2.0f));
}

RenderSettings view_settings(View view) {
  RenderSettings rs;
  rs.width = 192;
  rs.height = 96;
  rs.view = view;
  return rs;
}

ShadowSettings settings(Technique technique, Filter filter, int blur, bool soft = false) {
  ShadowSettings s;
  s.technique = technique;
  s.filter = filter;
  s.blur = blur;
  s.soft = soft;
  s.light_size = 0.5f;
  s.map_size = kMapSize;
  return s;
}

// Screen pixels one map texel spans on the ground, along x.
float texel_pixels(const Renderer& renderer, const RenderSettings& rs) {
  const float texel = renderer.light_view(0).texel_world * kLightHeight;
  const glm::mat4 vp = renderer.camera_projection(rs.width, rs.height) * renderer.camera_view();
  auto screen_x = [&](glm::vec3 p) {
    const glm::vec4 clip = vp * glm::vec4(p, 1.0f);
    return (clip.x / clip.w * 0.5f + 0.5f) * float(rs.width);
  };
  return screen_x({kEdgeX + texel, 0, 0}) - screen_x({kEdgeX, 0, 0});
}

struct RowStats {
  int longest_run = 0;     // pixels in a row of identical penumbra values
  float largest_step = 0;  // between horizontally neighbouring pixels
  int penumbra_pixels = 0;
};

// Scans every image row: the runs of exactly equal values inside the
// penumbra (0.02 < factor < 0.98), and the largest change between
// neighbouring pixels anywhere.
RowStats row_stats(const Image& image) {
  RowStats s;
  for (int y = 0; y < image.height; ++y) {
    int run = 1;
    for (int x = 1; x < image.width; ++x) {
      const float a = image.pixel(x - 1, y)[0], b = image.pixel(x, y)[0];
      s.largest_step = std::max(s.largest_step, std::abs(b - a));
      const bool penumbra = b > 0.02f && b < 0.98f;
      s.penumbra_pixels += penumbra;
      run = penumbra && a == b ? run + 1 : 1;
      s.longest_run = std::max(s.longest_run, run);
    }
  }
  return s;
}

RowStats render_stats(Renderer& renderer, View view, const ShadowSettings& s) {
  const RenderSettings rs = view_settings(view);
  renderer.render(rs, s);
  return row_stats(renderer.read_view());
}

// The fixed SAT box, the filtered hard-shadow reference it is measured
// against, and the soft SAT shadows: no texel-wide plateaus, and steps no
// larger than the Gaussian's at the same W.
TEST_F(GpuTest, SatLookupsAreSmoothWithinAMapTexel) {
  Renderer renderer(closeup_scene());
  const RenderSettings rs = view_settings(View::Shadow);
  for (Technique t : {Technique::Vsm, Technique::Msm}) {
    for (int blur : {1, 3}) {
      const RowStats sat = render_stats(renderer, View::Shadow, settings(t, Filter::Sat, blur));
      const float pixels = texel_pixels(renderer, rs);
      const RowStats gaussian =
          render_stats(renderer, View::Shadow, settings(t, Filter::Gaussian, blur));
      const RowStats reference =
          render_stats(renderer, View::ShadowReference, settings(t, Filter::Sat, blur));
      const RowStats soft =
          render_stats(renderer, View::Shadow, settings(t, Filter::Sat, blur, true));
      const char* name = enum_name<Technique>(kTechniqueNames, t).data();
      std::printf(
          "%s W=%d, %.1f px per texel: longest run sat %d, reference %d, soft %d; largest step "
          "sat %.4f, gaussian %.4f, reference %.4f, soft %.4f\n",
          name, blur, pixels, sat.longest_run, reference.longest_run, soft.longest_run,
          sat.largest_step, gaussian.largest_step, reference.largest_step, soft.largest_step);
      ASSERT_GE(pixels, 8.0f) << "the close-up no longer magnifies the map";
      ASSERT_GT(sat.penumbra_pixels, 4 * rs.height) << "no penumbra in view";
      const int texel_wide = int(std::floor(pixels));
      EXPECT_LT(sat.longest_run, texel_wide / 2) << name << " W=" << blur;
      EXPECT_LT(reference.longest_run, texel_wide / 2) << name << " W=" << blur;
      EXPECT_LT(soft.longest_run, texel_wide / 2) << name << " W=" << blur;
      EXPECT_LE(sat.largest_step, 1.5f * gaussian.largest_step) << name << " W=" << blur;
      EXPECT_LE(soft.largest_step, 1.5f * gaussian.largest_step) << name << " W=" << blur;
    }
  }
}

}  // namespace
}  // namespace penumbra
