// Texel density (--view texel-density) on the GPU against the cascades'
// own prediction: on a ground seen at increasing distance, each pixel's
// texels per pixel is the area of its footprint on the ground times the
// cosine of the sun's angle to the ground, over the area of a texel of
// the cascade that shades it (its extent over the map size, squared),
// computed here in double from the camera's rays and the cascades'
// projections. Within a cascade the density grows with distance (the
// pixel's footprint grows, the texel does not); at each split it drops,
// by the ratio of the two cascades' texel areas.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "gpu_fixture.hpp"
#include "render/camera_depth.hpp"
#include "render/renderer.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;
using testing::small_frame;
using testing::spot_light;
using testing::sun_light;
using testing::TestScene;

// A ground 300 units long under a sun, seen from 2 units up along it.
TestScene long_ground() {
  TestScene scene("long ground");
  scene.ground(60.0f, 300.0f, {0.0f, 0.0f, -140.0f})
      .camera({0.0f, 2.0f, 8.0f}, {0.0f, 0.0f, -12.0f}, 50.0f)
      .light(sun_light({0.4f, -1.0f, -0.3f}));
  return scene;
}

// The world point where the camera ray through NDC `ndc` meets the ground
// (y = 0); false if it does not.
bool ground_hit(const glm::dmat4& inverse_view_projection, glm::dvec2 ndc, glm::dvec3& hit) {
  const glm::dvec3 origin = position_from_depth(inverse_view_projection, ndc, CAMERA_NEAR_DEPTH);
  const glm::dvec3 direction =
      position_from_depth(inverse_view_projection, ndc, CAMERA_FAR_DEPTH) - origin;
  if (!(direction.y < 0.0)) return false;
  hit = origin + direction * (-origin.y / direction.y);
  return true;
}

// Where pixel (x, gl_row) of a width x height frame sees the ground, and
// the area of its footprint there (from its neighbours' rays).
struct GroundPixel {
  glm::dvec3 point;
  double area;
};
std::optional<GroundPixel> ground_pixel(const glm::dmat4& inverse_view_projection, int x,
                                        int gl_row, int width, int height) {
  const glm::dvec2 step(2.0 / width, 2.0 / height);
  const glm::dvec2 ndc((x + 0.5) * step.x - 1.0, (gl_row + 0.5) * step.y - 1.0);
  glm::dvec3 p, px, py;
  if (!ground_hit(inverse_view_projection, ndc, p) ||
      !ground_hit(inverse_view_projection, ndc + glm::dvec2(step.x, 0.0), px) ||
      !ground_hit(inverse_view_projection, ndc + glm::dvec2(0.0, step.y), py)) {
    return std::nullopt;
  }
  return GroundPixel{p, glm::length(glm::cross(px - p, py - p))};
}

TEST_F(GpuTest, TexelDensityOnAGroundIsWhatTheCascadesPredict) {
  const Scene scene = long_ground();
  Renderer renderer(scene);
  const RenderSettings rs = small_frame(32, 96, View::TexelDensity);
  ShadowSettings shadow;
  shadow.map_size = 256;
  shadow.cascades = 3;
  shadow.technique = Technique::Hard;
  renderer.render(rs, shadow);
  const Image density = renderer.read_texel_density();

  const LightShadowViews& views = renderer.shadow_views(0);
  ASSERT_EQ(views.views.size(), 3u);
  const glm::dmat4 view(renderer.camera_view());
  const glm::dmat4 inverse_view_projection =
      glm::inverse(glm::dmat4(renderer.camera_projection(rs.width, rs.height)) * view);
  const glm::dvec3 to_sun = -glm::dvec3(scene.lights[0].direction);
  const double cos_sun = to_sun.y;  // the ground's normal is +y

  const int x = rs.width / 2;
  std::vector<int> cascade_of_row;
  double previous = 0.0;
  int compared = 0, drops_within = 0, drops_at_splits = 0;
  // Rows from the bottom of the image (near) up (far), in GL's pixel rows.
  for (int gl_row = 0; gl_row < rs.height; ++gl_row) {
    const std::optional<GroundPixel> ground =
        ground_pixel(inverse_view_projection, x, gl_row, rs.width, rs.height);
    if (!ground) continue;
    const glm::dvec3 p = ground->point;
    if (p.z < -289.0) continue;  // beyond the ground's far edge
    const double camera_depth = -(view * glm::dvec4(p, 1.0)).z;
    std::size_t c = 0;
    while (c + 1 < views.cascade_end.size() && camera_depth > views.cascade_end[c]) ++c;
    // The cascade's orthographic extent across its map, over the map size.
    const double extent = 2.0 / views.views[c].projection[0][0];
    const double texel = extent / shadow.map_size;
    const double expected = ground->area * cos_sun / (texel * texel);
    const float* measured = density.pixel(x, rs.height - 1 - gl_row);
    ASSERT_EQ(measured[3], 1.0f) << "row " << gl_row << " sees the ground";
    EXPECT_NEAR(measured[0], expected, 0.02 * expected)
        << "row " << gl_row << ", camera depth " << camera_depth << ", cascade " << c;
    const bool split = !cascade_of_row.empty() && cascade_of_row.back() != static_cast<int>(c);
    if (split) {
      drops_at_splits += measured[0] < previous;
    } else {
      drops_within += measured[0] < previous * 0.9999;
    }
    previous = measured[0];
    cascade_of_row.push_back(static_cast<int>(c));
    ++compared;
  }
  EXPECT_GT(compared, rs.height / 2);
  EXPECT_EQ(drops_within, 0) << "within a cascade the density grows with distance";
  EXPECT_EQ(drops_at_splits, 2) << "it drops at both splits";
  ASSERT_FALSE(cascade_of_row.empty());
  EXPECT_EQ(cascade_of_row.front(), 0);
  EXPECT_EQ(cascade_of_row.back(), 2) << "the rows reach the last cascade";
}

// A spot light's texel grows with the depth from the light: at light-view
// depth z it is 2 z tan(fov / 2) / map size, read here from the view's
// projection (P[1][1] = 1 / tan(fov / 2)); the density on a ground under
// it follows.
TEST_F(GpuTest, TexelDensityUnderASpotLightFollowsItsFrustum) {
  TestScene built("spot ground");
  built.ground(20.0f)
      .camera({0.0f, 9.0f, 6.0f}, {0.0f, 0.0f, 0.0f}, 40.0f)
      .light(spot_light({1.0f, 6.0f, 1.0f}, {0.0f, 0.0f, 0.0f}, 40.0f, 35.0f));
  const Scene& scene = built;
  Renderer renderer(scene);
  const RenderSettings rs = small_frame(48, 32, View::TexelDensity);
  ShadowSettings shadow;
  shadow.map_size = 128;
  renderer.render(rs, shadow);
  const Image density = renderer.read_texel_density();
  const LightView& spot = renderer.light_view(0);
  const glm::dmat4 view(renderer.camera_view());
  const glm::dmat4 inverse_view_projection =
      glm::inverse(glm::dmat4(renderer.camera_projection(rs.width, rs.height)) * view);
  const glm::dmat4 light_view(spot.view);
  const double tan_half_fov = 1.0 / spot.projection[1][1];
  int compared = 0;
  double nearest = INFINITY, farthest = 0.0;
  for (int gl_row = 0; gl_row < rs.height; gl_row += 3) {
    for (int x = 0; x < rs.width; x += 3) {
      const std::optional<GroundPixel> ground =
          ground_pixel(inverse_view_projection, x, gl_row, rs.width, rs.height);
      if (!ground) continue;
      const glm::dvec3 p = ground->point;
      const glm::dvec4 clip = glm::dmat4(spot.view_projection) * glm::dvec4(p, 1.0);
      const glm::dvec2 uv = glm::dvec2(clip) / clip.w;
      const float* measured = density.pixel(x, rs.height - 1 - gl_row);
      if (std::abs(uv.x) > 0.98 || std::abs(uv.y) > 0.98) continue;  // at the map's edge
      const double depth = -(light_view * glm::dvec4(p, 1.0)).z;
      const double texel = 2.0 * depth * tan_half_fov / shadow.map_size;
      const double cos_light =
          glm::normalize(glm::dvec3(scene.lights[0].position) - p).y;  // ground normal +y
      const double expected = ground->area * cos_light / (texel * texel);
      EXPECT_NEAR(measured[0], expected, 0.02 * expected) << "pixel " << x << ", " << gl_row;
      nearest = std::min(nearest, expected);
      farthest = std::max(farthest, expected);
      ++compared;
    }
  }
  EXPECT_GT(compared, 40);
  EXPECT_GT(farthest, 1.5 * nearest) << "the frame spans a range of densities";
}

// The false-colour view shows the same values: green where a texel falls
// on a pixel, red where texels are four times a pixel's area or more,
// blue where four texels or more fall into a pixel.
TEST_F(GpuTest, TexelDensityViewColoursTheValues) {
  Renderer renderer(long_ground());
  const RenderSettings rs = small_frame(32, 96, View::TexelDensity);
  ShadowSettings shadow;
  shadow.map_size = 256;
  renderer.render(rs, shadow);
  const Image colours = renderer.read_view();
  const Image values = renderer.read_texel_density();
  int checked = 0;
  for (int y = 0; y < rs.height; ++y) {
    const float d = values.pixel(rs.width / 2, y)[0];
    const float* c = colours.pixel(rs.width / 2, y);
    if (values.pixel(rs.width / 2, y)[3] == 0.0f) continue;
    if (d <= 0.25f) {
      EXPECT_GT(c[0], c[1] + 0.5f) << "red at " << d;
      ++checked;
    } else if (d >= 4.0f) {
      EXPECT_GT(c[2], c[0] + 0.5f) << "blue at " << d;
      ++checked;
    } else if (std::abs(std::log2(d)) < 0.05f) {
      EXPECT_GT(c[1], c[0] + 0.5f) << "green at " << d;
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
}

}  // namespace
}  // namespace penumbra
