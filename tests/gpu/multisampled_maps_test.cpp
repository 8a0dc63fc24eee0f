// Multisampled shadow maps (--shadow-msaa, seed 002): a caster's straight
// edge crosses the texels of a spot light's map; with one sample a texel
// holds the caster's moments or the ground's, with four it holds their
// mix by the fraction of its samples the caster covers, which follows the
// texel's analytic coverage by the edge. The fused resolve + filter reads
// the samples as the resolve does; the depth techniques read the nearest
// sample; every light type renders its views multisampled.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/glm.hpp>
#include <vector>

#include "gpu_fixture.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/shadow/representation.hpp"
#include "penumbra/shadow_maps.hpp"
#include "render/renderer.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

constexpr int kMapSize = 64;
constexpr float kCasterHeight = 5.0f;

// The caster's edge: x = kEdgeSlope z + kEdgeOffset at the caster's height,
// a few degrees off the map's axes so that it crosses the texels at every
// offset; the caster covers the side x > the edge.
constexpr float kEdgeSlope = 0.12f;
constexpr float kEdgeOffset = 0.037f;

// A spot light looking straight down from 10 above a ground at y = 0, and
// a flat caster at y = 5 over the half x > the edge: both at one depth
// each along the light's axis.
struct EdgeScene {
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;
  std::vector<Light> lights;
  CameraFrustum camera;

  EdgeScene() {
    const float y = kCasterHeight, far = 20.0f;
    auto quad = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
      const auto first = static_cast<std::uint32_t>(positions.size());
      positions.insert(positions.end(), {a, b, c, d});
      for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(first + i);
    };
    quad({-far, 0.0f, -far}, {far, 0.0f, -far}, {far, 0.0f, far}, {-far, 0.0f, far});
    quad({kEdgeSlope * -far + kEdgeOffset, y, -far}, {far, y, -far}, {far, y, far},
         {kEdgeSlope * far + kEdgeOffset, y, far});
    Light spot;
    spot.position = {0.0f, 10.0f, 0.0f};
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.cone_degrees = 30.0f;
    lights.push_back(spot);
    camera.position = {0.0f, 12.0f, 12.0f};
    camera.forward = glm::normalize(glm::vec3(0.0f, -1.0f, -1.0f));
  }
};

// The scene's triangles at attribute 0.
testing::PositionMesh edge_mesh(const EdgeScene& scene) {
  std::vector<glm::vec3> triangles;
  for (std::uint32_t i : scene.indices) triangles.push_back(scene.positions[i]);
  return testing::PositionMesh(triangles);
}

std::vector<float> read_layer0(GLuint texture, GLenum format, int channels) {
  GLint layers = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_DEPTH, &layers);
  std::vector<float> texels(static_cast<std::size_t>(kMapSize) * kMapSize * layers * channels);
  glGetTextureImage(texture, 0, format, GL_FLOAT, static_cast<GLsizei>(texels.size() * 4),
                    texels.data());
  texels.resize(static_cast<std::size_t>(kMapSize) * kMapSize * channels);
  return texels;
}

struct Maps {
  std::vector<float> filtered;  // RG: the VSM moments (z, z^2), or the format's channels
  std::vector<float> depth;     // the depth maps (nearest sample)
  glm::mat4 view_projection{1.0f};
};

Maps render_maps(const ShadowSettings& settings, int channels = 2) {
  const EdgeScene scene;
  const testing::PositionMesh mesh = edge_mesh(scene);
  ShadowMaps maps;
  maps.update(scene.lights, scene.camera, CasterGeometry{scene.positions, scene.indices}, settings);
  maps.render([&](const CasterView&) { mesh.draw(); });
  glFinish();
  const GLenum format = channels == 4 ? GL_RGBA : channels == 2 ? GL_RG : GL_RED;
  return {maps.filtered_maps() != 0 ? read_layer0(maps.filtered_maps(), format, channels)
                                    : std::vector<float>{},
          read_layer0(maps.depth_maps(), GL_DEPTH_COMPONENT, 1),
          maps.block().views[0].view_projection};
}

// The fraction of each texel the caster covers, by 32 x 32 points a texel
// against the edge projected into the map (a straight line there: the
// caster is flat).
std::vector<double> analytic_coverage(const glm::mat4& view_projection) {
  auto to_map = [&](glm::vec3 p) {
    const glm::dvec4 clip = glm::dmat4(view_projection) * glm::dvec4(p, 1.0);
    return (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * double(kMapSize);
  };
  const glm::dvec2 a = to_map({kEdgeSlope * -5.0f + kEdgeOffset, kCasterHeight, -5.0f});
  const glm::dvec2 b = to_map({kEdgeSlope * 5.0f + kEdgeOffset, kCasterHeight, 5.0f});
  const glm::dvec2 inside = to_map({3.0f, kCasterHeight, 0.0f});
  const glm::dvec2 normal(a.y - b.y, b.x - a.x);
  const double side = glm::dot(inside - a, normal) > 0.0 ? 1.0 : -1.0;
  std::vector<double> coverage(static_cast<std::size_t>(kMapSize) * kMapSize);
  constexpr int kPoints = 32;
  for (int y = 0; y < kMapSize; ++y) {
    for (int x = 0; x < kMapSize; ++x) {
      int covered = 0;
      for (int j = 0; j < kPoints; ++j) {
        for (int i = 0; i < kPoints; ++i) {
          const glm::dvec2 p(x + (i + 0.5) / kPoints, y + (j + 0.5) / kPoints);
          covered += side * glm::dot(p - a, normal) > 0.0 ? 1 : 0;
        }
      }
      coverage[static_cast<std::size_t>(y) * kMapSize + x] = double(covered) / (kPoints * kPoints);
    }
  }
  return coverage;
}

struct EdgeProfile {
  int texels = 0;           // texels the edge crosses (analytic coverage in (0.05, 0.95))
  int intermediate = 0;     // of them, first moment strictly between the caster's and the ground's
  double mean_error = 0.0;  // mean |coverage from the first moment - analytic coverage|
};

// The caster's coverage of each texel the edge crosses, read from the
// first moment: m1 = c z_caster + (1 - c) z_ground.
EdgeProfile edge_profile(const Maps& maps, int channels = 2) {
  const std::vector<double> coverage = analytic_coverage(maps.view_projection);
  float z_caster = 1.0f, z_ground = 0.0f;
  for (std::size_t t = 0; t < coverage.size(); ++t) {
    const float m1 = maps.filtered[t * channels];
    if (coverage[t] == 1.0) z_caster = std::min(z_caster, m1);
    if (coverage[t] == 0.0) z_ground = std::max(z_ground, m1);
  }
  EXPECT_LT(z_caster + 0.1f, z_ground);
  EdgeProfile profile;
  for (std::size_t t = 0; t < coverage.size(); ++t) {
    if (coverage[t] <= 0.05 || coverage[t] >= 0.95) continue;
    const double c = (z_ground - maps.filtered[t * channels]) / double(z_ground - z_caster);
    ++profile.texels;
    if (c > 0.01 && c < 0.99) ++profile.intermediate;
    profile.mean_error += std::abs(c - coverage[t]);
  }
  if (profile.texels > 0) profile.mean_error /= profile.texels;
  return profile;
}

ShadowSettings vsm_unfiltered(int samples) {
  ShadowSettings s;
  s.technique = Technique::Vsm;
  s.map_size = kMapSize;
  s.blur = 0;
  s.shadow_msaa = samples;
  return s;
}

// One sample: every texel is the caster's or the ground's; four: the texels
// along the edge mix them, by about the fraction of the texel the caster
// covers (a 4-sample pattern resolves coverage to quarters: a mean error
// of at most about 1/8 against 1/4 for a binary texel).
TEST_F(GpuTest, MultisampledMomentsFollowTheEdgesCoverage) {
  const EdgeProfile one = edge_profile(render_maps(vsm_unfiltered(1)));
  const EdgeProfile four = edge_profile(render_maps(vsm_unfiltered(4)));
  std::printf(
      "edge texels %d: 1 sample: %d intermediate, coverage error %.3f; 4 samples: %d, %.3f\n",
      one.texels, one.intermediate, one.mean_error, four.intermediate, four.mean_error);
  ASSERT_GT(one.texels, kMapSize / 2);
  EXPECT_EQ(one.intermediate, 0);
  EXPECT_GT(four.intermediate, one.texels * 3 / 4);
  EXPECT_LT(four.mean_error, 0.6 * one.mean_error);
  EXPECT_LT(four.mean_error, 0.15);
}

// The depth techniques' map holds the nearest sample: a texel any sample
// of the caster covers holds the caster's depth, so the caster covers at
// least the texels it covers with one sample at the centre.
TEST_F(GpuTest, MultisampledDepthMapsHoldTheNearestSample) {
  const Maps one = render_maps(vsm_unfiltered(1));
  const Maps four = render_maps(vsm_unfiltered(4));
  const std::vector<double> coverage = analytic_coverage(four.view_projection);
  const float z_caster = *std::min_element(four.depth.begin(), four.depth.end());
  auto is_caster = [&](float z) { return std::abs(z - z_caster) < 1e-4f; };
  int caster_one = 0, caster_four = 0;
  for (std::size_t t = 0; t < coverage.size(); ++t) {
    caster_one += is_caster(one.depth[t]) ? 1 : 0;
    caster_four += is_caster(four.depth[t]) ? 1 : 0;
    if (coverage[t] >= 0.9) {
      EXPECT_TRUE(is_caster(four.depth[t])) << "texel " << t;
    }
    if (coverage[t] == 0.0) {
      EXPECT_FALSE(is_caster(four.depth[t])) << "texel " << t;
    }
  }
  EXPECT_GT(caster_four, caster_one);
}

// The techniques that read depth draw their maps with one sample whatever
// --shadow-msaa says: their depth maps are those of --shadow-msaa 1.
TEST_F(GpuTest, DepthTechniquesDrawOneSample) {
  for (const Technique technique : {Technique::Hard, Technique::Pcss}) {
    ShadowSettings s = vsm_unfiltered(1);
    s.technique = technique;
    const Maps one = render_maps(s, 1);
    s.shadow_msaa = 4;
    EXPECT_EQ(depth_samples(s), 1);
    EXPECT_EQ(render_maps(s, 1).depth, one.depth);
  }
}

// The fused resolve + Gaussian staging each texel's mean of its samples'
// moments gives the resolve and two-pass blur's maps, for the one-float,
// two- and four-moment representations.
TEST_F(GpuTest, FusedFilterOfMultisampledMapsMatchesTheTwoPassPath) {
  for (const auto& [technique, channels] :
       {std::pair{Technique::Esm, 1}, {Technique::Vsm, 2}, {Technique::Msm, 4}}) {
    ShadowSettings s = vsm_unfiltered(4);
    s.technique = technique;
    s.blur = 3;
    ASSERT_TRUE(uses_fused_filter(s));
    const Maps fused = render_maps(s, channels);
    s.fused = false;
    const Maps two_pass = render_maps(s, channels);
    double worst = 0.0;
    for (std::size_t i = 0; i < fused.filtered.size(); ++i) {
      worst = std::max(worst, double(std::abs(fused.filtered[i] - two_pass.filtered[i])));
    }
    EXPECT_LT(worst, 1e-5) << enum_name<Technique>(kTechniqueNames, technique);
  }
}

// Four-moment maps stage four floats a texel when multisampled: the fused
// pass takes radii up to 8 there (32 KiB of shared memory), wider ones run
// the two passes.
TEST(MultisampledPlan, FourMomentFusedRadiusFitsTheSharedMemoryEveryDeviceHas) {
  ShadowSettings s;
  s.technique = Technique::Msm;
  EXPECT_EQ(max_fused_blur(s), kMaxFusedBlur);
  s.shadow_msaa = 4;
  EXPECT_EQ(max_fused_blur(s), 8);
  s.blur = 9;
  EXPECT_FALSE(uses_fused_filter(s));
  s.technique = Technique::Vsm;
  EXPECT_EQ(max_fused_blur(s), kMaxFusedBlur);
  EXPECT_TRUE(uses_fused_filter(s));
}

// A box over a ground under one light of each type: its views (a spot
// view, the cascades, six cube faces) multisampled give the shadow of one
// sample up to antialiasing at its edges.
Scene box_scene(LightType type) {
  return testing::TestScene("box")
      .ground(12.0f)
      .box({0.0f, 1.5f, 0.0f}, glm::vec3(1.0f), {0.0f, 20.0f, 0.0f})
      .camera({0.0f, 6.0f, 7.0f}, {0.0f, 0.0f, 0.0f})
      .light(testing::overhead_light(type));
}

class MultisampledLightTypes : public GpuTest, public ::testing::WithParamInterface<LightType> {};

TEST_P(MultisampledLightTypes, ShadowMatchesOneSampleAwayFromEdges) {
  const Scene scene = box_scene(GetParam());
  Renderer renderer(scene);
  const RenderSettings render = testing::small_frame(64, 48);
  ShadowSettings shadow;
  shadow.technique = Technique::Vsm;
  shadow.map_size = 128;
  shadow.cascades = 2;
  renderer.render(render, shadow);
  const Image one = renderer.read_view();
  shadow.shadow_msaa = 4;
  renderer.render(render, shadow);
  const Image four = renderer.read_view();
  double sum = 0.0, shadowed = 0.0;
  int pixels = 0, differing = 0;
  for (int y = 0; y < render.height; ++y) {
    for (int x = 0; x < render.width; ++x) {
      if (one.pixel(x, y)[3] < 0.5f) continue;
      const double d = std::abs(double(one.pixel(x, y)[0]) - four.pixel(x, y)[0]);
      sum += d;
      differing += d > 1e-3 ? 1 : 0;
      shadowed += four.pixel(x, y)[0] < 0.5f ? 1.0 : 0.0;
      ++pixels;
    }
  }
  std::printf("%d pixels: mean difference %.4f, %d differ, %.0f in shadow\n", pixels, sum / pixels,
              differing, shadowed);
  EXPECT_GT(shadowed, 20.0);      // the box casts its shadow
  EXPECT_GT(differing, 0);        // the samples changed its edges
  EXPECT_LT(sum / pixels, 0.01);  // and nothing else
  // Back to one sample, every view is drawn again: the image of one sample.
  shadow.shadow_msaa = 1;
  renderer.render(render, shadow);
  EXPECT_EQ(renderer.read_view().rgba, one.rgba);
}

INSTANTIATE_TEST_SUITE_P(EveryLightType, MultisampledLightTypes,
                         ::testing::Values(LightType::Spot, LightType::Directional,
                                           LightType::Point),
                         testing::light_type_name);

}  // namespace
}  // namespace penumbra
