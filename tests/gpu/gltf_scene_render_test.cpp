// glTF scenes on the GPU: the file's camera and spot light, a textured
// quad's albedo, and alpha-masked and single-sided casters in every
// technique and in the traced reference.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <optional>

#include "gltf_files.hpp"
#include "gpu_fixture.hpp"
#include "reference/shadow_metrics.hpp"
#include "reference/traced_reference.hpp"
#include "render/renderer.hpp"
#include "scene/gltf_scene.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GltfQuad;
using testing::GltfSpec;
using testing::GpuTest;

constexpr int kSize = 96;  // image width and height

// A ground quad facing up (material 0), half-size `half`.
GltfQuad ground(float half) {
  return {{{-half, 0, half}, {half, 0, half}, {half, 0, -half}, {-half, 0, -half}}, 0};
}

// A horizontal square card of side 2 * half at height y, centred on c,
// facing up (or down); texture u along +x, v along +z.
GltfQuad card(glm::vec3 c, float half, int material, bool facing_up = true) {
  GltfQuad q{{c + glm::vec3(-half, 0, -half), c + glm::vec3(half, 0, -half),
              c + glm::vec3(half, 0, half), c + glm::vec3(-half, 0, half)},
             material};
  if (facing_up) std::swap(q.corners[1], q.corners[3]);  // counter-clockwise from above
  return q;
}

// Where the ray of pixel (x, y) of a camera at `eye` looking at `target`
// (vertical field of view yfov, up +y) meets the plane y = 0. Computed
// from the test's own camera, not the renderer's.
std::optional<glm::vec3> ground_point(glm::vec3 eye, glm::vec3 target, float yfov, int x, int y) {
  const glm::mat4 view = glm::lookAt(eye, target, glm::vec3(0, 1, 0));
  const glm::mat4 inverse = glm::inverse(glm::perspective(yfov, 1.0f, 0.1f, 100.0f) * view);
  const glm::vec2 ndc{(x + 0.5f) / kSize * 2.0f - 1.0f, 1.0f - (y + 0.5f) / kSize * 2.0f};
  const glm::vec4 a = inverse * glm::vec4(ndc, -1.0f, 1.0f);
  const glm::vec4 b = inverse * glm::vec4(ndc, 1.0f, 1.0f);
  const glm::vec3 origin = glm::vec3(a) / a.w;
  const glm::vec3 dir = glm::normalize(glm::vec3(b) / b.w - origin);
  if (dir.y >= 0.0f) return std::nullopt;
  return origin + dir * (-origin.y / dir.y);
}

RenderSettings shadow_view() {
  RenderSettings rs = testing::small_frame(kSize, kSize);
  return rs;
}

Image render(Renderer& renderer, View view, const ShadowSettings& shadow) {
  RenderSettings rs = shadow_view();
  rs.view = view;
  renderer.render(rs, shadow);
  return renderer.read_view();
}

// A scene the test writes: a ground, an opaque card at height 1.5 under a
// red spot light at (0, 6, 0), seen by the file's camera from -x. The
// shadow factor is 0 where the test finds the path to the light crosses
// the card and 1 where it clearly does not; the lit ground is red.
TEST_F(GpuTest, GltfCameraAndSpotLightRenderTheShadowWhereComputed) {
  const glm::vec3 eye{-7, 5, 0.5f}, target{0, 0, 0.5f};
  const float yfov = 0.9f;
  const glm::vec3 light{0, 6, 0};
  const glm::vec3 centre{0.6f, 1.5f, 0.4f};
  const float half = 0.5f;
  GltfSpec spec;
  spec.quads = {ground(5.0f), card(centre, half, 0)};
  spec.materials.push_back({});
  spec.cameras.push_back(
      {.position = eye, .target = target, .yfov = yfov, .znear = 0.5f, .zfar = 60.0f});
  spec.lights.push_back({.name = "key",
                         .type = "spot",
                         .color = {1, 0, 0},
                         .intensity = 40,
                         .inner_cone = 0.6f,
                         .outer_cone = 0.8f,
                         .position = light,
                         .direction = {0, -1, 0}});
  // A second camera the default must not use.
  spec.cameras.push_back({.position = {0, 10, 0.01f}, .target = {0, 0, 0}});
  Renderer renderer(gltf_scene(testing::write_gltf("camera-spot-render.gltf", spec)));
  ShadowSettings hard;
  hard.map_size = 1024;
  const Image factor = render(renderer, View::Shadow, hard);
  const Image final_image = render(renderer, View::Final, hard);

  int under = 0, under_dark = 0, outside = 0, outside_lit = 0, red = 0;
  const float margin = 0.12f;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const auto p = ground_point(eye, target, yfov, x, y);
      if (!p || std::abs(p->x) > 4.5f || std::abs(p->z) > 4.5f) continue;
      // Skip pixels that see the card itself (from the camera).
      const glm::vec3 to_eye = eye - *p;
      const glm::vec3 q_eye = *p + to_eye * ((centre.y - p->y) / to_eye.y);
      if (std::max(std::abs(q_eye.x - centre.x), std::abs(q_eye.z - centre.z)) < half + margin)
        continue;
      const glm::vec3 to_light = light - *p;
      if (glm::dot(glm::normalize(-to_light), glm::vec3(0, -1, 0)) < std::cos(0.55f)) continue;
      const glm::vec3 q = *p + to_light * ((centre.y - p->y) / to_light.y);
      const float d = std::max(std::abs(q.x - centre.x), std::abs(q.z - centre.z));
      const float f = factor.pixel(x, y)[0];
      if (d < half - margin) {
        ++under;
        under_dark += f < 0.1f;
      } else if (d > half + margin) {
        ++outside;
        outside_lit += f > 0.9f;
        const float* c = final_image.pixel(x, y);
        red += c[0] > 4.0f * c[1] && c[0] > 4.0f * c[2];
      }
    }
  }
  std::printf("under the card: %d/%d dark; outside: %d/%d lit, %d red\n", under_dark, under,
              outside_lit, outside, red);
  ASSERT_GT(under, 30);
  ASSERT_GT(outside, 300);
  EXPECT_EQ(under_dark, under);
  EXPECT_GE(outside_lit, outside - 2);
  EXPECT_GE(red, outside - 2) << "the light is the file's red spot";
}

// A 16 x 16 texture of 4 x 4 blocks, each a distinct colour, on a quad
// that the file's camera sees from straight above: the albedo view shows
// each block's colour (sRGB decoded) at the block's centre. (Whole blocks,
// so that the check holds whatever filter a driver applies within a few
// texels: llvmpipe's anisotropic filter blurs magnified texels.)
TEST_F(GpuTest, TexturedQuadAlbedoMatchesTheTexture) {
  const auto block_color = [](int bx, int by) {
    return std::array<int, 4>{30 + 60 * bx, 30 + 60 * by, 200 - 40 * bx, 255};
  };
  std::vector<std::uint8_t> rgba;
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      for (const int c : block_color(x / 4, y / 4)) rgba.push_back(static_cast<std::uint8_t>(c));
    }
  }
  testing::write_rgba_png("albedo4.png", 16, 16, rgba);
  GltfSpec spec;
  // u along +x, v along -z (the image's top edge at z = +1), facing up.
  spec.quads.push_back(ground(1.0f));
  spec.materials.push_back({.image = "albedo4.png"});
  const glm::vec3 eye{0, 4, 0.001f};
  spec.cameras.push_back({.position = eye, .target = {0, 0, 0}, .yfov = 0.8f});
  Renderer renderer(gltf_scene(testing::write_gltf("albedo-quad.gltf", spec)));
  const Image albedo = render(renderer, View::Albedo, ShadowSettings{});
  const glm::mat4 clip = renderer.camera_projection(kSize, kSize) * renderer.camera_view();
  const auto linear = [](int byte) {
    const float c = byte / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
  };
  double worst = 0.0;
  for (int ty = 0; ty < 4; ++ty) {
    for (int tx = 0; tx < 4; ++tx) {
      const glm::vec4 p = clip * glm::vec4(-0.75f + 0.5f * tx, 0.0f, 0.75f - 0.5f * ty, 1.0f);
      const int x = static_cast<int>((p.x / p.w * 0.5f + 0.5f) * kSize);
      const int y = static_cast<int>((0.5f - p.y / p.w * 0.5f) * kSize);
      ASSERT_TRUE(x >= 0 && x < kSize && y >= 0 && y < kSize);
      const float* got = albedo.pixel(x, y);
      const std::array<int, 4> want = block_color(tx, ty);
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, double(std::abs(got[c] - linear(want[c]))));
    }
  }
  std::printf("largest albedo difference at block centres: %.4f\n", worst);
  EXPECT_LT(worst, 0.02);
}

// Checkerboard cut-outs: texel (i, j) of a 4 x 4 alpha mask is a hole
// where i + j is odd.
std::vector<std::uint8_t> checker_mask() {
  std::vector<std::uint8_t> rgba;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      for (const int c : {90, 160, 60, (i + j) % 2 == 0 ? 255 : 0})
        rgba.push_back(static_cast<std::uint8_t>(c));
    }
  }
  return rgba;
}

constexpr glm::vec3 kCardCentre{0.0f, 1.2f, 0.0f};
constexpr float kCardHalf = 1.0f;
constexpr glm::vec3 kLight{0.3f, 6.0f, 0.2f};

// The alpha-masked card over a ground, a point-like spot light above,
// seen from above by the file's camera.
Scene masked_card_scene(const std::string& name, const std::string& alpha_mode, bool facing_up,
                        bool double_sided, const std::string& light_type = "spot") {
  testing::write_rgba_png("mask4.png", 4, 4, checker_mask());
  GltfSpec spec;
  spec.quads = {ground(4.0f), card(kCardCentre, kCardHalf, 1, facing_up)};
  spec.materials.push_back({});
  spec.materials.push_back(
      {.image = "mask4.png", .alpha_mode = alpha_mode, .double_sided = double_sided});
  spec.cameras.push_back({.position = {0.0f, 8.0f, 5.5f}, .target = {0, 0, 0.5f}, .yfov = 0.7f});
  // The directional light shines along -kLight: the same paths to it as
  // from a light at kLight, up to parallax.
  const bool directional = light_type == "directional";
  spec.lights.push_back({.type = light_type,
                         .intensity = directional ? 1.0f : 36.0f,
                         .inner_cone = 0.6f,
                         .outer_cone = 0.75f,
                         .position = kLight,
                         .direction = directional ? -kLight : glm::vec3(0, -1, 0)});
  return gltf_scene(testing::write_gltf(name, spec));
}

struct HoleCount {
  int holes = 0, holes_lit = 0, solid = 0, solid_dark = 0;
};

// Ground pixels whose path to the light crosses the card well inside a
// hole texel, or well inside a solid one; the card is seen from the
// camera at (0, 8, 5.5).
HoleCount count_holes(const Image& factor, float lit_above, float dark_below,
                      bool directional = false) {
  HoleCount h;
  const glm::vec3 eye{0.0f, 8.0f, 5.5f}, target{0, 0, 0.5f};
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const auto p = ground_point(eye, target, 0.7f, x, y);
      if (!p) continue;
      const glm::vec3 to_eye = eye - *p;
      const glm::vec3 seen = *p + to_eye * ((kCardCentre.y - p->y) / to_eye.y);
      if (std::max(std::abs(seen.x), std::abs(seen.z)) < kCardHalf + 0.1f) continue;  // the card
      const glm::vec3 to_light = directional ? kLight : kLight - *p;
      const glm::vec3 q = *p + to_light * ((kCardCentre.y - p->y) / to_light.y);
      // Texel coordinates on the card: u along x, v along z, 4 texels.
      const float u = (q.x - kCardCentre.x + kCardHalf) / (2.0f * kCardHalf) * 4.0f;
      const float v = (q.z - kCardCentre.z + kCardHalf) / (2.0f * kCardHalf) * 4.0f;
      if (u < 0.0f || v < 0.0f || u >= 4.0f || v >= 4.0f) continue;
      const float fu = u - std::floor(u), fv = v - std::floor(v);
      if (fu < 0.3f || fu > 0.7f || fv < 0.3f || fv > 0.7f) continue;  // near a texel's edge
      const bool hole = (static_cast<int>(u) + static_cast<int>(v)) % 2 == 1;
      const float f = factor.pixel(x, y)[0];
      if (hole) {
        ++h.holes;
        h.holes_lit += f > lit_above;
      } else {
        ++h.solid;
        h.solid_dark += f < dark_below;
      }
    }
  }
  return h;
}

ShadowSettings technique(Technique t) {
  ShadowSettings s;
  s.technique = t;
  s.map_size = 1024;
  s.light_size = 0.0f;  // a point source: the traced reference is the hard shadow
  s.pcf_width = 2.0f;
  s.blur = 1;
  return s;
}

// The card's holes let the light through in hard, pcf and msm shadows,
// and in the traced reference, which the hard shadow of a fine map
// matches.
TEST_F(GpuTest, AlphaMaskedCardShadowHasTheCardsHoles) {
  Renderer renderer(masked_card_scene("masked-card.gltf", "MASK", true, true));
  for (Technique t : {Technique::Hard, Technique::Pcf, Technique::Msm}) {
    const Image factor = render(renderer, View::Shadow, technique(t));
    const HoleCount h = count_holes(factor, 0.8f, 0.2f);
    std::printf("technique %d: holes %d/%d lit, solid %d/%d dark\n", static_cast<int>(t),
                h.holes_lit, h.holes, h.solid_dark, h.solid);
    ASSERT_GT(h.holes, 20);
    ASSERT_GT(h.solid, 20);
    EXPECT_EQ(h.holes_lit, h.holes);
    EXPECT_EQ(h.solid_dark, h.solid);
  }
  ShadowSettings fine = technique(Technique::Hard);
  fine.map_size = 4096;
  RenderSettings rs = shadow_view();
  const TracedReference traced = traced_reference(renderer, rs, fine, 1, "");
  const HoleCount h = count_holes(traced.image, 0.99f, 0.01f);
  std::printf("traced: holes %d/%d lit, solid %d/%d dark\n", h.holes_lit, h.holes, h.solid_dark,
              h.solid);
  EXPECT_EQ(h.holes_lit, h.holes);
  EXPECT_EQ(h.solid_dark, h.solid);
  const Image hard = render(renderer, View::Shadow, fine);
  const ShadowMetrics m = compare_shadow(hard, traced.image);
  std::printf("hard (4096) vs traced: MAE %.5f over %ld pixels\n", m.mean_absolute_error, m.pixels);
  EXPECT_LT(m.mean_absolute_error, 0.01);
}

// The holes in a point light's cube faces and a directional light's
// cascades, with a single-sided card facing the light (a face turned the
// wrong way in any view would drop its shadow there).
TEST_F(GpuTest, AlphaMaskedCardHolesInCubeFacesAndCascades) {
  for (const std::string light : {"point", "directional"}) {
    Renderer renderer(
        masked_card_scene("masked-card-" + light + ".gltf", "MASK", true, false, light));
    const bool directional = light == "directional";
    for (Technique t : {Technique::Hard, Technique::Msm}) {
      const HoleCount h =
          count_holes(render(renderer, View::Shadow, technique(t)), 0.8f, 0.2f, directional);
      std::printf("%s light, technique %d: holes %d/%d lit, solid %d/%d dark\n", light.c_str(),
                  static_cast<int>(t), h.holes_lit, h.holes, h.solid_dark, h.solid);
      ASSERT_GT(h.holes, 12);
      ASSERT_GT(h.solid, 12);
      EXPECT_EQ(h.holes_lit, h.holes);
      EXPECT_EQ(h.solid_dark, h.solid);
    }
    const TracedReference traced =
        traced_reference(renderer, shadow_view(), technique(Technique::Hard), 1, "");
    const HoleCount h = count_holes(traced.image, 0.99f, 0.01f, directional);
    EXPECT_EQ(h.holes_lit, h.holes) << light;
    EXPECT_EQ(h.solid_dark, h.solid) << light;
  }
}

// BLEND is drawn as MASK at 0.5: the same holes.
TEST_F(GpuTest, BlendCardCastsAsAMaskAtOneHalf) {
  Renderer renderer(masked_card_scene("blend-card.gltf", "BLEND", true, true));
  const HoleCount h =
      count_holes(render(renderer, View::Shadow, technique(Technique::Hard)), 0.8f, 0.2f);
  ASSERT_GT(h.holes, 20);
  EXPECT_EQ(h.holes_lit, h.holes);
  EXPECT_EQ(h.solid_dark, h.solid);
}

// A card whose back faces the light: double-sided, it casts (holes and
// all) in the shadow map and in the traced reference; single-sided, it
// casts nothing in either.
TEST_F(GpuTest, DoubleSidedCardCastsFromBothSides) {
  for (bool double_sided : {true, false}) {
    Renderer renderer(masked_card_scene(double_sided ? "two-sided.gltf" : "one-sided.gltf", "MASK",
                                        /*facing_up=*/false, double_sided));
    const ShadowSettings hard = technique(Technique::Hard);
    const HoleCount map = count_holes(render(renderer, View::Shadow, hard), 0.8f, 0.2f);
    const TracedReference traced = traced_reference(renderer, shadow_view(), hard, 1, "");
    const HoleCount ray = count_holes(traced.image, 0.99f, 0.01f);
    std::printf("double-sided %d: map solid %d/%d dark, traced solid %d/%d dark\n", double_sided,
                map.solid_dark, map.solid, ray.solid_dark, ray.solid);
    ASSERT_GT(map.solid, 20);
    EXPECT_EQ(map.holes_lit, map.holes);
    EXPECT_EQ(ray.holes_lit, ray.holes);
    EXPECT_EQ(map.solid_dark, double_sided ? map.solid : 0);
    EXPECT_EQ(ray.solid_dark, double_sided ? ray.solid : 0);
  }
}

}  // namespace
}  // namespace penumbra
