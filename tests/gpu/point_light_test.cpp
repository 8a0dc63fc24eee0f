// Point lights: six cube-face views with radial depth. The shadow lands on
// the wall behind the caster in each of the six directions and nowhere
// else, and is continuous across the faces' edges.
#include <glm/gtc/matrix_transform.hpp>

#include "gpu_fixture.hpp"
#include "reference/shadow_metrics.hpp"
#include "reference/shadow_ray_tracer.hpp"
#include "render/renderer.hpp"
#include "shadow/cube_views.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

constexpr float kRoom = 5.0f;        // the walls are at +-kRoom on each axis
constexpr float kCasterHalf = 0.5f;  // the caster, a cube, is this half-wide
constexpr float kCasterAt = 2.5f;    // ... and this far from the light

Light point_light(const glm::vec3& position) {
  return testing::point_light(position, 40.0f);
}

// A closed room: six planes facing inwards, a point light at the centre,
// a cube between the light and the wall in direction `axis`.
Scene room_with_caster(const glm::vec3& axis) {
  testing::TestScene scene("room");
  // Rotations that turn a plane's +y normal to face +x, -x, +y, -y, +z, -z.
  const glm::vec3 rotations[kCubeFaces] = {{0, 0, -90}, {0, 0, 90}, {0, 0, 0},
                                           {180, 0, 0}, {90, 0, 0}, {-90, 0, 0}};
  for (int face = 0; face < kCubeFaces; ++face) {
    // the wall facing +axis lies at -axis
    scene.plane(-kRoom * cube_face_axis(face), 2.0f * kRoom, rotations[face]);
  }
  return scene.box(kCasterAt * axis, glm::vec3(2.0f * kCasterHalf))
      .light(point_light(glm::vec3(0.0f)));
}

// Whether the segment from p to the origin (the light) crosses the caster
// grown by `grow` (negative: shrunk), by the slab test.
bool crosses_caster(const glm::vec3& p, const glm::vec3& caster, float grow) {
  const glm::vec3 lo = caster - (kCasterHalf + grow), hi = caster + (kCasterHalf + grow);
  const glm::vec3 dir = -p;  // t in [0, 1] runs from p to the light
  float enter = 0.0f, leave = 1.0f;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(dir[a]) < 1e-9f) {
      if (p[a] < lo[a] || p[a] > hi[a]) return false;
      continue;
    }
    float t0 = (lo[a] - p[a]) / dir[a], t1 = (hi[a] - p[a]) / dir[a];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return enter <= leave;
}

struct WallStats {
  int umbra = 0, umbra_shadowed = 0;  // wall points the caster hides from the light
  int lit = 0, lit_darkened = 0;      // wall points well clear of its shadow
};

TEST_F(GpuTest, PointLightShadowFallsOnTheWallBehindTheCaster) {
  for (int caster_face = 0; caster_face < kCubeFaces; ++caster_face) {
    const glm::vec3 axis = cube_face_axis(caster_face);
    Renderer renderer(room_with_caster(axis));
    RenderSettings rs = testing::small_frame(128, 128);
    ShadowSettings shadow;
    shadow.technique = Technique::Hard;
    shadow.map_size = 256;
    WallStats walls[kCubeFaces];
    // Look at each wall in turn, from inside the room off the walls' axes.
    for (int wall = 0; wall < kCubeFaces; ++wall) {
      const glm::vec3 w = cube_face_axis(wall), side = cube_face_up(wall);
      Camera camera;
      camera.position = 1.5f * w + 2.5f * side;
      camera.target = kRoom * w;
      camera.up = glm::abs(w.y) > 0.5f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
      camera.fov_y_degrees = 70.0f;
      renderer.set_camera(camera);
      renderer.render(rs, shadow);
      const Image image = renderer.read_view();
      const SurfacePoints surfaces = renderer.read_surfaces();
      for (std::size_t i = 0; i < surfaces.size(); ++i) {
        if (!surfaces.covered[i]) continue;
        const glm::vec3 p = surfaces.position[i];
        const int on_wall = cube_face(p);
        if (std::abs(glm::dot(p, cube_face_axis(on_wall)) - kRoom) > 0.01f) continue;  // caster
        const float value = image.rgba[4 * i];
        WallStats& s = walls[on_wall];
        if (crosses_caster(p, kCasterAt * axis, -0.1f)) {
          ++s.umbra;
          s.umbra_shadowed += value < 0.5f;
        } else if (!crosses_caster(p, kCasterAt * axis, 0.15f)) {
          ++s.lit;
          s.lit_darkened += value < 0.99f;
        }
      }
    }
    for (int wall = 0; wall < kCubeFaces; ++wall) {
      const WallStats& s = walls[wall];
      std::printf("caster towards face %d, wall %d: umbra %d/%d shadowed, lit %d/%d darkened\n",
                  caster_face, wall, s.umbra_shadowed, s.umbra, s.lit_darkened, s.lit);
      if (wall == caster_face) {
        EXPECT_GT(s.umbra, 200) << "the wall behind the caster must be seen in shadow";
        EXPECT_EQ(s.umbra_shadowed, s.umbra) << "caster " << caster_face;
      } else {
        EXPECT_EQ(s.umbra, 0);
      }
      EXPECT_GT(s.lit, 1000);
      EXPECT_LE(s.lit_darkened, s.lit / 1000) << "caster " << caster_face << ", wall " << wall;
    }
  }
}

// A caster beside the light, nearer to it than anything else and far off
// the axis of the cube faces that see it: the faces' shared depth range
// starts at its distance, while its depth along a face's axis is smaller
// (its nearest point, 1.9 from the light, is 1.4 along +x). Clipping the
// caster pass at the radial z0 cut it away, and its shadow with it (the
// default scene's high slab under a point light). The map's hard shadow
// against the traced hard shadow: they disagree only on edge pixels, and
// the shadow is there.
TEST_F(GpuTest, PointLightMapsKeepCastersFarOffTheFaceAxes) {
  const Scene scene = testing::TestScene("caster beside the light")
                          .ground(16.0f)
                          .box({1.8f, 2.3f, 0.0f}, glm::vec3(0.8f))
                          .light(point_light({0.0f, 4.0f, 0.0f}))
                          .camera({3.5f, 6.0f, 4.0f}, {3.8f, 0.0f, 0.0f}, 50.0f);
  Renderer renderer(scene);
  const RenderSettings rs = testing::small_frame(160, 120);
  ShadowSettings hard;
  hard.technique = Technique::Hard;
  hard.map_size = 1024;
  hard.light_size = 0.0f;  // the traced hard shadow
  renderer.render(rs, hard);
  const Image technique = renderer.read_view();
  const ShadowRayTracer tracer(renderer.mesh());
  const Image traced =
      tracer.trace(renderer.read_surfaces(),
                   make_reference_light(scene.lights[0], renderer.light_view(0), hard), 1);
  long compared = 0, shadowed = 0, disagree = 0;
  for (int y = 0; y < traced.height; ++y) {
    for (int x = 0; x < traced.width; ++x) {
      if (traced.pixel(x, y)[3] < 0.5f || technique.pixel(x, y)[3] < 0.5f) continue;
      ++compared;
      shadowed += traced.pixel(x, y)[0] < 0.5f;
      disagree += std::abs(technique.pixel(x, y)[0] - traced.pixel(x, y)[0]) > 0.5f;
    }
  }
  const ShadowMetrics m = compare_shadow(technique, traced);
  std::printf("%ld of %ld pixels in the traced shadow; %ld disagree; RMSE %.4f\n", shadowed,
              compared, disagree, m.rmse);
  EXPECT_GT(shadowed, compared / 20) << "the caster's shadow must be in view";
  EXPECT_LE(disagree, compared / 100);
  EXPECT_LT(m.rmse, 0.1);
}

// The seam measurement: a point light 2 above a large ground plane, a bar
// at height 1 lying diagonally, so that its shadow on the ground crosses
// the edge x = 2 between the -y face and the +x face at 45 degrees (the
// ground there receives the light at 45 degrees). Looking straight down,
// image columns are lines of constant x.
struct SeamJump {
  float seam = 0.0f;  // largest change of the shadow factor between the two columns across the edge
  float control = 0.0f;  // the same, between neighbouring columns inside each face
};

SeamJump measure_seam(const ShadowSettings& shadow) {
  Scene scene = testing::TestScene("seam")
                    .ground(24.0f)
                    // along (1, 0, 1)
                    .box({1.1f, 1.0f, 0.6f}, {3.0f, 0.15f, 0.3f}, {0.0f, -45.0f, 0.0f})
                    .light(point_light({0.0f, 2.0f, 0.0f}))
                    .camera({2.0f, 6.0f, 1.0f}, {2.0f, 0.0f, 1.0f}, 30.0f);
  scene.camera.up = {0.0f, 0.0f, -1.0f};
  Renderer renderer(scene);
  const RenderSettings rs = testing::small_frame(160, 160);
  renderer.render(rs, shadow);
  const Image image = renderer.read_view();
  const SurfacePoints surfaces = renderer.read_surfaces();
  SeamJump jump;
  for (int y = 0; y < rs.height; ++y) {
    const auto at = [&](int x) { return static_cast<std::size_t>(y) * rs.width + x; };
    // The two columns either side of the edge x = 2 on this row.
    int edge = -1;
    for (int x = 0; x + 1 < rs.width; ++x) {
      if (surfaces.covered[at(x)] && surfaces.covered[at(x + 1)] &&
          surfaces.position[at(x)].y < 1e-3f && surfaces.position[at(x + 1)].y < 1e-3f &&
          surfaces.position[at(x)].x < 2.0f && surfaces.position[at(x + 1)].x >= 2.0f) {
        edge = x;
      }
    }
    if (edge < 8 || edge + 9 >= rs.width) continue;
    const glm::vec3 p = surfaces.position[at(edge)];
    if (std::abs(p.z) > 1.9f) continue;  // only where the edge is between -y and +x
    const auto value = [&](int x) { return image.rgba[4 * at(x)]; };
    const auto ground = [&](int x) {
      return surfaces.covered[at(x)] && surfaces.position[at(x)].y < 1e-3f;
    };
    jump.seam = std::max(jump.seam, std::abs(value(edge + 1) - value(edge)));
    for (int x : {edge - 6, edge + 6}) {
      if (ground(x) && ground(x + 1)) {
        jump.control = std::max(jump.control, std::abs(value(x + 1) - value(x)));
      }
    }
  }
  return jump;
}

TEST_F(GpuTest, PointLightShadowIsContinuousAcrossCubeFaceEdges) {
  struct Case {
    Technique technique;
    Filter filter;
    int blur;
  };
  for (const Case& c : {Case{Technique::Vsm, Filter::Gaussian, 4}, Case{Technique::Pcf, {}, 0},
                        Case{Technique::Msm, Filter::Sat, 4}}) {
    ShadowSettings shadow;
    shadow.technique = c.technique;
    shadow.filter = c.filter;
    shadow.blur = c.blur;
    shadow.map_size = 256;
    shadow.pcf_width = 6.0f;
    const SeamJump with_band = measure_seam(shadow);
    shadow.guard_band = false;
    const SeamJump without_band = measure_seam(shadow);
    std::printf(
        "%s: largest step across the face edge %.3f with the guard band, %.3f without; "
        "between neighbours inside a face %.3f / %.3f\n",
        std::string(enum_name<Technique>(kTechniqueNames, c.technique)).c_str(), with_band.seam,
        without_band.seam, with_band.control, without_band.control);
    // The shadow crosses the edge: the profile changes from column to column.
    EXPECT_GT(with_band.control, 0.02f);
    // No step at the edge much larger than between neighbouring columns
    // inside a face (the penumbra's own slope: the two faces' texel grids
    // meet the ground differently, so the filter footprints differ a
    // little).
    EXPECT_LE(with_band.seam, 1.5f * with_band.control);
    // Without the guard band, the filters near the edge read the clamped
    // border of the face instead of the scene beyond it: a visible step.
    EXPECT_GT(without_band.seam, 2.0f * with_band.seam);
  }
}

// Backprojection's blockers' region is not capped as the filters' are: under
// a source 0.5 across, the bar's region reaches past the face's guard band
// (67 texels on a 2048^2 face), where the face holds no texels. Reading
// only the face, the bar's blockers beyond it were lost: a step of 0.26
// across the edge against 0.08 between neighbouring columns inside a face.
// The region past the band is read from the other faces
// (backprojection_cube_cell()): 0.05 against 0.07.
TEST_F(GpuTest, BackprojectionReadsBlockersPastACubeFacesGuardBand) {
  ShadowSettings shadow;
  shadow.technique = Technique::Backprojection;
  shadow.map_size = 2048;
  shadow.light_size = 0.5f;
  const SeamJump jump = measure_seam(shadow);
  std::printf("backprojection: largest step across the face edge %.3f, inside a face %.3f\n",
              jump.seam, jump.control);
  EXPECT_GT(jump.control, 0.02f);
  EXPECT_LE(jump.seam, 1.5f * jump.control);
}

// The shadow-map view of a point light: its six faces tiled three to a
// row, +x -x +y on top, -y +z -z below, each tile the face's map as it is.
TEST_F(GpuTest, ShadowMapViewTilesTheCubeFaces) {
  Renderer renderer(room_with_caster(cube_face_axis(3)));
  RenderSettings rs = testing::small_frame(64, 64, View::ShadowMap);
  ShadowSettings shadow;
  shadow.map_size = 48;
  renderer.render(rs, shadow);
  const Image tiled = renderer.read_view();
  const int n = shadow.map_size;
  ASSERT_EQ(tiled.width, 3 * n);
  ASSERT_EQ(tiled.height, 2 * n);
  for (int face = 0; face < kCubeFaces; ++face) {
    const Image map = renderer.read_shadow_view(renderer.first_view(0) + face);
    const int x0 = (face % 3) * n, y0 = (face / 3) * n;
    float worst = 0.0f;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        worst = std::max(worst, std::abs(tiled.pixel(x0 + x, y0 + y)[0] - map.pixel(x, y)[0]));
    EXPECT_EQ(worst, 0.0f) << "face " << face;
  }
  // The caster sits in the -y face: only that tile holds depths nearer
  // than the walls (every wall is at least kRoom away; the caster's
  // nearest point kCasterAt - kCasterHalf).
  for (int face = 0; face < kCubeFaces; ++face) {
    const int x0 = (face % 3) * n, y0 = (face / 3) * n;
    float nearest = 1.0f;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) nearest = std::min(nearest, tiled.pixel(x0 + x, y0 + y)[0]);
    const LightView& v = renderer.shadow_views(0).views[static_cast<std::size_t>(face)];
    const float nearest_distance = v.z0 + nearest * (v.z1 - v.z0);
    if (face == 3) {
      EXPECT_NEAR(nearest_distance, kCasterAt - kCasterHalf, 0.1f) << "the caster, in -y";
    } else {
      EXPECT_GT(nearest_distance, kRoom - 0.1f) << "face " << face << " sees only walls";
    }
  }
}

}  // namespace
}  // namespace penumbra
