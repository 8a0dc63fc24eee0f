// The filtered techniques on the default scene, measured against the
// filtered hard-shadow reference (the unfiltered map's depth tests averaged
// with the same kernel).
#include <algorithm>
#include <cmath>

#include "gpu_fixture.hpp"
#include "reference/shadow_metrics.hpp"
#include "render/renderer.hpp"
#include "scene/builtin_scenes.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

RenderSettings small_view(View view, int light = 0) {
  RenderSettings rs;
  rs.width = 256;
  rs.height = 192;
  rs.view = view;
  rs.light_index = light;
  return rs;
}

ShadowSettings filtered(Technique technique, Filter filter, int blur) {
  ShadowSettings s;
  s.technique = technique;
  s.filter = filter;
  s.blur = blur;
  s.map_size = 512;
  return s;
}

bool all_finite(const Image& image) {
  for (float v : image.rgba)
    if (!std::isfinite(v)) return false;
  return true;
}

// No NaN or Inf in any output, for every technique and filter, unfiltered
// and at a large width, in the final image and every map view.
TEST_F(GpuTest, FilteredTechniquesProduceNoNanOrInf) {
  Renderer renderer(*builtin_scene("default"));
  for (Technique t : {Technique::Vsm, Technique::Esm, Technique::Msm, Technique::Msm16,
                      Technique::Evsm2, Technique::Evsm4}) {
    for (Filter f : {Filter::Gaussian, Filter::Sat}) {
      if (!supports_sat(t) && f == Filter::Sat) continue;  // refused: see validate()
      // 4: the fused resolve + filter; 48: the two-pass Gaussian.
      for (int blur : {0, 4, 48}) {
        // The final image evaluates every light's shadow; the map views
        // show each light's map before and after the filter.
        for (auto [v, light] : {std::pair{View::Final, 0},
                                {View::Moments, 1},
                                {View::MomentsFiltered, 0},
                                {View::MomentsFiltered, 1}}) {
          {
            renderer.render(small_view(v, light), filtered(t, f, blur));
            Image image = renderer.read_view();
            ASSERT_TRUE(all_finite(image))
                << enum_name<Technique>(kTechniqueNames, t) << " "
                << enum_name<Filter>(kFilterNames, f) << " blur " << blur << " view "
                << enum_name<View>(kViewNames, v) << " light " << light;
          }
        }
      }
    }
  }
}

ShadowMetrics measure(Renderer& renderer, const ShadowSettings& settings, int light) {
  renderer.render(small_view(View::Shadow, light), settings);
  Image technique = renderer.read_view();
  renderer.render(small_view(View::ShadowReference, light), settings);
  Image reference = renderer.read_view();
  return compare_shadow(technique, reference);
}

// Peters & Klein's central claim: against the filtered hard shadow, 4MSM
// errs less than VSM and leaks light over a smaller area. The default
// scene's slab shadows the sphere, whose own shadow edge inside the slab's
// umbra is where VSM leaks (two occluders at different depths in one
// filter window).
TEST_F(GpuTest, MomentShadowMapsBeatVarianceShadowMaps) {
  Renderer renderer(*builtin_scene("default"));
  double vsm_leaks = 0.0;
  for (Filter filter : {Filter::Gaussian, Filter::Sat}) {
    for (auto [light, blur] : {std::pair{0, 8}, {0, 16}, {1, 8}}) {
      ShadowMetrics vsm = measure(renderer, filtered(Technique::Vsm, filter, blur), light);
      ShadowMetrics msm = measure(renderer, filtered(Technique::Msm, filter, blur), light);
      ShadowMetrics msm16 = measure(renderer, filtered(Technique::Msm16, filter, blur), light);
      const char* name = enum_name<Filter>(kFilterNames, filter).data();
      std::printf(
          "light %d, %s W=%d:  MAE vsm %.5f msm %.5f msm16 %.5f | leak vsm %.5f msm %.5f "
          "msm16 %.5f\n",
          light, name, blur, vsm.mean_absolute_error, msm.mean_absolute_error,
          msm16.mean_absolute_error, vsm.leak_fraction, msm.leak_fraction, msm16.leak_fraction);
      EXPECT_LT(msm.mean_absolute_error, 0.75 * vsm.mean_absolute_error) << name << " " << light;
      EXPECT_LT(msm16.mean_absolute_error, 0.75 * vsm.mean_absolute_error) << name << " " << light;
      if (vsm.leak_fraction > 0.0) {
        EXPECT_LT(msm.leak_fraction, vsm.leak_fraction) << name << " light " << light;
        EXPECT_LT(msm16.leak_fraction, vsm.leak_fraction) << name << " light " << light;
      } else {
        EXPECT_EQ(msm.leak_fraction, 0.0) << name << " light " << light;
        EXPECT_EQ(msm16.leak_fraction, 0.0) << name << " light " << light;
      }
      vsm_leaks += vsm.leak_fraction;
    }
  }
  EXPECT_GT(vsm_leaks, 0.0) << "the scene no longer shows VSM's light leaking";
}

// Lauritzen & McCool's claim for the exponential warps, against the
// filtered hard shadow on the default scene: evsm4 errs less than VSM, and
// less than evsm2, and leaks over no more area than evsm2. evsm2 alone
// leaks more than VSM here (measured: 0.6-0.7 % of the pixels against
// 0.01-0.05 %): like ESM, its positive warp weights the farthest depths of
// a filter window most, so a receiver next to the ground behind it (the
// box's shaded faces, the sphere's underside) sees a mean behind itself and
// is lit. The negative warp weights the nearest depths most and removes
// that (evsm4: 0-0.07 %).
TEST_F(GpuTest, ExponentialWarpsBeatVarianceShadowMaps) {
  Renderer renderer(*builtin_scene("default"));
  double evsm2_leaks = 0.0, vsm_leaks = 0.0;
  for (auto [light, blur] : {std::pair{0, 8}, {0, 16}, {1, 8}}) {
    const ShadowMetrics vsm =
        measure(renderer, filtered(Technique::Vsm, Filter::Gaussian, blur), light);
    const ShadowMetrics evsm2 =
        measure(renderer, filtered(Technique::Evsm2, Filter::Gaussian, blur), light);
    const ShadowMetrics evsm4 =
        measure(renderer, filtered(Technique::Evsm4, Filter::Gaussian, blur), light);
    std::printf(
        "light %d, W=%d: MAE vsm %.5f evsm2 %.5f evsm4 %.5f | leak vsm %.5f evsm2 %.5f "
        "evsm4 %.5f\n",
        light, blur, vsm.mean_absolute_error, evsm2.mean_absolute_error, evsm4.mean_absolute_error,
        vsm.leak_fraction, evsm2.leak_fraction, evsm4.leak_fraction);
    EXPECT_LT(evsm4.mean_absolute_error, vsm.mean_absolute_error) << light;
    EXPECT_LT(evsm4.mean_absolute_error, evsm2.mean_absolute_error) << light;
    EXPECT_LE(evsm4.leak_fraction, evsm2.leak_fraction) << light;
    evsm2_leaks += evsm2.leak_fraction;
    vsm_leaks += vsm.leak_fraction;
  }
  EXPECT_GT(evsm2_leaks, vsm_leaks) << "evsm2 no longer leaks more than vsm: update the comment";
}

// EVSM's map views show the positive warp exp(c+ (2 z - 1)) in depth units:
// unfiltered, the shadow-map view's depth itself.
TEST_F(GpuTest, EvsmMomentsViewShowsDepth) {
  Renderer renderer(*builtin_scene("default"));
  renderer.render(small_view(View::ShadowMap), filtered(Technique::Evsm4, Filter::Gaussian, 0));
  const Image depth = renderer.read_view();
  for (Technique t : {Technique::Evsm2, Technique::Evsm4}) {
    renderer.render(small_view(View::Moments), filtered(t, Filter::Gaussian, 0));
    const Image shown = renderer.read_view();
    ASSERT_EQ(depth.rgba.size(), shown.rgba.size());
    double max_error = 0.0;
    for (std::size_t p = 0; p < depth.rgba.size(); p += 4) {
      max_error = std::max(max_error, double(std::abs(shown.rgba[p] - depth.rgba[p])));
    }
    EXPECT_LT(max_error, 1e-5) << enum_name<Technique>(kTechniqueNames, t);
  }
}

// The reference and the techniques agree where there is nothing to filter:
// at W = 0 the reference is the hard shadow.
TEST_F(GpuTest, UnfilteredReferenceIsTheHardShadow) {
  Renderer renderer(*builtin_scene("default"));
  ShadowSettings hard;
  hard.map_size = 512;
  renderer.render(small_view(View::Shadow), hard);
  Image hard_image = renderer.read_view();
  renderer.render(small_view(View::ShadowReference), filtered(Technique::Msm, Filter::Gaussian, 0));
  Image reference = renderer.read_view();
  ShadowMetrics m = compare_shadow(hard_image, reference);
  // They differ only where the receiver-plane test and the single test
  // disagree: on a few pixels at silhouettes and terminators (surfaces
  // turned away from the light's centre are tested too, not set to 0:
  // MAE 0.0021).
  EXPECT_LT(m.mean_absolute_error, 0.003);
}

// msm stores the moments of u = 2 z - 1; its map views show them as the
// moments of z: unfiltered, (z, z^2, z^3) of the shadow-map view's depth.
TEST_F(GpuTest, MsmMomentsViewShowsTheMomentsOfDepth) {
  Renderer renderer(*builtin_scene("default"));
  renderer.render(small_view(View::ShadowMap), filtered(Technique::Msm, Filter::Gaussian, 0));
  const Image depth = renderer.read_view();
  renderer.render(small_view(View::Moments), filtered(Technique::Msm, Filter::Gaussian, 0));
  const Image moments = renderer.read_view();
  ASSERT_EQ(depth.rgba.size(), moments.rgba.size());
  double max_error = 0.0;
  for (std::size_t p = 0; p < depth.rgba.size(); p += 4) {
    const double z = depth.rgba[p];
    for (int k = 0; k < 3; ++k) {
      max_error = std::max(max_error, std::abs(moments.rgba[p + k] - std::pow(z, k + 1)));
    }
  }
  EXPECT_LT(max_error, 1e-6);
}

}  // namespace
}  // namespace penumbra
