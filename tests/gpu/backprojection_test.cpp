// Backprojection (shaders/shadow/backprojection.glsl) against the exact
// penumbra of a straight edge: a slab's edge, parallel to a side of the
// spot light's square source, shadows the ground. Seen from a receiver the
// slab hides the part of the source beyond one line, so the lit fraction
// is an integral of the source's radiometric weights (cos theta_source
// cos theta_receiver / d^2, the traced reference's) that the test computes
// in double. A micro-occluder that moves with the receiver's position
// inside its shadow-map texel shows up as a sawtooth with a period of one
// texel along the penumbra: the error binned by the receiver's position
// (bins of an eighth of a texel, each averaged over the pixels along the
// edge, so the source points' per-pixel shift averages out); that shift's
// noise shows in the error of each pixel.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "app/light_choice.hpp"
#include "gpu_fixture.hpp"
#include "io/image.hpp"
#include "reference/shadow_metrics.hpp"
#include "reference/traced_reference.hpp"
#include "render/renderer.hpp"
#include "render/surface_points.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/scene.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

constexpr double kLightHeight = 10.0;
constexpr double kSlabTop = 2.0;

// The slab covers x < edge; the source is a square `source` wide; the
// camera looks down on the penumbra from `camera_height`. The receiver
// stays on the ground the integral assumes unless `normal_offset` (texels)
// is given.
struct EdgeSetup {
  double edge = 0.5;
  double source = 0.5;
  float camera_height = 0.45f;  // close above the penumbra: a few pixels per texel
  float camera_back = 0.25f;
  float cone_degrees = 25.0f;
  float normal_offset = 0.0f;
  int backprojection_cells = ShadowSettings{}.backprojection_cells;
};

Scene edge_scene(const EdgeSetup& setup) {
  const float penumbra_x = float(setup.edge * kLightHeight / (kLightHeight - kSlabTop));
  return testing::TestScene("edge")
      .ground(16.0f)
      // x in [edge - 4, edge], z in [-2, 2], y in [1.9, 2]
      .box({float(setup.edge) - 2.0f, float(kSlabTop) - 0.05f, 0.0f}, {4.0f, 0.1f, 4.0f})
      .camera({penumbra_x, setup.camera_height, setup.camera_back}, {penumbra_x, 0.0f, 0.0f})
      // cone 25 degrees: a 1024^2 map has 9 mm texels on the ground
      .light(testing::spot_light({0.0f, float(kLightHeight), 0.0f}, {0.0f, 0.0f, 0.0f},
                                 setup.cone_degrees, 20.0f));
}

// Integral over t in [lo, hi] of 1 / (a + t^2)^2.
double inverse_square_squared(double a, double lo, double hi) {
  auto primitive = [a](double t) {
    return t / (2.0 * a * (a + t * t)) + std::atan(t / std::sqrt(a)) / (2.0 * a * std::sqrt(a));
  };
  return primitive(hi) - primitive(lo);
}

// Lit fraction of the ground point (x, 0, z) under the source square
// [-w/2, w/2]^2 at height H facing down, with the slab's edge at x = edge
// on top of the slab (height kSlabTop): the source points with
// l_x < x + (edge - x) H / h are hidden. Both cosines are H / d, so each
// source point weighs 1 / d^4; the z integral is closed-form.
double edge_lit_fraction(double x, double z, double edge, double source) {
  const double half = 0.5 * source;
  const double hidden_below = x + (edge - x) * kLightHeight / kSlabTop;
  constexpr int kColumns = 512;
  double lit = 0.0, total = 0.0;
  for (int i = 0; i < kColumns; ++i) {
    const double lx = -half + (i + 0.5) / kColumns * source;
    const double a = (lx - x) * (lx - x) + kLightHeight * kLightHeight;
    const double w = inverse_square_squared(a, -half - z, half - z);
    total += w;
    if (lx >= hidden_below) lit += w;
  }
  return lit / total;
}

// The slab's edge where the shadow map puts it: the texels whose centres
// see the slab are the slab, so its silhouette lies on the texel boundary
// nearest the true edge.
double map_edge(const LightView& view, int map_size, double slab_edge) {
  auto texel = [&](double x) {
    const glm::vec4 clip = view.view_projection * glm::vec4(float(x), float(kSlabTop), 0.0f, 1.0f);
    return glm::dvec2(clip.x / clip.w, clip.y / clip.w) * (0.5 * map_size) + 0.5 * map_size;
  };
  const glm::dvec2 at = texel(slab_edge), step = texel(slab_edge + 0.01) - at;
  const int axis = std::abs(step.x) > std::abs(step.y) ? 0 : 1;
  return slab_edge + (std::round(at[axis]) - at[axis]) * 0.01 / step[axis];
}

struct EdgeError {
  double rms = 0.0;   // of the binned mean error
  double peak = 0.0;  // largest |binned mean error|
  int bins = 0;
  double pixel_rms = 0.0;  // of each pixel's error: the bins' bias and the noise around it
};

EdgeError edge_error(Technique technique, int map_size, const EdgeSetup& setup = {}) {
  Renderer renderer(edge_scene(setup));
  RenderSettings rs = testing::small_frame(320, 240);
  ShadowSettings s;
  s.technique = technique;
  s.map_size = map_size;
  s.light_size = float(setup.source);
  s.normal_offset = setup.normal_offset;
  s.backprojection_cells = setup.backprojection_cells;
  renderer.render(rs, s);
  const Image image = renderer.read_view();
  const SurfacePoints surfaces = renderer.read_surfaces();
  const double edge = map_edge(renderer.light_view(0), map_size, setup.edge);
  // World width of a texel on the ground.
  const LightView& view = renderer.light_view(0);
  const double texel = view.texel_world * kLightHeight;
  const double centre = edge * kLightHeight / (kLightHeight - kSlabTop);
  const double half_penumbra = 0.5 * setup.source * kSlabTop / (kLightHeight - kSlabTop);
  const double from = centre - 1.5 * half_penumbra, to = centre + 1.5 * half_penumbra;
  const double bin_width = texel / 8.0;
  const int bins = int(std::ceil((to - from) / bin_width));
  std::vector<double> sum(bins, 0.0);
  std::vector<int> count(bins, 0);
  double pixel_squares = 0.0;
  int pixels = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::size_t i = std::size_t(y) * image.width + x;
      if (!surfaces.covered[i]) continue;
      const glm::vec3 p = surfaces.position[i];
      if (std::abs(p.y) > 1e-3f || std::abs(p.z) > 0.3f || p.x < from || p.x >= to) continue;
      const int b = int((p.x - from) / bin_width);
      const double error =
          double(image.pixel(x, y)[0]) - edge_lit_fraction(p.x, p.z, edge, setup.source);
      sum[b] += error;
      ++count[b];
      pixel_squares += error * error;
      ++pixels;
    }
  }
  EdgeError e;
  double squares = 0.0;
  for (int b = 0; b < bins; ++b) {
    if (count[b] < 8) continue;
    const double mean = sum[b] / count[b];
    squares += mean * mean;
    e.peak = std::max(e.peak, std::abs(mean));
    ++e.bins;
  }
  e.rms = e.bins ? std::sqrt(squares / e.bins) : 0.0;
  e.pixel_rms = pixels ? std::sqrt(pixel_squares / pixels) : 0.0;
  std::printf(
      "%d bins of 1/8 texel (%.4f) across a %.1f-texel penumbra: RMS %.4f, peak %.4f; "
      "%d pixels: RMS %.4f\n",
      e.bins, texel, 2.0 * half_penumbra / texel, e.rms, e.peak, pixels, e.pixel_rms);
  return e;
}

// A 1024^2 map: the penumbra is about 14 texels wide, where a micro-
// occluder centred on the lookup instead of its texel moved the silhouette
// by up to 0.7 texel (measured before the texel-aligned patches: RMS
// 0.0182, peak 0.046; with them 0.0017, peak 0.0056; with the multi-
// jittered source points 0.0001, peak 0.0004). Pixel by pixel, a regular
// grid of source points shifted per pixel hid one of 17 fractions of the
// source behind an edge parallel to its side: RMS 0.0207 over the
// penumbra's pixels; the multi-jittered points, one of 257: 0.0014.
TEST_F(GpuTest, BackprojectionHasNeitherSawtoothNorNoiseAcrossAStraightEdge) {
  const EdgeError e = edge_error(Technique::Backprojection, 1024);
  ASSERT_GT(e.bins, 60) << "too few receivers across the penumbra";
  EXPECT_LE(e.rms, 0.005);
  EXPECT_LE(e.pixel_rms, 0.005) << "the penumbra is noisy from pixel to pixel";
}

// The same edge 27 degrees off the light's axis, with the default normal
// offset (half a texel): moving the lookup along the ground's normal moved
// it half a texel times sin 27 degrees across the map, and the 9-texel
// penumbra with it (binned RMS 0.0222). Backprojection took the offset
// times 1 - cos theta (0.0024); now none where the receiver's slope is
// under the settings' max_slope (backprojection_normal_offset(): 0.0001).
TEST_F(GpuTest, BackprojectionKeepsAPenumbraInPlaceWhateverTheNormalOffset) {
  EdgeSetup setup;
  setup.edge = 4.0;
  setup.cone_degrees = 35.0f;
  setup.normal_offset = ShadowSettings{}.normal_offset;
  ASSERT_GT(setup.normal_offset, 0.0f);
  const EdgeError e = edge_error(Technique::Backprojection, 1024, setup);
  ASSERT_GT(e.bins, 60) << "too few receivers across the penumbra";
  EXPECT_LE(e.rms, 0.002);
}

// The straight edge's binned RMS at its worst over four places a texel
// apart (every `stride`-th of them) under a source 8 wide, a penumbra of
// about 220 texels, read with backprojection_cells `cells`.
double wide_edge_worst(int cells, int stride = 1) {
  const double cone = glm::radians(double(EdgeSetup{}.cone_degrees));
  const double slab_texel = 2.0 * std::tan(cone) * (kLightHeight - kSlabTop) / 1024;
  double worst = 0.0;
  for (int shift = 0; shift < 4; shift += stride) {
    EdgeSetup setup;
    setup.edge = 0.5 + shift * slab_texel;
    setup.source = 8.0;
    setup.camera_height = 1.2f;
    setup.camera_back = 0.6f;
    setup.backprojection_cells = cells;
    const EdgeError e = edge_error(Technique::Backprojection, 1024, setup);
    EXPECT_GT(e.bins, 60) << "too few receivers across the penumbra";
    std::printf("cells %d, edge %d texels on: binned RMS %.4f\n", cells, shift, e.rms);
    worst = std::max(worst, e.rms);
  }
  return worst;
}

// The wide edge's penumbra read from the depth hierarchy's cells 4
// texels wide (backprojection_cells 64). A cell that the slab's edge cuts
// stood for the slab wholly or not at all, as its centre texel did,
// moving the silhouette by up to half a cell with the edge's place among
// the cells: over four places a texel apart, binned RMS 0.0046, 0.0092,
// 0.0046 and 0.0005. Read as its quarters (each as a texel next to its
// centre does), by up to a quarter: 0.0046, 0.0005, 0.0046, 0.0005. Read
// texel by texel: 0.0005 at each.
TEST_F(GpuTest, BackprojectionReadsACellCutByAnEdgeTexelByTexel) {
  EXPECT_LE(wide_edge_worst(ShadowSettings{}.backprojection_cells), 0.002);
}

// The same penumbra with backprojection_cells 32, cells 8 texels wide
// whose cut ones are read as their quarters (binned RMS up to 0.0091), and
// 128, cells 2 texels wide whose quarters are the texels (0.0005).
TEST_F(GpuTest, BackprojectionCellsSetHowFineAWideRegionIsRead) {
  EXPECT_LE(wide_edge_worst(128, 2), 0.002);
  EXPECT_GT(wide_edge_worst(32), 0.004);
}

// A box floating over the ground, lit by a sun or a point light with a
// wide source: backprojection on a cube face and on cascades against the
// traced reference, with PCSS (which they fell back to before, the same
// error) as the yardstick: point light 0.0052 against pcss's 0.0887, sun
// 0.0020 against 0.0045.
Scene floating_box(LightType type) {
  return testing::TestScene("floating box")
      .ground(14.0f)
      .box({0.0f, 1.2f, 0.0f}, glm::vec3(1.0f))
      // standing on the ground: a contact shadow beside the wide one
      .box({1.6f, 0.5f, 1.0f}, {0.3f, 1.0f, 0.3f})
      .camera({0.0f, 6.0f, 5.0f}, {0.3f, 0.0f, 0.3f}, 50.0f)
      .light(testing::overhead_light(type));
}

struct SoftErrors {
  double pcss = 0.0, backprojection = 0.0;
};

// The RMSEs on floating_box(type), with conventional maps or `virtual_maps`.
SoftErrors soft_errors(LightType type, bool virtual_maps = false) {
  Renderer renderer(floating_box(type));
  RenderSettings rs = testing::small_frame(200, 150);
  ShadowSettings s = virtual_maps ? testing::virtual_maps(Technique::Pcss) : ShadowSettings{};
  s.map_size = 1024;
  s.light_size = 0.6f;  // the point light's sphere
  s.sun_angle = 6.0f;   // the sun's disc, degrees
  const TracedReference reference = traced_reference(renderer, rs, s, 256, "");
  SoftErrors e;
  for (Technique t : {Technique::Pcss, Technique::Backprojection}) {
    s.technique = t;
    renderer.render(rs, s);
    const double rmse = compare_shadow(renderer.read_view(), reference.image).rmse;
    (t == Technique::Pcss ? e.pcss : e.backprojection) = rmse;
  }
  std::printf("%s%s: RMSE pcss %.4f, backprojection %.4f\n",
              type == LightType::Point ? "point light" : "sun",
              virtual_maps ? ", virtual maps" : "", e.pcss, e.backprojection);
  return e;
}

TEST_F(GpuTest, BackprojectionSoftensAPointLightsShadowOnItsCubeFaces) {
  const SoftErrors e = soft_errors(LightType::Point);
  EXPECT_GT(e.backprojection, 0.0) << "nothing compared";
  EXPECT_LT(e.backprojection, 0.8 * e.pcss);
}

// A backprojection image and its traced reference.
struct CloseUp {
  Image shadow;
  Image reference;
};

// Backprojection and the traced reference (64 rays) on a small test scene,
// 160 x 120, 1024^2 maps, under its light with a source `light_size` wide.
CloseUp small_scene_images(const Scene& scene, float light_size) {
  Renderer renderer(scene);
  RenderSettings rs = testing::small_frame(160, 120);
  ShadowSettings s;
  s.technique = Technique::Backprojection;
  s.map_size = 1024;
  s.light_size = light_size;
  TracedReference reference = traced_reference(renderer, rs, s, 64, "");
  renderer.render(rs, s);
  return {renderer.read_view(), std::move(reference.image)};
}

// A slab 39 degrees off the point light's downward axis, its shadow seen
// from above (backprojection_sphere_width() and the near cut of
// shadow_backprojection()):
// - a cube face's corners lie 1.5 times farther from the light than their
//   axial depth, so the nearest distance the face stores is not its
//   nearest axial depth. Cut at that distance taken as a depth, the
//   blockers' region of a receiver in the umbra stopped short of the slab
//   texels that hide the source's rim, and the umbra read about 0.3 lit;
// - seen from a receiver that far off the axis, the sphere's image on the
//   face's plane is an ellipse 1.3 times as long as the sphere is wide
//   along the direction to the receiver; the disc that stood for it made
//   the penumbrae too narrow.
// Before: 131 of 8913 umbra pixels over 0.1, RMSE 0.0595; with the near
// cut alone none, 0.0275; with both none, 0.0200.
TEST_F(GpuTest, BackprojectionDarkensTheUmbraOfABlockerOffACubeFacesAxis) {
  const Scene scene = testing::TestScene("slab off the axis")
                          .ground(24.0f)
                          .box({4.0f, 3.0f, 0.0f}, {2.5f, 0.1f, 2.5f})
                          .camera({6.4f, 5.0f, 0.5f}, {6.4f, 0.0f, 0.0f}, 50.0f)
                          .light(testing::point_light({0.0f, 8.0f, 0.0f}, 60.0f));
  const CloseUp images = small_scene_images(scene, 0.6f);
  const Image& shadow = images.shadow;
  long umbra = 0, lit_in_umbra = 0;
  for (std::size_t i = 0; i < shadow.rgba.size(); i += 4) {
    const bool judged = images.reference.rgba[i + 3] > 0.0f;
    if (!judged || images.reference.rgba[i] > 0.01f) continue;  // outside the umbra
    ++umbra;
    if (shadow.rgba[i] > 0.1f) ++lit_in_umbra;
  }
  const ShadowMetrics m = compare_shadow(shadow, images.reference);
  std::printf("slab off the axis: %ld of %ld umbra pixels over 0.1, RMSE %.4f\n", lit_in_umbra,
              umbra, m.rmse);
  ASSERT_GT(umbra, 2000) << "too little of the umbra in view";
  EXPECT_EQ(lit_in_umbra, 0);
  EXPECT_LT(m.rmse, 0.024);
}

TEST_F(GpuTest, BackprojectionSoftensTheSunsShadowOnItsCascades) {
  const SoftErrors e = soft_errors(LightType::Directional);
  EXPECT_GT(e.backprojection, 0.0) << "nothing compared";
  EXPECT_LT(e.backprojection, 0.8 * e.pcss);
}

// The same through the sun's virtual maps: they took the scene's own sun
// (its disc 1 degree wide, the default) where the settings' sun_angle
// widens it to 6 degrees, as the cascades and the reference take it, and
// drew the penumbrae a sixth as wide (before: RMSE pcss 0.0177,
// backprojection 0.0180; now 0.0042, 0.0011).
TEST_F(GpuTest, VirtualMapsSoftenTheSunsShadowByTheSettingsSunAngle) {
  const SoftErrors e = soft_errors(LightType::Directional, true);
  EXPECT_GT(e.backprojection, 0.0) << "nothing compared";
  EXPECT_LT(e.backprojection, 0.8 * e.pcss);
  EXPECT_LT(e.backprojection, 0.01);
}

// Backprojection's shadow factor of `scene` (the first light's) with the
// settings `s`, and the traced reference of `rays` a pixel.
CloseUp backprojection_images(const Scene& scene, int width, int height, ShadowSettings s,
                              int rays) {
  Renderer renderer(scene);
  RenderSettings rs = testing::small_frame(width, height);
  s.technique = Technique::Backprojection;
  TracedReference reference = traced_reference(renderer, rs, s, rays, "");
  renderer.render(rs, s);
  return {renderer.read_view(), std::move(reference.image)};
}

// Backprojection and the traced reference (256 rays) on a close-up of the
// default scene, 200 x 150, under its spot light, or under `light`
// (--light's choice: a point light where the spot is), with a source
// `light_size` wide; the other settings `s`'s.
CloseUp default_scene_images(glm::vec3 camera, glm::vec3 target, float fov_y_degrees,
                             float light_size, const std::string& light = "",
                             ShadowSettings s = {}) {
  Scene scene = *builtin_scene("default");
  apply_light_choice(light, scene);
  scene.camera.position = camera;
  scene.camera.target = target;
  scene.camera.fov_y_degrees = fov_y_degrees;
  s.light_size = light_size;
  return backprojection_images(scene, 200, 150, s, 256);
}

// The same from the default scene's own camera, 320 x 180, 64 rays.
CloseUp default_view_images(const std::string& light, const ShadowSettings& s) {
  Scene scene = *builtin_scene("default");
  apply_light_choice(light, scene);
  return backprojection_images(scene, 320, 180, s, 64);
}

// llvmpipe ends every loop of a shader invocation once they have run
// 65535 iterations in all, counted for the eight pixels it shades
// together (gallivm's LP_MAX_TGSI_LOOP_ITERATIONS), and a lookup cut short
// reads lit. The default scene under its point light 3 wide, at
// backprojection_cells 128: with a loop for each row and each column of a
// merged cell's cells and for each row of a cut cell's quarters, 5 of the
// umbra's 760 pixels read lit (at 640x360 RMSE 0.0202 against 0.0068).
TEST_F(GpuTest, BackprojectionReadsEveryCellOfAWideRegion) {
  ShadowSettings s;
  s.light_size = 3.0f;
  s.backprojection_cells = 128;
  const CloseUp images = default_view_images("point", s);
  int umbra = 0, lit_in_umbra = 0;
  for (std::size_t i = 0; i < images.shadow.rgba.size(); i += 4) {
    const float* ref = &images.reference.rgba[i];
    if (ref[3] <= 0.0f || ref[0] > 0.05f) continue;  // judged and in the umbra
    ++umbra;
    if (images.shadow.rgba[i] > 0.5f) ++lit_in_umbra;
  }
  std::printf("umbra pixels %d, read lit %d\n", umbra, lit_in_umbra);
  ASSERT_GT(umbra, 100);
  EXPECT_EQ(lit_in_umbra, 0);
}

ShadowMetrics default_scene_close_up(glm::vec3 camera, glm::vec3 target, float fov_y_degrees,
                                     float light_size, const ShadowSettings& s = {}) {
  const CloseUp images = default_scene_images(camera, target, fov_y_degrees, light_size, "", s);
  return compare_shadow(images.shadow, images.reference);
}

// The default scene's box seen close up at its foot, under a source 1.5
// wide: the blockers' region of the ground along the foot spans over 40
// texels, so it is read from the hierarchy's cells, and the cell
// holding the receiver is cut by its plane (the box's side fills part of
// it). Read as one patch at its centre texel's depth, that cell hid the
// whole source from lit ground: pixels the reference lights (> 0.9) read
// under 0.7 (before the receiver's own cells were read as texels: 6 of
// 29 982, largest error 1.0, RMSE 0.0197; now none, 0.708, 0.0152).
TEST_F(GpuTest, BackprojectionLightsTheGroundAtTheFootOfALitWall) {
  const ShadowMetrics m =
      default_scene_close_up({-1.6f, 2.5f, 4.5f}, {-2.4f, 0.2f, 1.2f}, 40.0f, 1.5f);
  std::printf("box's foot: RMSE %.4f, largest error %.3f, over-dark %.3f %% of %ld pixels\n",
              m.rmse, m.max_error, 100.0 * m.over_dark_fraction, m.pixels);
  ASSERT_GT(m.pixels, 20000) << "too little of the scene compared";
  EXPECT_EQ(m.over_dark_fraction, 0.0);
  EXPECT_LT(m.max_error, 0.9);
}

// The same where the region is read from cells coarser than those whose
// 2 x 2 around the receiver are read as texels (BACKPROJECTION_REFINE_LEVEL):
// at most 16 patches a side, so cells 16 texels wide. Those 2 x 2 read as
// cells hid the whole source from the lit ground along the foot (RMSE
// 0.0472, largest error 1.0, 0.2 % of the pixels over-dark); read as
// texels, and the cells around them finer the nearer
// (backprojection_near_patches()), 0.0085, 0.708 and none.
TEST_F(GpuTest, BackprojectionLightsTheGroundAtTheFootOfALitWallFromCoarseCells) {
  ShadowSettings s;
  s.backprojection_cells = 16;
  const ShadowMetrics m =
      default_scene_close_up({-1.6f, 2.5f, 4.5f}, {-2.4f, 0.2f, 1.2f}, 40.0f, 1.5f, s);
  std::printf("box's foot: RMSE %.4f, largest error %.3f, over-dark %.3f %% of %ld pixels\n",
              m.rmse, m.max_error, 100.0 * m.over_dark_fraction, m.pixels);
  ASSERT_GT(m.pixels, 20000) << "too little of the scene compared";
  EXPECT_EQ(m.over_dark_fraction, 0.0);
  EXPECT_LT(m.max_error, 0.9);
}

// The default scene's box seen close up at its right-hand foot, in the
// high slab's penumbra, under a source `light_size` wide: in the map the
// slab's edge lies over the box and the ground. Pixels the traced
// reference lights more than 0.1 more, and the RMSE.
struct BetweenCasters {
  long judged = 0;
  long too_dark = 0;
  double rmse = 0.0;
};
BetweenCasters between_two_casters(float light_size) {
  const CloseUp images =
      default_scene_images({-0.4f, 1.6f, 3.2f}, {-1.7f, 0.2f, 1.0f}, 30.0f, light_size);
  BetweenCasters b;
  for (std::size_t i = 0; i < images.shadow.rgba.size(); i += 4) {
    if (images.reference.rgba[i + 3] <= 0.0f) continue;
    ++b.judged;
    if (images.shadow.rgba[i] < images.reference.rgba[i] - 0.1f) ++b.too_dark;
  }
  b.rmse = compare_shadow(images.shadow, images.reference).rmse;
  std::printf(
      "box's foot under the slab, source %.1f: %ld of %ld pixels over 0.1 too dark, "
      "RMSE %.4f\n",
      light_size, b.too_dark, b.judged, b.rmse);
  return b;
}

// Source 1.5: the hierarchy's cells there step from the slab's depth to
// the box's, and the reach of the slab's cell to its neighbour's
// projection of their shared edge (the gap filling that joins the
// patches of one surface) stood for a wall from the slab down to the box,
// which hid the light passing between them: the box's side and the ground
// at its foot read up to 0.3 too dark (before: 510 of 30 000 pixels over
// 0.1 darker than the reference, RMSE 0.0300; then 10, 0.0121).
TEST_F(GpuTest, BackprojectionLetsTheLightPassBetweenTwoCasters) {
  const BetweenCasters b = between_two_casters(1.5f);
  ASSERT_GT(b.judged, 25000) << "too little of the scene compared";
  EXPECT_LT(b.too_dark, b.judged / 500);
  EXPECT_LT(b.rmse, 0.02);
}

// Source 0.5: the region is read texel by texel, whose patches reached
// their neighbours whatever the step between them (backprojection_joined()
// judged only the cells'): 69 of 30 000 pixels over 0.1 too dark, RMSE
// 0.0103; with the same test as the cells', none, 0.0037.
TEST_F(GpuTest, BackprojectionLetsTheLightPassBetweenTwoCastersTexelByTexel) {
  const BetweenCasters b = between_two_casters(0.5f);
  ASSERT_GT(b.judged, 25000) << "too little of the scene compared";
  EXPECT_LT(b.too_dark, b.judged / 1000);
  EXPECT_LT(b.rmse, 0.007);
}

// The default scene's sphere seen close up at its terminator, under a
// source 0.5 wide. The traced reference weighs the source against the
// shading normal's horizon (docs/comparing.md, "The terminator model");
// weighed against the triangle's, near the terminator backprojection
// counted other points of the source, and where the pole's shadow crosses
// the terminator it read lit pixels the reference puts in shadow (before:
// 26 leaking pixels of 26 300, largest error 1.0, RMSE 0.0374; now none,
// 0.199, 0.0109).
TEST_F(GpuTest, BackprojectionWeighsTheSourceAboveTheShadingNormalsHorizon) {
  const ShadowMetrics m =
      default_scene_close_up({-0.6f, 2.6f, 3.9f}, {0.1f, 1.4f, 1.4f}, 30.0f, 0.5f);
  std::printf("sphere's terminator: RMSE %.4f, largest error %.3f, leaks %.3f %% of %ld pixels\n",
              m.rmse, m.max_error, 100.0 * m.leak_fraction, m.pixels);
  ASSERT_GT(m.pixels, 20000) << "too little of the scene compared";
  EXPECT_EQ(m.leak_fraction, 0.0);
  EXPECT_LT(m.max_error, 0.5);
}

// The default scene's sphere in the high slab's shadow, seen close up
// along its terminator, under a source 1.5 wide. Past the terminator a
// receiver's triangle faces away from the source's centre, and the rays to
// the part of the source above its horizon run behind its plane as the
// map sees it: cutting the blockers at that plane dropped the slab, and
// those pixels read lit where the traced reference reads 0 (before: 0.52 %
// of 20 785 pixels leaking, largest error 1.0, RMSE 0.0755; then none,
// 0.391, 0.0181). Along the terminator only a sliver of the source lies
// above the horizon, and the points spread over the whole square read it
// from the few of them in it; spread over the sliver's bounding rectangle
// (backprojection_horizon_window()), RMSE 0.0096, largest error 0.252.
TEST_F(GpuTest, BackprojectionKeepsTheBlockersOfTheSourceAboveATerminatorsHorizon) {
  const ShadowMetrics m =
      default_scene_close_up({-1.2f, 2.4f, 4.6f}, {-0.2f, 1.6f, 1.3f}, 25.0f, 1.5f);
  std::printf(
      "terminator under the slab: RMSE %.4f, largest error %.3f, leaks %.3f %% of %ld "
      "pixels\n",
      m.rmse, m.max_error, 100.0 * m.leak_fraction, m.pixels);
  ASSERT_GT(m.pixels, 10000) << "too little of the scene compared";
  EXPECT_EQ(m.leak_fraction, 0.0);
  EXPECT_LT(m.max_error, 0.35);
  EXPECT_LT(m.rmse, 0.012);
}

// The default scene's torus under the sun (its disc 2.82 degrees wide),
// close up along its terminator, through virtual maps: their lookup took
// the triangle's normal for the horizon the source is weighed against,
// where the traced reference takes the shading normal's (docs/comparing.md,
// "The terminator model"), and read dark where the part of the sun's disc
// above the shading normal's horizon is lit (before: RMSE 0.0184, largest
// error 0.739, leaks 0.010 %; now 0.0123, 0.599, none). At 1280x720 the
// whole default scene's sun at 2.82 degrees read 0.00315, now 0.00244.
TEST_F(GpuTest, VirtualBackprojectionWeighsTheSourceAboveTheShadingNormalsHorizon) {
  ShadowSettings s = testing::virtual_maps(Technique::Backprojection);
  s.sun_angle = 2.822f;
  const CloseUp images = default_scene_images({2.0f, 3.6f, 4.2f}, {2.6f, 1.1f, 0.2f}, 22.0f,
                                              s.light_size, "directional", s);
  const ShadowMetrics m = compare_shadow(images.shadow, images.reference);
  std::printf(
      "torus's terminator under the sun, virtual maps: RMSE %.4f, largest error %.3f of "
      "%ld pixels\n",
      m.rmse, m.max_error, m.pixels);
  ASSERT_GT(m.pixels, 20000) << "too little of the scene compared";
  EXPECT_LT(m.rmse, 0.015);
}

// The default scene's sphere's shadow on the ground, seen from above,
// under a source 1.5 wide: its blockers' region spans over 64 texels, so
// it is read from the hierarchy's cells 4 texels wide. Each cell's patch
// at the nearest depth of its texels drew the sphere's projection towards
// the source's centre, too dark outside its outline and too light inside
// (RMSE 0.0146; the cut cells texel by texel, 0.0143; the whole cells at
// their texels' mean depth as well, 0.0135); the cut cells' patches too
// at the mean depth of their texels in front, 0.0119.
TEST_F(GpuTest, BackprojectionReadsTheCellsOfAWideRegionAtTheirMeanDepth) {
  const ShadowMetrics m =
      default_scene_close_up({-0.5f, 3.0f, 2.6f}, {-0.5f, 0.0f, 0.7f}, 40.0f, 1.5f);
  std::printf("sphere's shadow under a source 1.5 wide: RMSE %.4f of %ld pixels\n", m.rmse,
              m.pixels);
  ASSERT_GT(m.pixels, 20000) << "too little of the scene compared";
  EXPECT_LE(m.rmse, 0.013);
}

// The default scene under the sun 8.45 degrees wide, its cascades fitted
// to the view (--tight-cascades): the penumbra of the torus's shadow on
// the ground spans over 64 texels, so its region is read from the
// hierarchy's cells. A cell reached to its neighbour's projection of their
// shared side at the neighbour's nearest depth, and a flat 2 x 2 of cells
// was one patch at its nearest, while the cells' patches lie at their
// mean depths: a crack between them, on the side away from the source's
// centre, through which the source showed in the umbra: here its 705
// pixels read 0.0027 lit on average, 29 of them over 0.02; now 0.0014 and
// 15 (at 1280 x 720, 298 of 10 970 over 0.02, now 94; read texel by
// texel, at backprojection_cells 128, 43).
TEST_F(GpuTest, BackprojectionLeavesNoCrackBetweenCellsInAnUmbra) {
  ShadowSettings s;
  s.sun_angle = 8.452f;
  s.tight_cascades = true;
  const CloseUp images = default_view_images("directional", s);
  int umbra = 0, cracked = 0;
  double light = 0.0;
  for (std::size_t i = 0; i < images.shadow.rgba.size(); i += 4) {
    const float* ref = &images.reference.rgba[i];
    if (ref[3] <= 0.0f || ref[0] > 0.0f) continue;  // judged and every ray blocked
    ++umbra;
    light += images.shadow.rgba[i];
    if (images.shadow.rgba[i] > 0.02f) ++cracked;
  }
  std::printf("umbra pixels %d: %.4f lit on average, %d over 0.02\n", umbra, light / umbra,
              cracked);
  ASSERT_GT(umbra, 300);
  EXPECT_LT(light / umbra, 0.002);
}

// A wall whose face is the plane z = 0, a square bar along x in front of
// it, and a spot light `degrees` from facing the wall, aimed at the wall's
// point at `aim_height` from `light_distance` away; the camera looks
// straight at the wall from `camera_distance` at `camera_height`.
struct BarBeforeAWall {
  const char* name;
  float degrees;
  glm::vec3 bar_centre;
  float bar_side;
  float aim_height, light_distance, camera_height, camera_distance;

  Scene scene() const {
    const float theta = glm::radians(degrees);
    const glm::vec3 to_light(0.0f, std::sin(theta), std::cos(theta));
    const glm::vec3 aim(0.0f, aim_height, 0.0f);
    const glm::vec3 eye(0.0f, camera_height, camera_distance);
    return testing::TestScene(name)
        .box({0.0f, 1.0f, -0.05f}, {2.0f, 2.0f, 0.1f})
        .box(bar_centre, {1.6f, bar_side, bar_side})
        .camera(eye, {0.0f, camera_height, 0.0f}, 30.0f)
        .light(testing::spot_light(aim + light_distance * to_light, aim, 20.0f, 20.0f));
  }
};

// A wall 80 degrees from facing a spot light, a rod 1 cm thick held 4 mm
// off it: along the light's rays the rod lies 2.3 cm in front of the wall
// where its shadow falls, 6 texels of the map's depth. The slope-scaled
// bias, following the wall's slope tan 80 degrees = 5.7, had moved the
// receiver's plane 9 texels towards the light and dropped the rod where
// it is nearest the wall: its umbra on the wall (where the traced
// reference reads under 0.1) read 0.38 lit on average; following it only
// up to BACKPROJECTION_BIAS_MAX_SLOPE (3.5 texels), 0.17, all of it from
// the umbra's lower edge, four rows read lit: the normal offset, 0.4 texel
// off the wall, moved the shadow's edge by a centimetre on a wall this
// steep; without it where the wall's slope is under the settings'
// max_slope (backprojection_normal_offset()), 0.043.
TEST_F(GpuTest, BackprojectionKeepsABlockerCloseToASteepReceiver) {
  const BarBeforeAWall rod{
      "rod before a wall", 80.0f, {0.0f, 1.2f, 0.009f}, 0.01f, 1.1f, 5.0f, 1.12f, 0.6f};
  const CloseUp images = small_scene_images(rod.scene(), 0.02f);
  double sum = 0.0;
  int umbra = 0;
  for (std::size_t i = 0; i < images.shadow.rgba.size(); i += 4) {
    if (images.reference.rgba[i + 3] <= 0.0f || images.reference.rgba[i] >= 0.1f) continue;
    sum += images.shadow.rgba[i];
    ++umbra;
  }
  ASSERT_GT(umbra, 200) << "too little of the rod's umbra in view";
  std::printf("the rod's umbra on the wall: %d pixels, mean %.3f lit\n", umbra, sum / umbra);
  EXPECT_LT(sum / umbra, 0.1);
}

// A rail 2 cm thick held 5 cm off a wall 78 degrees from facing a spot
// light (the foliage scene's fence under its lamp), its shadow 25 cm
// lower on the wall. A normal offset moves the lookup off the wall, and at
// grazing its shadows move along the wall by the offset times tan theta:
// the default half texel times 1 - cos theta moved the shadow a third of
// its width up the wall (RMSE 0.1175). Where the receiver's depth gradient
// follows the wall (under the settings' max_slope), its plane keeps the
// wall's own texels out without an offset (backprojection_normal_offset():
// 0.0381, most of it the rail's lower silhouette placed on a texel
// boundary, which a wall this steep stretches to two pixels).
TEST_F(GpuTest, BackprojectionKeepsAShadowInPlaceOnAWallLitAtGrazing) {
  const BarBeforeAWall rail{
      "rail before a wall", 78.0f, {0.0f, 1.2f, 0.06f}, 0.02f, 1.0f, 8.0f, 1.05f, 0.8f};
  const CloseUp images = small_scene_images(rail.scene(), 0.3f);
  const ShadowMetrics m = compare_shadow(images.shadow, images.reference);
  long shadowed = 0;
  for (std::size_t i = 0; i < images.reference.rgba.size(); i += 4) {
    if (images.reference.rgba[i + 3] > 0.0f && images.reference.rgba[i] < 0.5f) ++shadowed;
  }
  std::printf("the rail's shadow on the wall: %ld pixels under 0.5, RMSE %.4f\n", shadowed, m.rmse);
  ASSERT_GT(shadowed, 500) << "too little of the rail's shadow in view";
  EXPECT_LT(m.rmse, 0.06);
}

// The umbra pixels (the reference under 0.01) of the ground under the
// default scene's sphere, where the high slab hides the sphere's top from
// the source's centre (1.5 wide), that read over 0.05, and the RMSE.
struct UnderTheSlab {
  long umbra = 0, lit_in_umbra = 0;
  double rmse = 0.0;
};
UnderTheSlab under_the_slab(const std::string& light) {
  const CloseUp images =
      default_scene_images({0.9f, 1.2f, 3.6f}, {0.2f, 0.0f, 1.1f}, 30.0f, 1.5f, light);
  UnderTheSlab u;
  for (std::size_t i = 0; i < images.shadow.rgba.size(); i += 4) {
    const bool judged = images.reference.rgba[i + 3] > 0.0f;
    if (!judged || images.reference.rgba[i] > 0.01f) continue;  // outside the umbra
    ++u.umbra;
    if (images.shadow.rgba[i] > 0.05f) ++u.lit_in_umbra;
  }
  u.rmse = compare_shadow(images.shadow, images.reference).rmse;
  std::printf("sphere under the slab (%s light): %ld of %ld umbra pixels over 0.05, RMSE %.4f\n",
              light.empty() ? "spot" : light.c_str(), u.lit_in_umbra, u.umbra, u.rmse);
  return u;
}

// The first surfaces of the map there are the slab's, and a receiver
// under the sphere sees the sphere through the source's edges. Without the
// second surfaces (the nearest facing the light behind the first: the
// sphere) those pixels read up to 0.2 lit where the traced reference
// reads 0 (before: 584 of 5 146 umbra pixels over 0.05, RMSE 0.0247; now
// 7, 0.0156).
TEST_F(GpuTest, BackprojectionSeesACasterThatAnotherHidesFromTheSourcesCentre) {
  const UnderTheSlab u = under_the_slab("");
  ASSERT_GT(u.umbra, 3000) << "too little of the umbra in view";
  EXPECT_LT(u.lit_in_umbra, u.umbra / 100);
  EXPECT_LT(u.rmse, 0.02);
}

// The same under a point light's sphere 1.5 across where the spot is: its
// cube faces hold second surfaces too, drawn with the fragments' radial
// depth (before, with one layer: 382 of 5 961 umbra pixels over 0.05,
// RMSE 0.0237; now 65, 0.0141).
TEST_F(GpuTest, BackprojectionSeesOnACubeFaceACasterThatAnotherHides) {
  const UnderTheSlab u = under_the_slab("point");
  ASSERT_GT(u.umbra, 3000) << "too little of the umbra in view";
  EXPECT_LT(u.lit_in_umbra, u.umbra / 40);
  EXPECT_LT(u.rmse, 0.018);
}

}  // namespace
}  // namespace penumbra
